#include "render/figures/label_raster.hpp"

#include <stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/base/embedded_data.hpp"

namespace pw::render {
inline namespace figures {

struct LabelRaster::Font {
    stbtt_fontinfo info{};
};

std::vector<uint32_t> decodeUtf8(std::string_view s) {
    std::vector<uint32_t> out;
    for (size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        const int extra = b < 0x80 ? 0 : (b >> 5) == 0x6 ? 1 : (b >> 4) == 0xE ? 2 : (b >> 3) == 0x1E ? 3 : -1;
        if (extra < 0 || i + size_t(extra) >= s.size()) {  // not a lead byte, or cut short
            out.push_back(0xFFFD);
            ++i;
            continue;
        }
        uint32_t cp = extra == 0 ? b : b & (0x3Fu >> extra);
        bool ok = true;
        for (int k = 1; k <= extra; ++k) {
            const auto c = static_cast<unsigned char>(s[i + size_t(k)]);
            ok = ok && (c >> 6) == 0x2;
            cp = (cp << 6) | (c & 0x3Fu);
        }
        out.push_back(ok ? cp : 0xFFFD);
        i += ok ? size_t(extra) + 1 : 1;
    }
    return out;
}

LabelRaster::LabelRaster() : font_(std::make_unique<Font>()) {
    const auto* data = reinterpret_cast<const unsigned char*>(embedded::uiFontTtf.data());
    const int offset = stbtt_GetFontOffsetForIndex(data, 0);
    if (offset < 0 || !stbtt_InitFont(&font_->info, data, offset)) throw std::runtime_error("the embedded font could not be read");
}

LabelRaster::~LabelRaster() = default;

std::array<float, 2> LabelRaster::measure(std::string_view text, float pixels) const {
    const float scale = stbtt_ScaleForPixelHeight(&font_->info, pixels);
    float x = 0.0f;
    uint32_t prev = 0;
    for (uint32_t cp : decodeUtf8(text)) {
        int advance = 0, lsb = 0;
        stbtt_GetCodepointHMetrics(&font_->info, int(cp), &advance, &lsb);
        if (prev) x += scale * float(stbtt_GetCodepointKernAdvance(&font_->info, int(prev), int(cp)));
        x += scale * float(advance);
        prev = cp;
    }
    return {x, pixels};
}

void blendPixel(PixelImage& img, int x, int y, const std::array<uint8_t, 4>& c, float coverage) {
    if (x < 0 || y < 0 || x >= int(img.width) || y >= int(img.height) || coverage <= 0.0f) return;
    const float a = std::min(coverage, 1.0f) * float(c[3]) / 255.0f;
    uint8_t* p = &img.rgba[(size_t(y) * img.width + size_t(x)) * 4];
    for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::lround(float(p[k]) * (1.0f - a) + float(c[size_t(k)]) * a));
    p[3] = uint8_t(std::max(float(p[3]), a * 255.0f));
}

void fillRect(PixelImage& img, float x0, float y0, float x1, float y1, const std::array<uint8_t, 4>& c) {
    for (int y = int(std::floor(y0)); y < int(std::ceil(y1)); ++y)
        for (int x = int(std::floor(x0)); x < int(std::ceil(x1)); ++x) blendPixel(img, x, y, c, 1.0f);
}

void LabelRaster::draw(PixelImage image, float x, float y, std::string_view text, const TextStyle& style, float ax, float ay) const {
    const auto size = measure(text, style.pixels);
    const float left = x - ax * size[0], top = y - ay * size[1];
    if (style.box) {
        const float pad = std::ceil(style.pixels * 0.2f);
        fillRect(image, left - pad, top - pad, left + size[0] + pad, top + size[1] + pad, style.boxColor);
    }
    const stbtt_fontinfo* f = &font_->info;
    const float scale = stbtt_ScaleForPixelHeight(f, style.pixels);
    int ascent = 0, descent = 0, gap = 0;
    stbtt_GetFontVMetrics(f, &ascent, &descent, &gap);
    const float baseline = top + scale * float(ascent);
    float pen = left;
    uint32_t prev = 0;
    std::vector<unsigned char> glyph;
    for (uint32_t cp : decodeUtf8(text)) {
        if (prev) pen += scale * float(stbtt_GetCodepointKernAdvance(f, int(prev), int(cp)));
        int advance = 0, lsb = 0;
        stbtt_GetCodepointHMetrics(f, int(cp), &advance, &lsb);
        const float shift = pen - std::floor(pen);
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        stbtt_GetCodepointBitmapBoxSubpixel(f, int(cp), scale, scale, shift, 0.0f, &x0, &y0, &x1, &y1);
        const int gw = x1 - x0, gh = y1 - y0;
        if (gw > 0 && gh > 0) {
            glyph.assign(size_t(gw) * size_t(gh), 0);
            stbtt_MakeCodepointBitmapSubpixel(f, glyph.data(), gw, gh, gw, scale, scale, shift, 0.0f, int(cp));
            const int ox = int(std::floor(pen)) + x0, oy = int(std::lround(baseline)) + y0;
            for (int gy = 0; gy < gh; ++gy)
                for (int gx = 0; gx < gw; ++gx)
                    blendPixel(image, ox + gx, oy + gy, style.color, float(glyph[size_t(gy) * size_t(gw) + size_t(gx)]) / 255.0f);
        }
        pen += scale * float(advance);
        prev = cp;
    }
}

}  // namespace figures
}  // namespace pw::render

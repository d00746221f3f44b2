#include "core/model/height_map.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"

namespace pw {
inline namespace model {

namespace {
constexpr uint32_t kMaxSide = 8192;

// libpng (Debian's libpng16) reads the maps: it checks every chunk's CRC and zlib's Adler-32 of the
// image data, where stb_image accepted damaged files. Its errors longjmp back to decodePng.
struct PngSource {
    const unsigned char* data;
    size_t size, at;
    char message[256];
};

void pngError(png_structp png, png_const_charp message) {
    auto* src = static_cast<PngSource*>(png_get_error_ptr(png));
    std::snprintf(src->message, sizeof src->message, "%s", message);
    png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}  // an ancillary chunk dropped: nothing a height map uses

void pngRead(png_structp png, png_bytep out, size_t n) {
    auto* src = static_cast<PngSource*>(png_get_io_ptr(png));
    if (n > src->size - src->at) png_error(png, "the file ends early (it is cut short)");
    std::memcpy(out, src->data + src->at, n);
    src->at += n;
}

// libpng's message in words, naming the chunk ("IDAT: CRC error").
std::string pngProblem(const std::string& message) {
    const bool named = message.size() > 6 && message[4] == ':' && message[5] == ' ';
    const std::string chunk = named ? message.substr(0, 4) : "", what = named ? message.substr(6) : message;
    if (what.find("CRC error") != std::string::npos) return "PNG chunk " + chunk + " fails its CRC check (the file is damaged)";
    if (what.find("incorrect data check") != std::string::npos)
        return "the PNG's image data (" + (named ? chunk : std::string("IDAT")) + ") fails its Adler-32 check (the file is damaged)";
    return named ? "PNG chunk " + chunk + ": " + what : "unreadable PNG: " + what;
}

// Decodes into m (one 16-bit grey channel, the file's bit depth in m.bits); false with
// src.message set when libpng refuses the file or it is larger than the limit. Nothing with a
// destructor is made between setjmp and a longjmp: `rows` and `m` belong to the caller.
bool decodePng(PngSource& src, HeightMap& m, std::vector<unsigned char*>& rows) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &src, pngError, pngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        std::snprintf(src.message, sizeof src.message, "out of memory");
        png_destroy_read_struct(&png, nullptr, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_set_read_fn(png, &src, pngRead);
    png_read_info(png, info);
    const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    if (w > kMaxSide || h > kMaxSide) {
        std::snprintf(src.message, sizeof src.message, "height map is %u x %u; the limit is 8192 x 8192", unsigned(w), unsigned(h));
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    const int depth = png_get_bit_depth(png, info), type = png_get_color_type(png, info);
    // One grey channel of 16 bits, little-endian, whatever the file holds (8 bits x 257).
    if (type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (type == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (type & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
    if (type & PNG_COLOR_MASK_COLOR) png_set_rgb_to_gray_fixed(png, 1, -1, -1);
    png_set_expand_16(png);
    png_set_swap(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_channels(png, info) != 1 || png_get_rowbytes(png, info) != size_t(w) * 2)
        png_error(png, "the pixels do not convert to one grey channel");
    m.width = w;
    m.height = h;
    m.bits = depth == 16 ? 16 : 8;
    m.texels.resize(size_t(w) * h);
    rows.resize(h);
    for (png_uint_32 y = 0; y < h; ++y) rows[y] = reinterpret_cast<unsigned char*>(m.texels.data() + size_t(y) * w);
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);  // the last chunks' CRCs and the end of the image data
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

}  // namespace

double HeightMap::texel(int64_t x, int64_t y) const {
    x = std::clamp<int64_t>(x, 0, int64_t(width) - 1);
    y = std::clamp<int64_t>(y, 0, int64_t(height) - 1);
    return texels[size_t(y) * width + size_t(x)] / 65535.0;
}

double HeightMap::sample(double u, double v) const {
    if (empty()) return 0.0;
    const double x = u * width - 0.5, y = v * height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double fx = x - x0, fy = y - y0;
    const auto ix = int64_t(x0), iy = int64_t(y0);
    const double a = texel(ix, iy) * (1 - fx) + texel(ix + 1, iy) * fx;
    const double b = texel(ix, iy + 1) * (1 - fx) + texel(ix + 1, iy + 1) * fx;
    return a * (1 - fy) + b * fy;
}

HeightMap loadHeightMap(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::string bytes = readFileLimited(path);  // InputError naming the file when unreadable
    if (bytes.size() < 8 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
        throw InputError(name, "not a PNG file (a height map is an 8- or 16-bit PNG)");
    PngSource src{reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), 0, {}};
    HeightMap m;
    std::vector<unsigned char*> rows;
    if (!decodePng(src, m, rows)) throw InputError(name, pngProblem(src.message));
    m.source = name;
    return m;
}

HeightMap heightMapFromValues(uint32_t width, uint32_t height, const std::vector<double>& values, std::string source) {
    HeightMap m;
    m.width = width;
    m.height = height;
    m.bits = 16;
    m.source = std::move(source);
    m.texels.resize(size_t(width) * height);
    for (size_t i = 0; i < m.texels.size() && i < values.size(); ++i)
        m.texels[i] = uint16_t(std::lround(std::clamp(values[i], 0.0, 1.0) * 65535.0));
    return m;
}

std::vector<HeightMap> heightMipChain(const HeightMap& map, int levels) {
    std::vector<HeightMap> out;
    out.reserve(size_t(std::max(levels, 0)));  // `prev` points into it
    const HeightMap* prev = &map;
    for (int l = 1; l <= levels && !prev->empty() && (prev->width > 1 || prev->height > 1); ++l) {
        HeightMap m;
        m.width = std::max(1u, prev->width / 2);
        m.height = std::max(1u, prev->height / 2);
        m.bits = 16;
        m.source = map.source;
        m.texels.resize(size_t(m.width) * m.height);
        for (uint32_t y = 0; y < m.height; ++y)
            for (uint32_t x = 0; x < m.width; ++x) {
                // The 2 x 2 texels above (one of them where that side is 1 texel): a box filter.
                const uint32_t x0 = std::min(2 * x, prev->width - 1), x1 = std::min(2 * x + 1, prev->width - 1);
                const uint32_t y0 = std::min(2 * y, prev->height - 1), y1 = std::min(2 * y + 1, prev->height - 1);
                const auto at = [&](uint32_t tx, uint32_t ty) { return uint32_t(prev->texels[size_t(ty) * prev->width + tx]); };
                m.texels[size_t(y) * m.width + x] = uint16_t((at(x0, y0) + at(x1, y0) + at(x0, y1) + at(x1, y1) + 2) / 4);
            }
        out.push_back(std::move(m));
        prev = &out.back();
    }
    return out;
}

}  // namespace model
}  // namespace pw

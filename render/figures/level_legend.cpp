#include "render/figures/level_legend.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/gpu/level_colour.h"

namespace pw::render {
inline namespace figures {

void drawLevelLegend(std::vector<uint8_t>& rgba, uint32_t width, uint32_t height, const std::array<int, 4>& rect,
                     const LabelRaster& labels) {
    const float text = std::clamp(float(std::min(rect[2], rect[3])) / 30.0f, 10.0f, 28.0f);
    const int barW = int(std::min(float(rect[2]) * 0.45f, text * 16.0f)), barH = int(std::ceil(text * 0.9f));
    const int pad = int(std::ceil(text * 0.6f));
    const int boxW = barW + 2 * pad, boxH = barH + int(std::ceil(text * 2.6f)) + 2 * pad;
    const int x0 = rect[0] + rect[2] - boxW - pad, y0 = rect[1] + rect[3] - boxH - pad;
    if (x0 < rect[0] || y0 < rect[1]) return;  // no room in so small a pane
    const auto put = [&](int x, int y, float r, float g, float b, float a) {
        if (x < 0 || y < 0 || x >= int(width) || y >= int(height)) return;
        uint8_t* p = &rgba[(size_t(y) * width + size_t(x)) * 4];
        const float c[3] = {r, g, b};
        for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::lround(float(p[k]) * (1.0f - a) + 255.0f * c[k] * a));
    };
    for (int y = y0; y < y0 + boxH; ++y)  // a light box behind, so the legend reads on any background
        for (int x = x0; x < x0 + boxW; ++x) put(x, y, 1.0f, 1.0f, 1.0f, 0.85f);
    const int bx = x0 + pad, by = y0 + pad + int(std::ceil(text * 1.3f));
    for (int x = 0; x < barW; ++x) {
        const float level = std::exp2(6.0f * (float(x) + 0.5f) / float(barW));  // 1 .. 64 on a log scale
        const glm::vec3 c = gpu::levelColour(level);
        for (int y = by; y < by + barH; ++y) put(bx + x, y, c.r, c.g, c.b, 1.0f);
    }
    PixelImage img{width, height, rgba};
    TextStyle st;
    st.pixels = text;
    labels.draw(img, float(bx), float(y0 + pad), "tessellation level", st, 0.0f, 0.0f);
    for (int k = 0; k <= 6; ++k) {
        const int x = bx + int(std::lround(float(barW) * float(k) / 6.0f));
        for (int y = by + barH; y < by + barH + int(text * 0.35f); ++y) put(std::min(x, bx + barW - 1), y, 0.1f, 0.1f, 0.1f, 1.0f);
        labels.draw(img, float(x), float(by + barH) + text * 0.4f, std::to_string(1 << k), st, 0.5f, 0.0f);
    }
}

}  // namespace figures
}  // namespace pw::render

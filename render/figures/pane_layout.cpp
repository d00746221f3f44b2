#include "render/figures/pane_layout.hpp"

#include <algorithm>
#include <cmath>

namespace pw::render {
inline namespace figures {

std::vector<std::array<float, 4>> splitPanes(int count, const std::array<float, 4>& a) {
    std::vector<std::array<float, 4>> out;
    const int n = std::clamp(count, 1, 4);
    const int cols = n == 1 ? 1 : 2, rows = n <= 2 ? 1 : 2;
    const float w = a[2] / float(cols), h = a[3] / float(rows);
    for (int i = 0; i < n; ++i) out.push_back({a[0] + float(i % cols) * w, a[1] + float(i / cols) * h, w, h});
    return out;
}

std::array<int, 4> pixelRect(const std::array<float, 4>& r) {
    const int x0 = int(std::lround(r[0])), y0 = int(std::lround(r[1]));
    const int x1 = int(std::lround(r[0] + r[2])), y1 = int(std::lround(r[1] + r[3]));
    return {x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0)};
}

void drawPaneDividers(std::vector<uint8_t>& rgba, uint32_t width, uint32_t height, const std::vector<std::array<float, 4>>& rects) {
    const auto grey = [&](uint32_t x, uint32_t y) {
        if (x < width && y < height && (size_t(y) * width + x) * 4 + 3 <= rgba.size())
            std::fill_n(&rgba[(size_t(y) * width + x) * 4], 3, uint8_t(160));
    };
    for (const auto& rf : rects) {
        const auto r = pixelRect(rf);
        const auto x0 = uint32_t(std::max(r[0], 0)), y0 = uint32_t(std::max(r[1], 0));
        const auto x1 = uint32_t(std::max(r[0] + r[2], 0)), y1 = uint32_t(std::max(r[1] + r[3], 0));
        if (x0 > 0)
            for (uint32_t y = y0; y < y1; ++y) grey(x0, y);
        if (y0 > 0)
            for (uint32_t x = x0; x < x1; ++x) grey(x, y0);
    }
}

}  // namespace figures
}  // namespace pw::render

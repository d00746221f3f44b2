#include "render/figures/stage_bars.hpp"

#include <algorithm>
#include <cmath>

namespace pw::render {

std::vector<StageCount> stageCounts(const FrameStats& s) {
    if (!s.pipelineStatsValid) return {};
    std::vector<StageCount> out = {{"vertex shader", "invocations", s.vsInvocations},
                                   {"control shader", "patches", s.tcsPatches},
                                   {"evaluation shader", "invocations", s.tesInvocations},
                                   {"primitives", "triangles", s.triangles()}};
    uint64_t largest = 0;
    for (const StageCount& c : out) largest = std::max(largest, c.count);
    for (StageCount& c : out) c.bar = largest ? float(std::log1p(double(c.count)) / std::log1p(double(largest))) : 0.0f;
    return out;
}

std::array<uint8_t, 4> stageColor(size_t i) {
    static const std::array<uint8_t, 4> kBar[] = {{255, 150, 40, 255}, {90, 200, 255, 255}, {255, 90, 220, 255}, {120, 220, 90, 255}};
    return kBar[i % 4];
}

void drawStageBars(PixelImage image, const std::array<float, 4>& rect, const std::vector<StageCount>& counts, float textPixels,
                   const LabelRaster& labels) {
    if (counts.empty()) return;
    const float pad = textPixels * 0.5f, row = textPixels * 1.45f, barW = textPixels * 7.0f;
    float labelW = 0.0f, numberW = 0.0f;
    for (const StageCount& c : counts) {
        labelW = std::max(labelW, labels.measure(c.stage, textPixels)[0]);
        numberW = std::max(numberW, labels.measure(std::to_string(c.count) + " " + c.unit, textPixels)[0]);
    }
    const float w = pad * 4.0f + labelW + barW + numberW, h = pad * 2.0f + row * float(counts.size());
    const float x0 = rect[0] + rect[2] - w - pad, y0 = rect[1] + rect[3] - h - pad;
    fillRect(image, x0, y0, x0 + w, y0 + h, {0, 0, 0, 170});
    for (size_t i = 0; i < counts.size(); ++i) {
        const float y = y0 + pad + row * float(i);
        TextStyle st;
        st.pixels = textPixels;
        st.color = {235, 235, 235, 255};
        labels.draw(image, x0 + pad, y + row * 0.5f, counts[i].stage, st, 0.0f, 0.5f);
        const float bx = x0 + pad * 2.0f + labelW;
        fillRect(image, bx, y + row * 0.2f, bx + std::max(2.0f, barW * counts[i].bar), y + row * 0.8f, stageColor(i));
        labels.draw(image, bx + barW + pad, y + row * 0.5f, std::to_string(counts[i].count) + " " + counts[i].unit, st, 0.0f, 0.5f);
    }
}

}  // namespace pw::render

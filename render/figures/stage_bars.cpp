#include "render/figures/stage_bars.hpp"

#include <algorithm>
#include <cmath>

namespace pw::render {
inline namespace figures {

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

StageBarsLayout layoutStageBars(const std::vector<StageCount>& counts, float textPixels,
                                const std::function<float(const std::string&)>& width, const std::array<float, 4>& rect, bool atTop) {
    StageBarsLayout out;
    const float pad = textPixels * 0.5f, row = textPixels * 1.45f, barW = textPixels * 7.0f;
    float labelW = 0.0f, numberW = 0.0f;
    for (const StageCount& c : counts) {
        out.rows.push_back({});
        out.rows.back().number = std::to_string(c.count) + " " + c.unit;
        labelW = std::max(labelW, width(c.stage));
        numberW = std::max(numberW, width(out.rows.back().number));
    }
    const float w = pad * 4.0f + labelW + barW + numberW, h = pad * 2.0f + row * float(counts.size());
    const float x0 = rect[0] + rect[2] - w - pad, y0 = atTop ? rect[1] + pad : rect[1] + rect[3] - h - pad;
    out.box = {x0, y0, w, h};
    for (size_t i = 0; i < counts.size(); ++i) {
        StageBarsLayout::Row& r = out.rows[i];
        const float y = y0 + pad + row * float(i), bx = x0 + pad * 2.0f + labelW;
        r.labelX = x0 + pad;
        r.textY = y + row * 0.5f;
        r.bar = {bx, y + row * 0.2f, bx + std::max(2.0f, barW * counts[i].bar), y + row * 0.8f};
        r.numberX = bx + barW + pad;
    }
    return out;
}

void drawStageBars(PixelImage image, const std::array<float, 4>& rect, const std::vector<StageCount>& counts, float textPixels,
                   const LabelRaster& labels) {
    if (counts.empty()) return;
    const StageBarsLayout l = layoutStageBars(
        counts, textPixels, [&](const std::string& t) { return labels.measure(t, textPixels)[0]; }, rect, false);
    fillRect(image, l.box[0], l.box[1], l.box[0] + l.box[2], l.box[1] + l.box[3], {0, 0, 0, 170});
    TextStyle st;
    st.pixels = textPixels;
    st.color = {235, 235, 235, 255};
    for (size_t i = 0; i < counts.size(); ++i) {
        const StageBarsLayout::Row& r = l.rows[i];
        labels.draw(image, r.labelX, r.textY, counts[i].stage, st, 0.0f, 0.5f);
        fillRect(image, r.bar[0], r.bar[1], r.bar[2], r.bar[3], stageColor(i));
        labels.draw(image, r.numberX, r.textY, r.number, st, 0.0f, 0.5f);
    }
}

}  // namespace figures
}  // namespace pw::render

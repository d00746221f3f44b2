// The per-stage counters of one frame as a bar figure, the pipeline of the lecture in numbers:
// vertex shader invocations (control points fed), control shader patches, evaluation shader
// invocations (vertices the tessellator made) and primitives (triangles). The bars are log-scaled
// (the counts span four orders of magnitude at level 64); the numbers are printed beside them.
// Drawn in figure panes (`render --stage-bars`) and in the editor's panes (Teaching > Stage counters).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/figures/label_raster.hpp"
#include "render/vk/stats.hpp"

namespace pw::render {
inline namespace figures {

struct StageCount {
    std::string stage;  // "vertex shader", "control shader", "evaluation shader", "primitives"
    std::string unit;   // "invocations", "patches", "invocations", "triangles"
    uint64_t count = 0;
    float bar = 0.0f;  // 0..1: log(1 + count) / log(1 + the largest count)
};
// Empty when the device has no pipeline statistics.
std::vector<StageCount> stageCounts(const FrameStats& s);
// The bar colour of stage `i` (RGBA): the editor's bars and the figures' alike.
std::array<uint8_t, 4> stageColor(size_t i);

// Where the bars go, for the figures' raster and the editor's ImGui alike: a backdrop box, and per
// stage its name and its number (each anchored left, centred on `textY`) and its bar.
struct StageBarsLayout {
    std::array<float, 4> box{};  // x, y, width, height
    struct Row {
        float labelX = 0, numberX = 0, textY = 0;
        std::array<float, 4> bar{};  // x0, y0, x1, y1
        std::string number;          // "9248 invocations"
    };
    std::vector<Row> rows;
};
// The layout for text `textPixels` high whose widths `width` measures, in the bottom-right corner
// of `rect` (x, y, width, height), or its top-right one with `atTop`.
StageBarsLayout layoutStageBars(const std::vector<StageCount>& counts, float textPixels,
                                const std::function<float(const std::string&)>& width, const std::array<float, 4>& rect, bool atTop);

// The bars in the bottom-right corner of `rect` (the panes' captions are at the top) (x, y, width, height) of an RGBA8 image.
void drawStageBars(PixelImage image, const std::array<float, 4>& rect, const std::vector<StageCount>& counts, float textPixels,
                   const LabelRaster& labels);

}  // namespace figures
}  // namespace pw::render

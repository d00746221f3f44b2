// The legend of `--shading level`: a colour bar of core/gpu/level_colour.h from level 1 to 64 with
// a tick at every power of two, drawn into the bottom-right corner of a pane of an RGBA8 image.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "render/figures/label_raster.hpp"

namespace pw::render {
inline namespace figures {

// Draws the legend inside `rect` (x, y, width, height in pixels) of the `width` x `height` image.
void drawLevelLegend(std::vector<uint8_t>& rgba, uint32_t width, uint32_t height, const std::array<int, 4>& rect,
                     const LabelRaster& labels);

}  // namespace figures
}  // namespace pw::render

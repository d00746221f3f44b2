// The Bézier math diagram (core/eval/bezier_math.hpp) drawn onto a rendered frame: `render --math`,
// the slide of the editor's Teaching > Bezier math overlay. Strokes and dots anti-aliased on the
// CPU, labels with LabelRaster, the numbers in a box at the bottom left.
#pragma once

#include <array>

#include "core/eval/bezier_math.hpp"
#include "core/model/document.hpp"
#include "render/figures/label_raster.hpp"

namespace pw::render {
inline namespace figures {

// Draws `d` as `cam` sees it in the rectangle `rect` (x, y, width, height) of `image`; `textPixels`
// is the label size (dots and strokes scale with it).
void drawMathDiagram(PixelImage image, const MathDiagram& d, const Camera& cam, const std::array<float, 4>& rect, float textPixels,
                     const LabelRaster& labels);

}  // namespace figures
}  // namespace pw::render

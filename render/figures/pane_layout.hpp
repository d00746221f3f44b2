// Comparison panes: how 1, 2 or 4 panes share an area, their pixel rectangles, and the thin lines
// between them in a headless figure. Shared by the domain figures, the model figures and the editor.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace pw::render {
inline namespace figures {

// The rectangles (x, y, width, height) of `count` panes (1, 2: side by side, 3 or 4: a 2 x 2 grid)
// filling `area`.
std::vector<std::array<float, 4>> splitPanes(int count, const std::array<float, 4>& area);

// A pane rectangle in whole pixels: its edges rounded, so neighbouring panes share an edge and
// leave no gap.
std::array<int, 4> pixelRect(const std::array<float, 4>& rect);

// A thin grey line along each pane's left and top edge where another pane adjoins it, drawn into
// an RGBA8 image of `width` x `height`.
void drawPaneDividers(std::vector<uint8_t>& rgba, uint32_t width, uint32_t height, const std::vector<std::array<float, 4>>& rects);

}  // namespace figures
}  // namespace pw::render

// Domain figures drawn from the tessellator's primitives (cairo, from Debian): SVG or PDF with the
// same layout, colours and labels as the PNG figure (render/figures/domain_figure.hpp), every
// triangle the tessellator made one closed, filled and outlined path (an isoline segment one open
// path), the vertex dots circles and the labels glyph outlines in DejaVu Sans, so the figure stays
// sharp when projected; and device comparisons (`render --compare-device`), as SVG, PDF or PNG.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/figures/cairo_canvas.hpp"
#include "render/figures/domain_figure.hpp"

namespace pw::render {
inline namespace figures {

// What one pane of a figure drawn from patterns shows: the primitives a tessellator made
// (DomainView::capture or a capture file), the vertices and primitives for the caption
// (shownCounts), and optionally, per primitive, 1 where it is drawn in the highlight colour (the
// primitives another device made differently).
struct PatternPane {
    TessPattern pattern;
    std::array<uint64_t, 2> counts{};
    std::vector<uint8_t> highlight;
    bool numbered = false;  // each triangle's emission index at its centre (where it fits)
};

// The figure's file bytes, laid out as `layout` for a `width` x `height` pixel figure: SVG (in
// pixels) or PDF (one point a pixel) as `format` says, else a PNG drawn by the same code (cairo's
// image surface) for `output`.
std::string patternFigure(std::optional<VectorFormat> format, const std::filesystem::path& output, uint32_t width, uint32_t height,
                          const DomainFigureLayout& layout, const std::vector<PatternPane>& panes);

}  // namespace figures
}  // namespace pw::render

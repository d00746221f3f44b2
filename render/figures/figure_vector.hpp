// Domain figures as vector graphics (cairo, from Debian): SVG or PDF with the same layout, colours
// and labels as the PNG figure (render/figures/domain_figure.hpp), every triangle the tessellator made one
// closed, filled and outlined path (an isoline segment one open path), the vertex dots circles and
// the labels glyph outlines in DejaVu Sans, so the figure stays sharp when projected.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/figures/domain_figure.hpp"

namespace pw::render {

enum class VectorFormat { Svg, Pdf };

// SVG for a name ending in .svg, PDF for .pdf (any case); nothing otherwise.
std::optional<VectorFormat> vectorFormatFor(const std::string& path);

// The figure's file bytes: `patterns[i]` the primitives pane i's tessellator made (DomainView::
// capture), `counts[i]` its vertices and primitives for the caption (shownCounts), laid out as
// `layout` for a `width` x `height` pixel figure (SVG in pixels; PDF one point a pixel).
std::string domainFigureVector(VectorFormat format, uint32_t width, uint32_t height, const DomainFigureLayout& layout,
                               const std::vector<DomainPattern>& patterns, const std::vector<std::array<uint64_t, 2>>& counts);

}  // namespace pw::render

// Figures drawn with cairo (from Debian) into SVG, PDF or PNG from one drawing function: the
// domain figures' vector form (render/figures/figure_vector.hpp) and the rounding table
// (render/figures/rounding_figure.hpp) share the surface set-up, the text placement and the
// PNG read-back here.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "render/figures/label_raster.hpp"

typedef struct _cairo cairo_t;  // cairo.h's own declaration: cairo stays private to render/figures

namespace pw::render {
inline namespace figures {

enum class VectorFormat { Svg, Pdf };

// SVG for a name ending in .svg, PDF for .pdf (any case); nothing otherwise.
std::optional<VectorFormat> vectorFormatFor(const std::string& path);

// The figure's file bytes: `draw` paints a `width` x `height` pixel canvas, written as SVG (in
// pixels) or PDF (one point a pixel) as `format` says, else as a PNG for `output` (cairo's image
// surface). Throws when cairo fails.
std::string cairoFigure(std::optional<VectorFormat> format, const std::filesystem::path& output, uint32_t width, uint32_t height,
                        const std::function<void(cairo_t*)>& draw);

// Text placed as LabelRaster places it, in DejaVu Sans: `st.pixels` is the line height (ascent +
// descent), the anchor (ax, ay) picks the point of the text's box at (x, y).
void cairoText(cairo_t* cr, double x, double y, const std::string& text, const TextStyle& st, double ax, double ay);
// The advance width of `text` at line height `pixels`.
double cairoTextWidth(cairo_t* cr, const std::string& text, double pixels);

void cairoColor(cairo_t* cr, const std::array<uint8_t, 4>& c);

}  // namespace figures
}  // namespace pw::render

#include "render/figures/figure_vector.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "core/base/file_io.hpp"
#include "core/tess/tess_pattern.hpp"
#include "render/figures/pane_layout.hpp"
#include "render/targets/png_writer.hpp"

namespace pw::render {

std::optional<VectorFormat> vectorFormatFor(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".svg") return VectorFormat::Svg;
    if (ext == ".pdf") return VectorFormat::Pdf;
    return std::nullopt;
}

namespace {

using Rgba = std::array<float, 4>;

void setColor(cairo_t* cr, const Rgba& c) { cairo_set_source_rgba(cr, c[0], c[1], c[2], c[3]); }
void setColor(cairo_t* cr, const std::array<uint8_t, 4>& c) {
    cairo_set_source_rgba(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, c[3] / 255.0);
}

// Text placed as LabelRaster places it: `pixels` is the line height (ascent + descent), the anchor
// (ax, ay) picks the point of the text's box at (x, y).
void drawText(cairo_t* cr, double x, double y, const std::string& text, const TextStyle& st, double ax, double ay) {
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 100.0);
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    const double size = 100.0 * st.pixels / std::max(1e-6, fe.ascent + fe.descent);
    cairo_set_font_size(cr, size);
    cairo_font_extents(cr, &fe);
    cairo_text_extents_t te;
    cairo_text_extents(cr, text.c_str(), &te);
    const double left = x - ax * te.x_advance, top = y - ay * st.pixels;
    if (st.box) {
        const double pad = std::ceil(st.pixels * 0.2);
        setColor(cr, st.boxColor);
        cairo_rectangle(cr, left - pad, top - pad, te.x_advance + 2 * pad, st.pixels + 2 * pad);
        cairo_fill(cr);
    }
    setColor(cr, st.color);
    cairo_move_to(cr, left, top + fe.ascent);
    cairo_show_text(cr, text.c_str());
    cairo_new_path(cr);
}

// Where the differing primitives of a device comparison are filled.
const Rgba kHighlight{0.98f, 0.60f, 0.22f, 1.0f};

// Each triangle's index in the order the device emitted it, at its centre, sized to its incircle
// (left out where that is under 7 pixels).
void drawEmissionOrder(cairo_t* cr, const DomainPlacement& at, const TessPattern& pattern, float textPixels) {
    TextStyle st;
    st.color = {40, 60, 110, 255};
    for (size_t p = 0; p < pattern.primitives(); ++p) {
        std::array<std::array<float, 2>, 3> v;
        for (size_t k = 0; k < 3; ++k) {
            const auto d = domainPicturePoint(pattern.kind, pattern.uv[3 * p + k]);
            v[k] = at.toPixels(d[0], d[1]);
        }
        const auto len = [](const std::array<float, 2>& a, const std::array<float, 2>& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); };
        const float area = 0.5f * std::abs((v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0]));
        const float perimeter = len(v[0], v[1]) + len(v[1], v[2]) + len(v[2], v[0]);
        const std::string text = std::to_string(p);
        st.pixels = std::min(textPixels * 0.7f, 2.0f * area / std::max(perimeter, 1e-3f) * (text.size() > 1 ? 0.9f : 1.2f));
        if (st.pixels < 7.0f) continue;
        drawText(cr, (v[0][0] + v[1][0] + v[2][0]) / 3.0, (v[0][1] + v[1][1] + v[2][1]) / 3.0, text, st, 0.5, 0.5);
    }
}

void drawPane(cairo_t* cr, const DomainViewOptions& o, const PatternPane& pane, float textPixels) {
    const TessPattern& pattern = pane.pattern;
    cairo_save(cr);
    const auto r = pixelRect(o.rect);
    cairo_rectangle(cr, r[0], r[1], r[2], r[3]);
    cairo_clip(cr);
    setColor(cr, o.background);
    cairo_paint(cr);
    const DomainPlacement at = placeDomain(o);
    cairo_set_line_width(cr, 1.0);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    const int n = pattern.vertsPerPrimitive();
    for (size_t p = 0; p < pattern.primitives(); ++p) {
        const bool marked = p < pane.highlight.size() && pane.highlight[p];
        for (int k = 0; k < n; ++k) {
            const auto d = domainPicturePoint(pattern.kind, pattern.uv[p * size_t(n) + size_t(k)]);
            const auto px = at.toPixels(d[0], d[1]);
            k == 0 ? cairo_move_to(cr, px[0], px[1]) : cairo_line_to(cr, px[0], px[1]);
        }
        if (n == 3) {  // one closed path: filled, then outlined (one <path> in SVG)
            cairo_close_path(cr);
            setColor(cr, marked ? kHighlight : o.fillColor);
            cairo_fill_preserve(cr);
        }
        setColor(cr, marked && n == 2 ? kHighlight : o.lineColor);
        cairo_set_line_width(cr, marked && n == 2 ? 3.0 : 1.0);
        cairo_stroke(cr);
    }
    setColor(cr, o.pointColor);
    for (const auto& uv : pattern.distinctPoints()) {
        const auto d = domainPicturePoint(pattern.kind, uv);
        const auto px = at.toPixels(d[0], d[1]);
        cairo_new_sub_path(cr);
        cairo_arc(cr, px[0], px[1], 0.5 * o.pointSize, 0.0, 2.0 * M_PI);
    }
    cairo_fill(cr);
    if (pane.numbered && n == 3) drawEmissionOrder(cr, at, pattern, textPixels);
    // Lines broken where the PNG figure breaks them (its measure).
    static const LabelRaster raster;
    const auto widthOf = [&](const std::string& t) { return raster.measure(t, textPixels)[0]; };
    for (const DomainLabel& l : domainLabels(o, pane.counts[0], pane.counts[1], textPixels, widthOf))
        drawText(cr, l.x, l.y, l.text, domainLabelStyle(l.role, textPixels), l.ax, l.ay);
    cairo_restore(cr);
}

cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::string patternFigure(std::optional<VectorFormat> format, const std::filesystem::path& output, uint32_t width, uint32_t height,
                          const DomainFigureLayout& layout, const std::vector<PatternPane>& panes) {
    std::string bytes;
    cairo_surface_t* surface = !format                        ? cairo_image_surface_create(CAIRO_FORMAT_RGB24, int(width), int(height))
                               : *format == VectorFormat::Svg ? cairo_svg_surface_create_for_stream(appendBytes, &bytes, width, height)
                                                              : cairo_pdf_surface_create_for_stream(appendBytes, &bytes, width, height);
    if (format == VectorFormat::Svg) cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
    if (format == VectorFormat::Pdf) cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "Patchwork");
    cairo_t* cr = cairo_create(surface);
    cairo_font_options_t* fo = cairo_font_options_create();
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);  // advances as the PNG's labels have them
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_set_font_options(cr, fo);
    cairo_font_options_destroy(fo);
    for (size_t i = 0; i < layout.panes.size() && i < panes.size(); ++i) drawPane(cr, layout.panes[i], panes[i], layout.textPixels[i]);
    // The thin grey lines between panes (drawPaneDividers in the PNG).
    cairo_set_source_rgb(cr, 160 / 255.0, 160 / 255.0, 160 / 255.0);
    for (const auto& rf : layout.rects) {
        const auto r = pixelRect(rf);
        if (r[0] > 0) cairo_rectangle(cr, r[0], r[1], 1, r[3]);
        if (r[1] > 0) cairo_rectangle(cr, r[0], r[1], r[2], 1);
    }
    cairo_fill(cr);
    const cairo_status_t drawn = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(surface);
    std::vector<uint8_t> rgba;
    if (!format && drawn == CAIRO_STATUS_SUCCESS) {  // native-endian 0xXXRRGGBB words -> RGBA bytes
        const unsigned char* data = cairo_image_surface_get_data(surface);
        const int stride = cairo_image_surface_get_stride(surface);
        rgba.resize(size_t(width) * height * 4);
        for (uint32_t y = 0; y < height; ++y)
            for (uint32_t x = 0; x < width; ++x) {
                uint32_t px;
                std::memcpy(&px, data + size_t(y) * size_t(stride) + size_t(x) * 4, 4);
                uint8_t* o = &rgba[(size_t(y) * width + x) * 4];
                o[0] = uint8_t(px >> 16), o[1] = uint8_t(px >> 8), o[2] = uint8_t(px), o[3] = 255;
            }
    }
    cairo_surface_finish(surface);
    const cairo_status_t finished = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (drawn != CAIRO_STATUS_SUCCESS || finished != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("cairo could not write the figure: ") +
                                 cairo_status_to_string(drawn != CAIRO_STATUS_SUCCESS ? drawn : finished));
    return format ? bytes : encodePng(output, width, height, rgba);
}

}  // namespace pw::render

#include "render/figures/cairo_canvas.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/base/file_io.hpp"
#include "render/targets/png_writer.hpp"

namespace pw::render {
inline namespace figures {

std::optional<VectorFormat> vectorFormatFor(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".svg") return VectorFormat::Svg;
    if (ext == ".pdf") return VectorFormat::Pdf;
    return std::nullopt;
}

void cairoColor(cairo_t* cr, const std::array<uint8_t, 4>& c) {
    cairo_set_source_rgba(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, c[3] / 255.0);
}

namespace {

// The font size whose ascent + descent is `pixels`, selected on `cr`.
void selectFont(cairo_t* cr, double pixels) {
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 100.0);
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    cairo_set_font_size(cr, 100.0 * pixels / std::max(1e-6, fe.ascent + fe.descent));
}

cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

}  // namespace

double cairoTextWidth(cairo_t* cr, const std::string& text, double pixels) {
    selectFont(cr, pixels);
    cairo_text_extents_t te;
    cairo_text_extents(cr, text.c_str(), &te);
    return te.x_advance;
}

void cairoText(cairo_t* cr, double x, double y, const std::string& text, const TextStyle& st, double ax, double ay) {
    selectFont(cr, st.pixels);
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    cairo_text_extents_t te;
    cairo_text_extents(cr, text.c_str(), &te);
    const double left = x - ax * te.x_advance, top = y - ay * st.pixels;
    if (st.box) {
        const double pad = std::ceil(st.pixels * 0.2);
        cairoColor(cr, st.boxColor);
        cairo_rectangle(cr, left - pad, top - pad, te.x_advance + 2 * pad, st.pixels + 2 * pad);
        cairo_fill(cr);
    }
    cairoColor(cr, st.color);
    cairo_move_to(cr, left, top + fe.ascent);
    cairo_show_text(cr, text.c_str());
    cairo_new_path(cr);
}

std::string cairoFigure(std::optional<VectorFormat> format, const std::filesystem::path& output, uint32_t width, uint32_t height,
                        const std::function<void(cairo_t*)>& draw) {
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
    draw(cr);
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

}  // namespace figures
}  // namespace pw::render

#include "render/figures/figure_vector.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>

#include "core/tess/tess_pattern.hpp"
#include "render/figures/pane_layout.hpp"

namespace pw::render {
inline namespace figures {

namespace {

using Rgba = std::array<float, 4>;

void setColor(cairo_t* cr, const Rgba& c) { cairo_set_source_rgba(cr, c[0], c[1], c[2], c[3]); }

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
        cairoText(cr, (v[0][0] + v[1][0] + v[2][0]) / 3.0, (v[0][1] + v[1][1] + v[2][1]) / 3.0, text, st, 0.5, 0.5);
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
        cairoText(cr, l.x, l.y, l.text, domainLabelStyle(l.role, textPixels), l.ax, l.ay);
    cairo_restore(cr);
}

}  // namespace

std::string patternFigure(std::optional<VectorFormat> format, const std::filesystem::path& output, uint32_t width, uint32_t height,
                          const DomainFigureLayout& layout, const std::vector<PatternPane>& panes) {
    return cairoFigure(format, output, width, height, [&](cairo_t* cr) {
        for (size_t i = 0; i < layout.panes.size() && i < panes.size(); ++i) drawPane(cr, layout.panes[i], panes[i], layout.textPixels[i]);
        // The thin grey lines between panes (drawPaneDividers in the PNG).
        cairo_set_source_rgb(cr, 160 / 255.0, 160 / 255.0, 160 / 255.0);
        for (const auto& rf : layout.rects) {
            const auto r = pixelRect(rf);
            if (r[0] > 0) cairo_rectangle(cr, r[0], r[1], 1, r[3]);
            if (r[1] > 0) cairo_rectangle(cr, r[0], r[1], r[2], 1);
        }
        cairo_fill(cr);
    });
}

}  // namespace figures
}  // namespace pw::render

#include "domain_figure.hpp"

#include <algorithm>
#include <cmath>

#include "domain_labels.hpp"

namespace pw::render {

std::vector<std::array<float, 4>> splitPanes(int count, const std::array<float, 4>& a) {
    std::vector<std::array<float, 4>> out;
    const int n = std::clamp(count, 1, 4);
    const int cols = n == 1 ? 1 : 2, rows = n <= 2 ? 1 : 2;
    const float w = a[2] / float(cols), h = a[3] / float(rows);
    for (int i = 0; i < n; ++i) out.push_back({a[0] + float(i % cols) * w, a[1] + float(i / cols) * h, w, h});
    return out;
}

std::array<uint64_t, 2> shownCounts(const DomainStats& gpu, const DomainPane& pane) {
    const DomainCounts c = expectedDomainCounts(pane.kind, pane.levels, pane.spacing);
    return {c.vertices, gpu.valid ? gpu.primitives : c.primitives};
}

std::vector<DomainStats> renderDomainFigure(DomainView& view, OffscreenTarget& target, const LabelRaster& labels,
                                            const std::vector<DomainPane>& panes, float textPixels,
                                            std::vector<uint8_t>& rgba) {
    const VkExtent2D ext = target.extent();
    const auto rects = splitPanes(int(panes.size()), {0.0f, 0.0f, float(ext.width), float(ext.height)});
    std::vector<DomainViewOptions> opts;
    std::vector<float> textSizes;
    std::vector<DomainStats> stats;
    for (size_t i = 0; i < rects.size(); ++i) {
        DomainViewOptions o;
        o.kind = panes[i].kind;
        o.levels = panes[i].levels;
        o.spacing = panes[i].spacing;
        o.rect = rects[i];
        const float px = textPixels > 0.0f ? textPixels : std::clamp(std::min(o.rect[2], o.rect[3]) / 26.0f, 11.0f, 40.0f);
        o.margin = domainLabelMargin(px);
        textSizes.push_back(px);
        o.pointSize = std::clamp(px * 0.3f, 3.0f, 9.0f);
        opts.push_back(o);
    }
    stats = view.draw(target, opts, true);
    rgba = target.pixels();
    PixelImage img{ext.width, ext.height, rgba};
    for (size_t i = 0; i < opts.size(); ++i) {
        const float px = textSizes[i];
        const auto counts = shownCounts(stats[i], panes[i]);
        for (const DomainLabel& l : domainLabels(opts[i], counts[0], counts[1], px)) {
            TextStyle st;
            st.pixels = l.role == DomainLabel::Role::Title ? px * 1.1f : px;
            if (l.role == DomainLabel::Role::Edge) st.color = {150, 30, 20, 255};
            labels.draw(img, l.x, l.y, l.text, st, l.ax, l.ay);
        }
    }
    // A thin grey line along each pane's left and top edge where another pane adjoins it.
    const auto grey = [&](uint32_t x, uint32_t y) {
        if (x < ext.width && y < ext.height) std::fill_n(&rgba[(size_t(y) * ext.width + x) * 4], 3, uint8_t(160));
    };
    for (const auto& r : rects) {
        const auto x0 = uint32_t(r[0]), y0 = uint32_t(r[1]), x1 = uint32_t(r[0] + r[2]), y1 = uint32_t(r[1] + r[3]);
        if (x0 > 0)
            for (uint32_t y = y0; y < y1; ++y) grey(x0, y);
        if (y0 > 0)
            for (uint32_t x = x0; x < x1; ++x) grey(x, y0);
    }
    return stats;
}

}  // namespace pw::render

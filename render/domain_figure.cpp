#include "render/domain_figure.hpp"

#include <algorithm>
#include <cmath>

#include "render/domain_labels.hpp"

namespace pw::render {

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
        static_cast<DomainPane&>(o) = panes[i];
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
    drawPaneDividers(rgba, ext.width, ext.height, rects);
    return stats;
}

}  // namespace pw::render

#include "render/figures/domain_figure.hpp"

#include <algorithm>
#include <cmath>

#include "render/domain/domain_labels.hpp"

namespace pw::render {
inline namespace figures {

std::array<uint64_t, 2> shownCounts(const DomainStats& gpu, const DomainPane& pane) {
    const DomainCounts c = expectedDomainCounts(pane.kind, pane.levels, pane.spacing);
    return {c.vertices, gpu.valid ? gpu.primitives : c.primitives};
}

TextStyle domainLabelStyle(DomainLabel::Role role, float textPixels) {
    TextStyle st;
    st.pixels = role == DomainLabel::Role::Title ? textPixels * 1.1f : textPixels;
    if (role == DomainLabel::Role::Edge) st.color = {150, 30, 20, 255};
    return st;
}

DomainFigureLayout layoutDomainFigure(const std::vector<DomainPane>& panes, uint32_t width, uint32_t height, float textPixels,
                                      const std::string& device) {
    DomainFigureLayout l;
    l.rects = splitPanes(int(panes.size()), {0.0f, 0.0f, float(width), float(height)});
    for (size_t i = 0; i < l.rects.size(); ++i) {
        DomainViewOptions o;
        static_cast<DomainPane&>(o) = panes[i];
        o.rect = l.rects[i];
        o.device = device;
        const float px = textPixels > 0.0f ? textPixels : std::clamp(std::min(o.rect[2], o.rect[3]) / 26.0f, 11.0f, 40.0f);
        o.margin = domainLabelMargin(px);
        l.textPixels.push_back(px);
        o.pointSize = std::clamp(px * 0.3f, 3.0f, 9.0f);
        l.panes.push_back(o);
    }
    titleByPartitioning(l.panes);
    return l;
}

std::vector<DomainStats> renderDomainFigure(DomainView& view, OffscreenTarget& target, const LabelRaster& labels,
                                            const std::vector<DomainPane>& panes, float textPixels, std::vector<uint8_t>& rgba) {
    const VkExtent2D ext = target.extent();
    const DomainFigureLayout layout = layoutDomainFigure(panes, ext.width, ext.height, textPixels, view.deviceName());
    const auto& opts = layout.panes;
    const std::vector<DomainStats> stats = view.draw(target, opts, true);
    rgba = target.pixels();
    PixelImage img{ext.width, ext.height, rgba};
    for (size_t i = 0; i < opts.size(); ++i) {
        const float px = layout.textPixels[i];
        const auto counts = shownCounts(stats[i], panes[i]);
        const auto widthOf = [&](const std::string& t) { return labels.measure(t, px)[0]; };
        for (const DomainLabel& l : domainLabels(opts[i], counts[0], counts[1], px, widthOf)) {
            labels.draw(img, l.x, l.y, l.text, domainLabelStyle(l.role, px), l.ax, l.ay);
        }
    }
    drawPaneDividers(rgba, ext.width, ext.height, layout.rects);
    return stats;
}

}  // namespace figures
}  // namespace pw::render

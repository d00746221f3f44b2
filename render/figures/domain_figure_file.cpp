#include "render/figures/domain_figure_file.hpp"

#include "render/figures/domain_figure.hpp"
#include "render/figures/figure_vector.hpp"
#include "render/figures/label_raster.hpp"
#include "render/targets/offscreen_target.hpp"
#include "render/targets/png_writer.hpp"

namespace pw::render {

DomainFigureFile encodeDomainFigure(Device& dev, const std::filesystem::path& output, uint32_t w, uint32_t h,
                                    const std::vector<DomainPane>& panes, bool msaa) {
    OffscreenTarget target(dev, w, h, msaa);
    DomainView view(dev, target.colorFormat(), target.depthFormat(), target.samples());
    DomainFigureFile f;
    const auto vector = vectorFormatFor(output.string());
    if (!vector) {
        const LabelRaster labels;
        std::vector<uint8_t> rgba;
        f.stats = renderDomainFigure(view, target, labels, panes, 0.0f, rgba);
        f.bytes = encodePng(output.string(), w, h, rgba);
        return f;
    }
    // SVG or PDF: the panes drawn once for their statistics (no pixels read back, no labels
    // rasterised), and the primitives the tessellator made read back, one path each.
    const DomainFigureLayout layout = layoutDomainFigure(panes, w, h, 0.0f);
    target.setReadback(false);
    f.stats = view.draw(target, layout.panes, true);
    std::vector<DomainPattern> patterns;
    std::vector<std::array<uint64_t, 2>> counts;
    for (size_t i = 0; i < panes.size(); ++i) {
        patterns.push_back(view.capture(panes[i]));
        counts.push_back(shownCounts(f.stats[i], panes[i]));
    }
    f.bytes = domainFigureVector(*vector, w, h, layout, patterns, counts);
    return f;
}

}  // namespace pw::render

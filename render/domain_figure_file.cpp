#include "render/domain_figure_file.hpp"

#include "render/domain_figure.hpp"
#include "render/figure_vector.hpp"
#include "render/label_raster.hpp"
#include "render/offscreen_target.hpp"
#include "render/png_writer.hpp"

namespace pw::render {

DomainFigureFile encodeDomainFigure(Device& dev, const std::filesystem::path& output, uint32_t w, uint32_t h,
                                    const std::vector<DomainPane>& panes, bool msaa) {
    OffscreenTarget target(dev, w, h, msaa);
    DomainView view(dev, target.colorFormat(), target.depthFormat(), target.samples());
    const LabelRaster labels;
    std::vector<uint8_t> rgba;
    DomainFigureFile f;
    f.stats = renderDomainFigure(view, target, labels, panes, 0.0f, rgba);
    if (const auto vector = vectorFormatFor(output.string())) {
        // The primitives the tessellator made, read back, one path each.
        std::vector<DomainPattern> patterns;
        std::vector<std::array<uint64_t, 2>> counts;
        for (size_t i = 0; i < panes.size(); ++i) {
            patterns.push_back(view.capture(panes[i]));
            counts.push_back(shownCounts(f.stats[i], panes[i]));
        }
        f.bytes = domainFigureVector(*vector, w, h, layoutDomainFigure(panes, w, h, 0.0f), patterns, counts);
    } else {
        f.bytes = encodePng(output.string(), w, h, rgba);
    }
    return f;
}

}  // namespace pw::render

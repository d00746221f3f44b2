#include "render/figures/domain_figure_file.hpp"

#include "render/figures/domain_figure.hpp"
#include "render/figures/figure_vector.hpp"
#include "render/figures/label_raster.hpp"
#include "render/targets/offscreen_target.hpp"
#include "render/targets/png_writer.hpp"

namespace pw::render {
inline namespace figures {

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
    const DomainFigureLayout layout = layoutDomainFigure(panes, w, h, 0.0f, dev.name());
    target.setReadback(false);
    f.stats = view.draw(target, layout.panes, true);
    std::vector<PatternPane> shown;
    for (size_t i = 0; i < panes.size(); ++i) shown.push_back({view.capture(panes[i]), shownCounts(f.stats[i], panes[i]), {}});
    f.bytes = patternFigure(*vector, output, w, h, layout, shown);
    return f;
}

DeviceComparison encodeDeviceComparison(Device& dev, const std::filesystem::path& output, uint32_t w, uint32_t h, const DomainPane& pane,
                                        const TessPattern& other, const std::string& otherDevice) {
    DomainView view(dev, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_UNDEFINED, VK_SAMPLE_COUNT_1_BIT);
    DeviceComparison c;
    c.mine = view.capture(pane);
    c.diff = comparePatterns(c.mine, other);
    DomainFigureLayout layout = layoutDomainFigure({pane, pane}, w, h, 0.0f);
    const auto counts = [](const TessPattern& p) { return std::array<uint64_t, 2>{p.distinctPoints().size(), p.primitives()}; };
    const auto note = [&](size_t differ) { return differ == 0 ? std::string("none differ") : std::to_string(differ) + " differ"; };
    layout.panes[0].device = dev.name();
    layout.panes[0].countsNote = note(c.diff.primitivesOnlyA);
    layout.panes[1].device = otherDevice;
    layout.panes[1].countsNote = note(c.diff.primitivesOnlyB);
    c.bytes = patternFigure(vectorFormatFor(output.string()), output, w, h, layout,
                            {{c.mine, counts(c.mine), c.diff.onlyInA, true}, {other, counts(other), c.diff.onlyInB, true}});
    return c;
}

}  // namespace figures
}  // namespace pw::render

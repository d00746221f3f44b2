// Domain-view figures as a lecturer needs them: one domain, or 2 or 4 panes side by side (each with
// its own levels or partitioning), tessellated by the GPU, with every edge labelled and a caption
// of the counts (render/domain_labels). Used by `patchwork render --domain` and `patchwork sweep`.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "render/domain/domain_labels.hpp"
#include "render/domain/domain_view.hpp"
#include "render/figures/label_raster.hpp"
#include "render/figures/pane_layout.hpp"
#include "render/targets/offscreen_target.hpp"

namespace pw::render {
inline namespace figures {

// The vertices and primitives to show for a pane: the distinct vertices of the pattern (the rules:
// a GPU may run the evaluation shader more than once for a vertex, NVIDIA's does under fractional
// and pow2 spacing, so invocations are not vertices) and the primitives the GPU's statistics
// counted (the rules' where the device has no statistics).
std::array<uint64_t, 2> shownCounts(const DomainStats& gpu, const DomainPane& pane);

// Where each pane of a `width` x `height` figure goes, with its text size (`textPixels`, 0: from the
// pane size), label margin and dot size: shared by the PNG and the vector figures. Each pane's title
// names `device`, the device that drew it (none: no name).
struct DomainFigureLayout {
    std::vector<std::array<float, 4>> rects;
    std::vector<DomainViewOptions> panes;
    std::vector<float> textPixels;
};
DomainFigureLayout layoutDomainFigure(const std::vector<DomainPane>& panes, uint32_t width, uint32_t height, float textPixels,
                                      const std::string& device = {});

// How a label of this role is drawn at `textPixels` (titles larger, edge levels red).
TextStyle domainLabelStyle(DomainLabel::Role role, float textPixels);

// Draws the panes into `target` (which must read back), labels them with `labels` at `textPixels`
// line height (0: from the pane size), titled with the view's device, and returns the statistics per pane; the labelled image is
// in `rgba` (target-sized).
std::vector<DomainStats> renderDomainFigure(DomainView& view, OffscreenTarget& target, const LabelRaster& labels,
                                            const std::vector<DomainPane>& panes, float textPixels, std::vector<uint8_t>& rgba);

}  // namespace figures
}  // namespace pw::render

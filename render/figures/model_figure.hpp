// Comparison of one model under several tessellation settings: 2 or 4 panes of the same view, each
// with its own partitioning and, optionally, its own uniform level. Used by `patchwork render
// --compare`, `patchwork sweep --compare` (headless, captioned) and the editor's split viewport.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "render/figures/label_raster.hpp"
#include "render/figures/pane_layout.hpp"
#include "render/scene/renderer.hpp"
#include "render/targets/offscreen_target.hpp"

namespace pw::render {
inline namespace figures {

struct ModelPane {
    Spacing spacing = Spacing::Equal;
    float level = 0.0f;    // a uniform level for this pane (no adaptivity); 0: the document's levels
    double farther = 1.0;  // the camera this many times its distance from the target (near/far figures)
    std::string label;     // words before the caption ("far, 4x the distance"); empty: none
};

// What one pane drew: its tessellation settings (after paneOptions), its rectangle and statistics.
struct PaneResult {
    TessSettings tess;
    std::array<int, 4> rect{};
    FrameStats stats;
};

// The size in whole pixels of each of `count` panes (at least 1) sharing a width x height target.
std::array<uint32_t, 2> paneSize(int count, uint32_t width, uint32_t height);

// `base` drawn as pane `index` into `rect` (target pixels): its partitioning and level, the first
// pane clearing the target, the later ones drawing beside it.
RenderOptions paneOptions(const RenderOptions& base, const ModelPane& pane, const std::array<float, 4>& rect, size_t index);

// What a pane shows, e.g. "fractional_odd · level 4.5 · 1,234 triangles" (with `twoLines` the
// triangles go on a second line, for narrow panes); the levels are the pane's (`ts` after paneOptions).
std::string paneCaption(const TessSettings& ts, uint64_t triangles, bool twoLines = false);

// Draws the panes side by side (1, 2) or in a 2 x 2 grid (3, 4) into `target` (which must read
// back), one submission each, captions them with `labels` (`textPixels` line height, 0: from the
// pane size) and returns what each pane drew; the image is in `rgba` (target-sized).
std::vector<PaneResult> renderModelFigure(Renderer& renderer, OffscreenTarget& target, const LabelRaster& labels, const RenderOptions& base,
                                          const std::vector<ModelPane>& panes, float textPixels, std::vector<uint8_t>& rgba);

}  // namespace figures
}  // namespace pw::render

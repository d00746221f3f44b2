// Figures for slides from the editor (the `domain-figure` and `sweep-animation` commands): the
// domain view's panes as an SVG, PDF or PNG figure, and the Teaching sweep as a GIF, MP4 or WebM,
// written exactly as `patchwork render --domain` and `patchwork sweep` write them (render/
// domain_figure_file, render/sweep_figure, render/animation_writer), atomically.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"

#include "render/figures/animation_writer.hpp"
#include "render/figures/domain_figure_file.hpp"
#include "render/figures/sweep_figure.hpp"
#include "ui/editor/editor.hpp"

namespace pw::ui {
inline namespace editor {

namespace {

constexpr double kAnimationFps = 10.0;

// The panes the domain view shows (framebuffer rectangles dropped: the figure lays them out anew)
// and a figure size with the window's aspect, 1280 pixels wide.
std::vector<render::DomainPane> shownDomainPanes(const Teaching& t, uint32_t& w, uint32_t& h) {
    if (t.domainPanes.empty())
        throw EditError("the domain view is not open: show it first (Teaching > Domain view), with the panes the figure should have");
    std::vector<render::DomainPane> panes(t.domainPanes.begin(), t.domainPanes.end());
    const float aspect = t.windowRect[2] > 0.0f ? std::clamp(t.windowRect[3] / t.windowRect[2], 0.3f, 1.5f) : 0.75f;
    w = 1280;
    h = uint32_t(std::lround(1280.0f * aspect)) & ~1u;
    return panes;
}

}  // namespace

void Editor::domainFigure(const std::string& path) {
    (void)checkOutputPath(path);
    uint32_t w = 0, h = 0;
    const std::vector<render::DomainPane> panes = shownDomainPanes(teaching_, w, h);
    const render::DomainFigureFile f = render::encodeDomainFigure(window_.device(), path, w, h, panes, true);
    writeFileAtomic(path, f.bytes);
    status("Domain figure saved to " + path + " (" + std::to_string(panes.size()) + (panes.size() == 1 ? " pane)" : " panes)"));
}

void Editor::sweepAnimation(const std::string& path) {
    const auto format = render::animationFormatFor(path);
    if (!format) throw EditError("'" + path + "' is not a .gif, .mp4 or .webm file");
    (void)checkOutputPath(path);
    const Teaching::Sweep& sw = teaching_.sweep;
    render::SweepSpec spec;
    spec.from = sw.from;
    spec.to = sw.to;
    spec.frames = std::clamp(int(std::lround(double(sw.seconds) * kAnimationFps)) + 1, 2, 10000);
    if (!teaching_.domainPanes.empty()) {
        spec.domainPanes = shownDomainPanes(teaching_, spec.width, spec.height);
    } else {
        // The 3D view as it is now (camera, shading, overlays), split into its panes if it is.
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        const float viewW = teaching_.viewSplit() ? display.x : display.x - layout().left - layout().right;
        spec.width = std::max(64u, uint32_t(viewW) & ~1u);
        spec.height = std::max(64u, uint32_t(display.y) & ~1u);
        spec.document = &doc_;
        spec.heightMap = documentHeightMap();
        spec.options = drawnOptions();  // what the view shows (a heavy document screen-adaptive, as drawn)
        spec.options.hoveredPoint = spec.options.selectedPoint = -1;
        if (teaching_.viewSplit())
            for (int i = 0; i < teaching_.paneCount; ++i)
                spec.modelPanes.push_back({kPaneSpacings[teaching_.paneSpacing[size_t(i)]], 0.0f});
    }
    render::AnimationEncoder encoder(path, *format, spec.width, spec.height, kAnimationFps);
    render::renderSweep(window_.device(), spec, [&](int, const std::vector<uint8_t>& rgba) { encoder.addFrame(rgba); });
    writeFileAtomic(path, encoder.finish());
    status("Sweep animation saved to " + path + " (" + std::to_string(spec.frames) + " frames)");
}

}  // namespace editor
}  // namespace pw::ui

// Teaching: the live domain view (the quad, triangle or isoline domain tessellated by the GPU with
// the document's levels, in 1, 2 or 4 panes with their own partitioning and level), the split 3D
// view in the same panes, the notes' presets, an animated level sweep (popping under integer
// spacing, sliding under fractional), and presentation mode (F5: no editing chrome, large levels
// and counts, high contrast). Files: panel_teaching.cpp (the Teaching section of the right panel,
// the sweep, presentation on/off), panel_domain_view.cpp (the domain view window and its GPU
// panes), panel_presentation.cpp (the presentation overlay), view_panes.cpp (the split 3D view:
// pane rectangles, the pane the mouse works in, one render per pane, captions).
#pragma once

#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/domain/domain_view.hpp"
#include "render/figures/model_figure.hpp"
#include "ui/panels/panel_context.hpp"

namespace pw::render {
inline namespace scene {
class Renderer;
struct RenderOptions;
}  // namespace scene
}  // namespace pw::render
namespace pw::ui {
inline namespace platform {
class AppWindow;
}  // namespace platform
}  // namespace pw::ui

namespace pw::ui {
inline namespace panels {

// The partitionings a comparison pane can pick, in the order of its combo.
inline constexpr Spacing kPaneSpacings[] = {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2};

class Teaching {
public:
    // `shadersOpen`: the Shaders window's flag (a checkbox here opens it too).
    Teaching(AppWindow& window, bool& shadersOpen) : window_(window), shadersOpen_(shadersOpen) {}

    // panel_teaching.cpp
    void input(PanelContext& ctx);  // advances a playing sweep (one undo step when it stops)
    void setPresentation(PanelContext& ctx, bool on);
    void drawControls(PanelContext& ctx);  // the Teaching section of the right panel
    // panel_domain_view.cpp
    void drawDomainWindow(PanelContext& ctx);  // where its panes go this frame, their labels
    void drawDomainPanes();                    // after the 3D view, before ImGui: the GPU domain tessellation
    // panel_presentation.cpp
    void drawPresentationOverlay(PanelContext& ctx);
    // view_panes.cpp
    bool viewSplit() const { return splitView && paneCount > 1; }
    // Where the 3D view's panes are (window pixels): one covering the window unless split, else
    // the panes between the side panels.
    std::vector<std::array<float, 4>> viewPaneRects(const PanelLayout& layout) const;
    // The pane the mouse works in: the one under it, held while an interaction lasts (`hold`).
    std::array<float, 4> interactionPane(const PanelLayout& layout, double mouseX, double mouseY, bool hold);
    // The 3D view: one render, or one per pane; the (first pane's) stats.
    render::FrameStats renderView(render::Renderer& renderer, const render::RenderOptions& o, const PanelLayout& layout);
    void drawPaneCaptions(const PanelLayout& layout);  // each split pane's partitioning, level, triangles
    // With `stageBars`: each pane's per-stage counters (render/figures/stage_bars) in a corner,
    // from the frame that drew it; `single` is the unsplit view's stats.
    void drawStageBars(const PanelLayout& layout, const render::FrameStats& single);

    // State the editor, the Shaders window and the test trace read.
    bool showDomain = false, presentation = false;
    int domainKind = 0, paneCount = 1;
    std::array<int, 4> paneSpacing{0, 1, 2, 3};  // index into kPaneSpacings
    std::array<float, 4> paneLevel{0, 0, 0, 0};  // a pane's own uniform level; 0: the document's
    bool splitView = false;                      // the 3D view split into the same panes, one camera
    bool stageBars = false;                      // per-stage counters beside each pane
    // The debug camera: the view's camera frozen when it was turned on keeps deciding levels and
    // culling while the view moves away; the patches it culls are drawn greyed, its frustum drawn.
    std::optional<Camera> debugCamera;
    int stageBarRows = 0;  // rows drawn last frame (the test trace)
    int activePane = 0;
    std::vector<render::PaneResult> viewPanes;           // what each split pane drew last frame
    std::vector<render::DomainViewOptions> domainPanes;  // this frame's panes, framebuffer pixels
    std::array<float, 4> windowRect{0, 0, 0, 0};         // the domain window (x, y, w, h), 0 when hidden
    std::vector<std::array<float, 4>> labelBoxes;        // where its labels went (x, y, w, h; the test trace)
    std::vector<render::DomainStats> domainStats;        // the GPU's counts of the panes last drawn
    std::vector<std::array<uint64_t, 2>> domainCounts;   // this frame's panes: vertices, primitives (their labels say these)
    float domainTextPixels = 0.0f;                       // the size its labels were drawn at (the test trace)
    struct Sweep {
        bool playing = false, loop = true;
        float from = 1.0f, to = 16.0f, seconds = 4.0f, level = 1.0f;
        std::chrono::steady_clock::time_point start;
    } sweep;
    float presentationScale = 2.0f;          // the text-scale setting (presentation-text, the Teaching panel)
    std::array<float, 2> overlaySize{0, 0};  // the presentation overlay's size last frame (the test trace)
    float overlayTextRight = 0.0f;           // where its widest line ends, from the overlay's left edge
    std::vector<std::string> overlayLines;   // what it said (the test trace)
    TessSettings viewTess;                   // the levels the 3D view was last drawn with (its stats are theirs)
    // Presentation mode's label size: the text scale times the interface's font, grown with the
    // window (relative to an 800-pixel-high one), so a projector's 1080 lines get larger type.
    float presentationTextPixels() const;
    // The left edge of what presentation mode shows beside its levels box (the panes start there).
    float presentationLeft() const { return 16.0f + overlaySize[0] + 8.0f; }

    // The Bézier math overlay (ui/editor/math_overlay.cpp): one patch's evaluation at (u, v) drawn
    // on its control net. `patch` -1: the selected patch, else patch 0; a click on the surface
    // while it is on picks the patch and (u, v).
    struct MathView {
        bool on = false;
        int patch = -1;
        float u = 0.35f, v = 0.6f;
    } math;
    std::vector<std::string> mathLines;  // what its box said last frame (the test trace)
    int mathLabels = 0;                  // weight labels drawn last frame

    // The levels a preset or the sweep shows, apart from the document's, which stay the user's:
    // while active the 3D view, the domain view, the shader panel and presentation mode show these
    // (panel_teaching.cpp); "Back to document" drops them, "Keep in document" makes them one undo
    // step. Nothing else edits the document's levels from here.
    struct Lesson {
        bool active = false;
        std::string name;  // "Preset quad {1,2,3,4 | 4,4}", "Sweep"
        std::array<float, 4> outer{};
        std::array<float, 2> inner{};
        Spacing spacing = Spacing::Equal;
    } lesson;
    // `doc` with the lesson's levels and partitioning (and no adaptivity) while one is active.
    TessSettings shownTess(const TessSettings& doc) const;
    // Ends the lesson; with `keep` its levels become the document's (one undo step).
    void endLesson(PanelContext& ctx, bool keep);

private:
    AppWindow& window_;
    bool& shadersOpen_;
    std::unique_ptr<render::DomainView> domainView_;
    std::vector<render::DomainPane> drawnDomain_;  // the panes domainStats counted
};

}  // namespace panels
}  // namespace pw::ui

// The two side panels and the panels in them, one file each: left ("Scene": panel_outliner,
// panel_inspector, panel_patch_ops, panel_net, panel_surfaces), right ("Properties": panel_tessellation,
// panel_display, panel_stats, panel_continuity, then the Teaching section of ui/panels/teaching.hpp).
// Their backgrounds are not drawn by ImGui but filled by one clear each in the overlay pass
// (fills()): on CPU devices ImGui's textured, blended background quads cost ~1.5 ms a frame at
// 720p (docs/PERFORMANCE.md).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/edit/drag_controller.hpp"
#include "core/solve/continuity_report.hpp"
#include "ui/panels/panel_context.hpp"

namespace pw::ui {
inline namespace panels {

class Teaching;

// Panels without inputs of their own.
void drawOutliner(PanelContext& ctx);
void drawTessellationPanel(PanelContext& ctx);
void drawDisplayPanel(PanelContext& ctx);
void drawDisplacementPanel(PanelContext& ctx);  // ui/panels/panel_displacement.cpp
void drawStatsPanel(const FrameReport& report);

// A name being typed into the Inspector: for which item, and the field's ImGui id.
struct TypedName {
    std::string what;  // "patch", "triangle"
    uint32_t index = 0;
    std::string text;
    unsigned field = 0;
};

class InspectorPanel {  // panel_inspector.cpp: the selected point, patch or triangle
public:
    void draw(PanelContext& ctx);
    void documentReplaced() { held_.reset(); }

private:
    HeldPointEdit held_;                  // dragging the Position row holds the joins like a drag in the view
    std::optional<TypedName> typedName_;  // the name being typed into a Name row
    void setPoint(PanelContext& ctx, uint32_t p, const Vec3& position);
};

class PatchOpsPanel {  // panel_patch_ops.cpp: buttons that run the model commands, the join inputs
public:
    void draw(PanelContext& ctx);

private:
    float splitT_ = 0.5f;
    int joinA_ = 0, joinB_ = 1, joinEdgeA_ = 2, joinEdgeB_ = 0, joinKind_ = 1;
};

class SurfacesPanel {  // panel_surfaces.cpp: surfaces from the selected curve or a list of curves and edges; the selected patch's
                       // construction
public:
    void draw(PanelContext& ctx);

private:
    int axis_ = 2;
    float degrees_ = 360.0f, length_ = 1.0f;
    std::vector<std::string> sections_;  // the curves listed so far ("c0", ..., "/" in a network)
    std::string trimSurface_;            // the patch or net the trim buttons cut ("3", "n0"): the last one selected
    bool loftClosed_ = false;
    int loftEnds_[2] = {0, 0};     // G0, G1, G2 at the loft's first and last section
    double sweepTolerance_ = 0.0;  // 0: sweep1's default
    void drawTrims(PanelContext& ctx, const std::function<void(const char*, const std::string&, const char*)>& button);  // issue 64
};

class NetPanel {  // panel_net.cpp: net surfaces (create, rows/columns, closing, basis, conversion)
public:
    void draw(PanelContext& ctx);

private:
    int rows_ = 7, cols_ = 7, shape_ = 0, basis_ = 1;  // "Add net" inputs
    void drawCreate(PanelContext& ctx);                // add a net, convert patches to a net
    void drawActive(PanelContext& ctx, uint32_t net);  // the selected net's basis, closing, rows, columns
};

class ContinuityPanel {  // panel_continuity.cpp: measured continuity per join
public:
    void draw(PanelContext& ctx);

private:
    double residual_ = 0.0;  // maxConstraintResidual at version_
    uint64_t version_ = ~0ull;
    ContinuityTolerances tol_;  // the fields, while edited
    bool onlyFailing_ = false;
};

class SidePanels {
public:
    void beginFrame() { fills_.clear(); }
    void drawLeft(PanelContext& ctx);
    void drawRight(PanelContext& ctx, Teaching& teaching);
    const std::vector<std::array<float, 4>>& fills() const { return fills_; }  // this frame's panel rectangles
    const PanelLayout& layout() const { return layout_; }
    InspectorPanel inspector;

private:
    // A fixed full-height side panel window at x, with no ImGui background.
    void begin(const char* name, float x, float width);
    std::vector<std::array<float, 4>> fills_;
    PanelLayout layout_;
    PatchOpsPanel patchOps_;
    SurfacesPanel surfaces_;
    NetPanel net_;
    ContinuityPanel continuity_;
};

}  // namespace panels
}  // namespace pw::ui

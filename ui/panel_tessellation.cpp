// Tessellation (right panel): levels (linked or per edge), partitioning, adaptive modes, the
// isoline levels, culling. Each change is one undo step.
#include <imgui.h>

#include "ui/imgui_tip.hpp"
#include "ui/panel_rows.hpp"
#include "ui/side_panels.hpp"
#include "ui/test_trace.hpp"

namespace pw::ui {

void drawTessellationPanel(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Tessellation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    EditSession& s = ctx.session();
    TessSettings& ts = s.doc.tess;
    bool linked = ts.linked;
    if (ImGui::Checkbox("Link levels", &linked)) {
        ts.linked = linked;
        s.commit("Link levels");
    }
    tip("One slider drives all four outer and both inner levels");
    if (ts.linked) {
        float l = ts.outer[0];
        const bool c = ImGui::SliderFloat("Level", &l, 1.0f, 64.0f, "%.1f");
        if (c) {
            ts.outer = {l, l, l, l};
            ts.inner = {l, l};
        }
        commitEdit(ctx, c, "Tessellation level");
        tip("Outer and inner tessellation level (1-64)");
    } else {
        commitEdit(ctx, ImGui::SliderFloat4("Outer", ts.outer.data(), 1.0f, 64.0f, "%.1f"), "Outer levels");
        tip("Outer levels: edge u=0, v=0, u=1, v=1");
        commitEdit(ctx, ImGui::SliderFloat2("Inner", ts.inner.data(), 1.0f, 64.0f, "%.1f"), "Inner levels");
        tip("Inner levels along u and v");
    }
    const char* spacings[] = {"equal", "fractional odd", "fractional even", "pow2"};
    enumCombo(ctx, "Partitioning", ts.spacing, spacings, "Partitioning");
    tip("Spacing of the tessellator: equal, fractional odd/even (smooth level changes), pow2 (rounded up)");
    const char* modes[] = {"none", "distance", "screen space", "orientation"};
    enumCombo(ctx, "Adaptive", ts.adaptive, modes, "Adaptive mode");
    tip("Per-edge levels from the distance to the eye, the projected edge length, or the silhouette");
    if (ts.adaptive == AdaptiveMode::Distance) {
        commitEdit(ctx, ImGui::DragFloat("Near", &ts.distanceNear, 0.05f, 0.0f, 1e6f), "Adaptive near");
        tip("Full level at or below this distance");
        commitEdit(ctx, ImGui::DragFloat("Far", &ts.distanceFar, 0.1f, 0.0f, 1e6f), "Adaptive far");
        tip("Level 1 at or beyond this distance");
    }
    if (ts.adaptive == AdaptiveMode::ScreenSpace) {
        commitEdit(ctx, ImGui::SliderFloat("Pixels/segment", &ts.targetPixels, 1.0f, 64.0f, "%.1f"), "Target pixels");
        tip("Target length of one segment on screen (about 8 px is the lecture advice)");
    }
    commitEdit(ctx, ImGui::SliderFloat("Max level", &ts.maxLevel, 1.0f, 64.0f, "%.0f"), "Max level");
    tip("Upper clamp of every level");
    commitEdit(ctx, ImGui::SliderFloat2("Isolines", ts.isolineLevels.data(), 1.0f, 64.0f, "%.2f"), "Isoline levels");
    traceItem("tess.isolines");
    tip("Isoline domain: lines (always rounded up to an integer) and segments per line (under the partitioning). "
        "Curves draw one line; the isocurve overlay draws this many per direction, the first and last on the boundary");
    bool cb = ts.cullBackfaces, co = ts.cullOffscreen;
    if (ImGui::Checkbox("Cull back faces", &cb)) {
        ts.cullBackfaces = cb;
        s.commit("Culling");
    }
    tip("Skip patches whose control net faces away from the eye");
    ImGui::SameLine();
    if (ImGui::Checkbox("Cull off-screen", &co)) {
        ts.cullOffscreen = co;
        s.commit("Culling");
    }
    tip("Skip patches outside the view frustum");
}

}  // namespace pw::ui

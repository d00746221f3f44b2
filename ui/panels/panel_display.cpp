// Display (right panel): shading mode, overlays (control net, wireframe, normals, boundaries,
// isocurves, curvature combs with their scale and teeth), normal length, light direction,
// background. Every widget is a row of the settings table (core/model/settings.hpp) and writes the
// document through the `set` command; each change is one undo step.
#include <imgui.h>

#include "ui/panels/panel_rows.hpp"
#include "ui/panels/side_panels.hpp"

namespace pw::ui {
inline namespace panels {

void drawDisplayPanel(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
    settingRow(ctx, "display.shading");
    settingRow(ctx, "display.showGrid");
    ImGui::SameLine();
    settingRow(ctx, "display.showWireframe");
    settingRow(ctx, "display.showNormals");
    ImGui::SameLine();
    settingRow(ctx, "display.showBoundaries");
    settingRow(ctx, "display.showIsocurves");
    ImGui::SameLine();
    settingRow(ctx, "display.showCombs");
    if (ctx.session().doc.display.showCombs) {
        settingRow(ctx, "display.combScale");
        settingRow(ctx, "display.combDensity");
    }
    settingRow(ctx, "display.normalLength");
    settingRow(ctx, "display.lightDir");
    settingRow(ctx, "display.background");
}

}  // namespace panels
}  // namespace pw::ui

// Display (right panel): shading mode, overlays (control net, wireframe, normals, boundaries,
// isocurves, curvature combs with their scale and teeth), normal length, light direction, background. Each change is one undo step.
#include <imgui.h>

#include "ui/imgui_tip.hpp"
#include "ui/panel_rows.hpp"
#include "ui/side_panels.hpp"
#include "ui/test_trace.hpp"

namespace pw::ui {

void drawDisplayPanel(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
    EditSession& s = ctx.session();
    DisplaySettings& ds = s.doc.display;
    const char* shadings[] = {"lit", "normal", "patch id", "uv checker", "zebra", "gaussian curvature", "mean curvature"};
    enumCombo(ctx, "Shading", ds.shading, shadings, "Shading");
    tip("How the surface is coloured");
    auto flag = [&](const char* label, bool& v, const char* help) {
        bool b = v;
        if (ImGui::Checkbox(label, &b)) {
            v = b;
            s.commit(label);
        }
        tip(help);
    };
    flag("Control net", ds.showGrid, "Show the control points and net lines");
    ImGui::SameLine();
    flag("Wireframe", ds.showWireframe, "Show the tessellated triangles");
    flag("Normals", ds.showNormals, "Show surface normals");
    ImGui::SameLine();
    flag("Boundaries", ds.showBoundaries, "Patch boundaries coloured by continuity (grey open, red C0, green C1, blue G1, yellow C2, violet G2); joins out of tolerance thick in orange");
    traceItem("display.boundaries");
    flag("Isocurves", ds.showIsocurves, "Isoparametric curves of every patch through the isoline tessellator (levels in Tessellation)");
    traceItem("display.isocurves");
    ImGui::SameLine();
    flag("Combs", ds.showCombs,
         "Curvature combs (GPU, isoline tessellator) on every curve and on the isocurves (2 isocurve lines: the boundary curves); "
         "with a joined edge of the selected patch highlighted, the curvature graph across that join");
    traceItem("display.combs");
    if (ds.showCombs) {
        commitEdit(ctx, ImGui::SliderFloat("Comb scale", &ds.combScale, -10.0f, 10.0f, "%.3g"), "Comb scale");
        tip("Tooth length: 1 = 0.02 x model size² x curvature; negative points the teeth towards the centre of curvature");
        commitEdit(ctx, ImGui::SliderInt("Comb teeth", &ds.combDensity, 2, 21), "Comb teeth");
        tip("Teeth per curve or isocurve");
    }
    commitEdit(ctx, ImGui::SliderFloat("Normal length", &ds.normalLength, 0.001f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic), "Normal length");
    tip("Length of the drawn normals");
    commitEdit(ctx, ImGui::SliderFloat3("Light", ds.lightDir.data(), -1.0f, 1.0f, "%.2f"), "Light direction");
    tip("Direction towards the light");
    commitEdit(ctx, ImGui::ColorEdit3("Background", ds.background.data()), "Background");
    tip("Viewport clear colour");
}

}  // namespace pw::ui

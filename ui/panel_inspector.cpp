// The Inspector (left panel): the selected point's position (dragged or typed, the joins held by
// core/drag_controller.hpp's HeldPointEdit), the selected patch's or triangle's name and own
// tessellation levels.
#include <imgui.h>

#include <cstdio>

#include "ui/imgui_tip.hpp"
#include "ui/side_panels.hpp"
#include "ui/test_trace.hpp"

namespace pw::ui {

void InspectorPanel::setPoint(PanelContext& ctx, uint32_t p, const Vec3& position) {
    const std::string error = held_.set(ctx.session(), p, position);
    if (!error.empty()) return ctx.showError(error);
    ctx.documentChanged(false);
}

void InspectorPanel::draw(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Inspector", ImGuiTreeNodeFlags_DefaultOpen)) return;
    EditSession& s = ctx.session();
    Document& doc = s.doc;
    const Selection& sel = s.sel;
    if (sel.points.size() == 1 && !ctx.interacting()) {
        const uint32_t p = sel.points.front();
        ImGui::Text("Point %u", p);
        double v[3] = {doc.points[p].x, doc.points[p].y, doc.points[p].z};
        const double step = 0.001 * modelSize(doc);
        if (ImGui::DragScalarN("Position", ImGuiDataType_Double, v, 3, float(step), nullptr, nullptr, "%.4f")) {
            setPoint(ctx, p, Vec3(v[0], v[1], v[2]));
        }
        traceItem("inspector.position");
        if (ImGui::IsItemDeactivatedAfterEdit()) s.commit("Edit point");
        tip("Drag to change; joins are held (the solver moves the neighbours)");
        // Exact entry: applied when Enter is pressed.
        double typed[3] = {doc.points[p].x, doc.points[p].y, doc.points[p].z};
        if (ImGui::InputScalarN("Set", ImGuiDataType_Double, typed, 3, nullptr, nullptr, "%.6g",
                                ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CharsScientific)) {
            setPoint(ctx, p, Vec3(typed[0], typed[1], typed[2]));
            s.commit("Set point");
        }
        traceItem("inspector.set");
        tip("Type exact coordinates and press Enter; joins are held");
    } else if (sel.points.size() > 1) {
        const Vec3 c = selectionCentroid(doc, sel);
        ImGui::Text("%zu points selected", sel.points.size());
        ImGui::Text("Centre %.4f %.4f %.4f", c.x, c.y, c.z);
    } else if (sel.points.empty()) {
        ImGui::TextDisabled("No point selected");
    }
    if (sel.patch >= 0 && sel.patch < int(doc.patches.size())) {
        ImGui::Separator();
        Patch& pt = doc.patches[size_t(sel.patch)];
        ImGui::Text("Patch %d  (%s)", sel.patch, basisName(pt.basis).data());
        char name[128];
        std::snprintf(name, sizeof name, "%s", pt.name.c_str());
        if (ImGui::InputText("Name", name, sizeof name)) pt.name = name;
        if (ImGui::IsItemDeactivatedAfterEdit()) s.commit("Rename patch");
        tip("Name shown in the outliner");
        bool ov = pt.tessOverride.has_value();
        if (ImGui::Checkbox("Override tessellation", &ov)) {
            if (ov) pt.tessOverride = std::array<float, 6>{8, 8, 8, 8, 8, 8};
            else pt.tessOverride.reset();
            s.commit("Patch tessellation override");
            ctx.documentChanged(false);
        }
        tip("Give this patch its own outer/inner levels");
        if (pt.tessOverride) {
            if (ImGui::SliderFloat4("Outer##ov", pt.tessOverride->data(), 1.0f, 64.0f, "%.0f")) ctx.documentChanged(false);
            if (ImGui::IsItemDeactivatedAfterEdit()) s.commit("Patch tessellation override");
            tip("Outer levels of edges u0, v0, u1, v1");
            if (ImGui::SliderFloat2("Inner##ov", pt.tessOverride->data() + 4, 1.0f, 64.0f, "%.0f")) ctx.documentChanged(false);
            if (ImGui::IsItemDeactivatedAfterEdit()) s.commit("Patch tessellation override");
            tip("Inner levels along u and v");
        }
    }
    if (sel.triangle >= 0 && sel.triangle < int(doc.triangles.size())) {
        ImGui::Separator();
        TrianglePatch& tri = doc.triangles[size_t(sel.triangle)];
        ImGui::Text("Bézier triangle %d  (10 points)", sel.triangle);
        char name[128];
        std::snprintf(name, sizeof name, "%s", tri.name.c_str());
        if (ImGui::InputText("Name##tri", name, sizeof name)) tri.name = name;
        if (ImGui::IsItemDeactivatedAfterEdit()) s.commit("Rename triangle");
        tip("Name shown in the outliner");
        bool ov = tri.tessOverride.has_value();
        if (ImGui::Checkbox("Override tessellation##tri", &ov)) {
            if (ov) tri.tessOverride = std::array<float, 4>{8, 8, 8, 8};
            else tri.tessOverride.reset();
            s.commit("Triangle tessellation override");
            ctx.documentChanged(false);
        }
        traceItem("inspector.triOverride");
        tip("Give this triangle its own three outer levels and inner level");
        if (tri.tessOverride) {
            if (ImGui::SliderFloat3("Outer##triov", tri.tessOverride->data(), 1.0f, 64.0f, "%.0f")) ctx.documentChanged(false);
            if (ImGui::IsItemDeactivatedAfterEdit()) s.commit("Triangle tessellation override");
            tip("Outer levels of edges u = 0, v = 0, w = 0");
            if (ImGui::SliderFloat("Inner##triov", tri.tessOverride->data() + 3, 1.0f, 64.0f, "%.0f")) ctx.documentChanged(false);
            if (ImGui::IsItemDeactivatedAfterEdit()) s.commit("Triangle tessellation override");
            tip("Inner level");
        }
    }
}

}  // namespace pw::ui

// The Outliner (left panel): every patch, net surface, Bézier triangle and curve; a click selects it.
#include <imgui.h>

#include <cstdio>

#include "ui/imgui_tip.hpp"
#include "ui/side_panels.hpp"

namespace pw::ui {

void drawOutliner(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Outliner", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const Document& doc = ctx.session().doc;
    Selection& sel = ctx.session().sel;
    ImGui::BeginChild("outliner", ImVec2(0, 200), true);
    for (size_t i = 0; i < doc.patches.size(); ++i) {
        const Patch& p = doc.patches[i];
        char label[160];
        std::snprintf(label, sizeof label, "%zu  %s", i, p.name.empty() ? "patch" : p.name.c_str());
        if (ImGui::Selectable(label, sel.patch == int(i))) {
            sel.clear();
            sel.patch = int(i);
        }
    }
    for (size_t i = 0; i < doc.surfaces.size(); ++i) {
        char label[160];
        std::snprintf(label, sizeof label, "net %zu  %s (%ux%u, %s)", i, doc.surfaces[i].name.c_str(), doc.surfaces[i].rows,
                      doc.surfaces[i].cols, basisName(doc.surfaces[i].basis).data());
        if (ImGui::Selectable(label, sel.surface == int(i))) {
            sel.clear();
            sel.surface = int(i);
        }
    }
    for (size_t i = 0; i < doc.triangles.size(); ++i) {
        char label[160];
        std::snprintf(label, sizeof label, "triangle %zu  %s", i, doc.triangles[i].name.c_str());
        if (ImGui::Selectable(label, sel.triangle == int(i))) {
            sel.clear();
            sel.triangle = int(i);
        }
    }
    for (size_t i = 0; i < doc.curves.size(); ++i) {
        char label[160];
        std::snprintf(label, sizeof label, "curve %zu  %s", i, doc.curves[i].name.c_str());
        if (ImGui::Selectable(label, sel.curve == int(i))) {
            sel.clear();
            sel.curve = int(i);
            applyBox(sel, {doc.curves[i].idx.begin(), doc.curves[i].idx.end()}, false);
        }
    }
    ImGui::EndChild();
    tip("Patches, net surfaces, Bézier triangles and curves of the document; click to select one");
    ImGui::Text("%zu points, %zu patches, %zu joins", doc.points.size(), doc.patches.size(), doc.joins.size());
    if (!doc.curves.empty() || !doc.triangles.empty()) ImGui::Text("%zu triangles, %zu curves", doc.triangles.size(), doc.curves.size());
}

}  // namespace pw::ui

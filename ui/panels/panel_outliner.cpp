// The Outliner (left panel): every patch, net surface, Bézier triangle, curve (cN) and surface made
// from curves (kN, red when its inputs no longer fit; hidden items dimmed); a click selects it.
#include <imgui.h>

#include <cstdio>
#include <string>

#include "core/model/construction_refs.hpp"
#include "ui/panels/side_panels.hpp"
#include "ui/platform/imgui_tip.hpp"

namespace pw::ui {
inline namespace panels {

void drawOutliner(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Outliner", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const Document& doc = ctx.session().doc;
    Selection& sel = ctx.session().sel;
    ImGui::BeginChild("outliner", ImVec2(0, 200), true);
    // One row per item; a click selects the item alone (a curve also selects its points).
    // Hidden items (H) are dimmed and marked; Alt+H shows them again.
    auto row = [&](int& slot, size_t i, bool hidden, const char* fmt, auto... args) {
        char label[180];
        const int n = std::snprintf(label, sizeof label, fmt, i, args...);
        if (hidden && n > 0 && size_t(n) < sizeof label) std::snprintf(label + n, sizeof label - size_t(n), "  (hidden)");
        if (hidden) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        const bool clicked = ImGui::Selectable(label, slot == int(i));
        if (hidden) ImGui::PopStyleColor();
        if (!clicked) return false;
        sel.clear();
        slot = int(i);
        return true;
    };
    for (size_t i = 0; i < doc.patches.size(); ++i)
        row(sel.patch, i, doc.patches[i].hidden, "%zu  %s", doc.patches[i].name.empty() ? "patch" : doc.patches[i].name.c_str());
    for (size_t i = 0; i < doc.surfaces.size(); ++i) {
        const Surface& n = doc.surfaces[i];
        row(sel.surface, i, n.hidden, "net %zu  %s (%ux%u, %s)", n.name.c_str(), n.rows, n.cols, basisName(n.basis).data());
    }
    for (size_t i = 0; i < doc.triangles.size(); ++i)
        row(sel.triangle, i, doc.triangles[i].hidden, "triangle %zu  %s", doc.triangles[i].name.c_str());
    for (size_t i = 0; i < doc.curves.size(); ++i)
        if (row(sel.curve, i, doc.curves[i].hidden, "c%zu  %s", doc.curves[i].name.c_str()))
            applyBox(sel, {doc.curves[i].idx.begin(), doc.curves[i].idx.end()}, false);
    // Surfaces made from curves: a click selects the first patch; inputs that no longer fit in red.
    for (size_t k = 0; k < doc.constructions.size(); ++k) {
        const Construction& c = doc.constructions[k];
        const std::string label = constructionLabel(doc, k) + (c.error.empty() ? "" : "  (inputs do not fit)");
        if (!c.error.empty()) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
        const bool clicked = ImGui::Selectable(label.c_str(), !c.patches.empty() && sel.patch == int(c.patches.front()));
        if (!c.error.empty()) {
            ImGui::PopStyleColor();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.error.c_str());
        }
        if (clicked && !c.patches.empty()) {
            sel.clear();
            sel.patch = int(c.patches.front());
        }
    }
    ImGui::EndChild();
    tip("Patches, net surfaces, Bézier triangles and curves of the document; click to select one");
    ImGui::Text("%zu points, %zu patches, %zu joins", doc.points.size(), doc.patches.size(), doc.joins.size());
    if (!doc.curves.empty() || !doc.triangles.empty()) ImGui::Text("%zu triangles, %zu curves", doc.triangles.size(), doc.curves.size());
}

}  // namespace panels
}  // namespace pw::ui

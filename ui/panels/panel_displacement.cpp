// Displacement (right panel, DESIGN §11): load or remove the height map, its scale and bias (live
// while dragged, one undo step on release), the mapping, and the selected patch's, net's or
// triangle's own scale and bias.
#include <imgui.h>

#include <cmath>

#include "ui/panels/panel_rows.hpp"
#include "ui/panels/side_panels.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

namespace {

// The selection's own displacement, if the selection is a patch, net or triangle.
const std::optional<DisplacementOverride>* selectedOwn(const EditSession& s) {
    if (s.sel.patch >= 0 && size_t(s.sel.patch) < s.doc.patches.size()) return &s.doc.patches[size_t(s.sel.patch)].displacement;
    if (s.sel.surface >= 0 && size_t(s.sel.surface) < s.doc.surfaces.size()) return &s.doc.surfaces[size_t(s.sel.surface)].displacement;
    if (s.sel.triangle >= 0 && size_t(s.sel.triangle) < s.doc.triangles.size())
        return &s.doc.triangles[size_t(s.sel.triangle)].displacement;
    return nullptr;
}

}  // namespace

void drawDisplacementPanel(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Displacement")) return;
    const EditSession& s = ctx.session();
    const DisplacementSettings& d = s.doc.displacement;
    if (widget::Button("Load height map...##displacement.load")) ctx.runCommand({"displacement"});
    tip("An 8- or 16-bit PNG; the surface moves along its normal by scale x map + bias");
    if (!d.active()) {
        ImGui::TextDisabled("No height map");
        return;
    }
    ImGui::SameLine();
    if (ImGui::Button("Remove")) return ctx.runCommand({"displacement", "off"});
    ImGui::TextWrapped("%s", d.map.c_str());
    settingRow(ctx, "displacement.scale");
    settingRow(ctx, "displacement.bias");
    settingRow(ctx, "displacement.mapping");
    const float speed = float(std::max(modelSize(s.doc), 1e-6) * 1e-3);
    // The selection's own scale and bias: the displacement-own command (previewed while dragged,
    // one undo step on release).
    if (const std::optional<DisplacementOverride>* selected = selectedOwn(s)) {
        const std::optional<DisplacementOverride> own = *selected;  // a copy: a command replaces the arrays
        bool has = own.has_value();
        if (ImGui::Checkbox("Own scale and bias", &has))
            ctx.runCommand(has ? std::vector<std::string>{"displacement-own", commandWord(d.scale), commandWord(d.bias)}
                               : std::vector<std::string>{"displacement-own", "off"});
        tip("The selected patch, net or triangle displaced by its own scale and bias");
        if (own.has_value()) {
            float scale = own->scale, bias = own->bias;
            for (float* v : {&scale, &bias}) {
                const bool moved = ImGui::DragFloat(v == &scale ? "Own scale" : "Own bias", v, speed, -1e6f, 1e6f, "%.4g");
                const std::vector<std::string> words{"displacement-own", commandWord(scale), commandWord(bias)};
                if (moved) ctx.previewCommand(words);
                if (ImGui::IsItemDeactivatedAfterEdit()) ctx.runCommand(words);
            }
        }
    }
    ImGui::TextDisabled("Adaptive levels follow the map's detail");
    tip("With an adaptive mode on, each edge's level grows with the height map's detail along it and its size on screen (Stats)");
}

}  // namespace panels
}  // namespace pw::ui

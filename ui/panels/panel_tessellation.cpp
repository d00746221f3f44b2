// Tessellation (right panel): levels (linked or per edge), partitioning, adaptive modes, the
// isoline levels, culling. Every widget is a row of the settings table (core/model/settings.hpp)
// and writes the document through the `set` command; each change is one undo step.
#include <imgui.h>

#include "ui/panels/panel_rows.hpp"
#include "ui/panels/side_panels.hpp"

namespace pw::ui {
inline namespace panels {

namespace {

// What measuring the distance there means for the picture (the lecture's point about cracks).
const char* distanceFromExplanation(DistanceFrom f) {
    switch (f) {
        case DistanceFrom::Centre:
            return "One level per patch, from its centre (the notes): neighbours disagree on their shared edge, so cracks open.";
        case DistanceFrom::EdgesInnerCentre:
            return "Edges from their midpoints (neighbours agree, no crack), the inside from the centre (the terrain notes).";
        case DistanceFrom::Edges:
            break;
    }
    return "Each edge from its midpoint: neighbours agree, no crack (the notes' centre differs by up to a segment).";
}

}  // namespace

void drawTessellationPanel(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Tessellation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const TessSettings& ts = ctx.session().doc.tess;
    settingRow(ctx, "tess.linked");
    if (ts.linked) {
        settingRow(ctx, "tess.level");
    } else {
        settingRow(ctx, "tess.outer");
        settingRow(ctx, "tess.inner");
    }
    settingRow(ctx, "tess.spacing");
    settingRow(ctx, "tess.adaptive");
    if (ts.adaptive == AdaptiveMode::Distance) {
        settingRow(ctx, "tess.distanceNear");
        settingRow(ctx, "tess.distanceFar");
        settingRow(ctx, "tess.distanceCurve");
        if (ts.distanceCurve == DistanceCurve::Pow2) settingRow(ctx, "tess.distanceExponents");
        settingRow(ctx, "tess.distanceFrom");
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", distanceFromExplanation(ts.distanceFrom));
        ImGui::PopStyleColor();
        settingRow(ctx, "tess.cullFar");  // only where it applies
    }
    if (ts.adaptive == AdaptiveMode::ScreenSpace) settingRow(ctx, "tess.targetPixels");
    if (ts.adaptive != AdaptiveMode::None && ctx.session().doc.displacement.active()) settingRow(ctx, "tess.heightDetail");
    settingRow(ctx, "tess.maxLevel");
    settingRow(ctx, "tess.isoline");
    settingRow(ctx, "tess.cullBackfaces");
    ImGui::SameLine();
    settingRow(ctx, "tess.cullOffscreen");
}

}  // namespace panels
}  // namespace pw::ui

// Continuity (right panel): the joins' measured continuity against the document's tolerances
// (core/solve/continuity_watch.hpp: live next to a drag, everything when it settles), the tolerances
// themselves (the `tolerances` command), the largest constraint residual, and a table of the joins
// with the values out of tolerance in red.
#include <imgui.h>

#include <cstdio>

#include "core/model/topology.hpp"
#include "core/solve/constraint_solver.hpp"
#include "ui/panels/side_panels.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

namespace {

const ImVec4 kOut(1.0f, 0.45f, 0.3f, 1.0f);

// A value, red when out of tolerance.
void cell(const char* format, double v, bool out) {
    if (out) ImGui::PushStyleColor(ImGuiCol_Text, kOut);
    ImGui::Text(format, v);
    if (out) ImGui::PopStyleColor();
}

}  // namespace

void ContinuityPanel::draw(PanelContext& ctx) {
    if (!widget::CollapsingHeader("Continuity##panel.continuity")) return;
    const Document& doc = ctx.session().doc;
    if (version_ != ctx.documentVersion() && !ctx.interacting()) {
        residual_ = maxConstraintResidual(doc);
        version_ = ctx.documentVersion();
    }
    const ContinuityWatch& watch = ctx.continuityWatch();

    // Tolerances: edited here as one `tolerances` command each time a field is left changed.
    tol_ = ctx.interacting() || ImGui::IsAnyItemActive() ? tol_ : doc.tolerances;
    const float w = ImGui::GetContentRegionAvail().x / 3.0f - ImGui::GetStyle().ItemSpacing.x;
    bool edited = false;
    auto field = [&](const char* id, double& v, const char* format, const char* help) {
        ImGui::SetNextItemWidth(w);
        widget::InputDouble(id, &v, 0.0, 0.0, format, 0);
        edited = edited || ImGui::IsItemDeactivatedAfterEdit();
        tip(help);
    };
    field("##continuity.position", tol_.position, "%.4g", "Position tolerance (model units): the largest gap between the two sides");
    ImGui::SameLine();
    field("##continuity.angle", tol_.angleDeg, "%.3g°",
          "Angle tolerance (degrees): the largest angle between the two sides' normals (C1, G1, C2, G2)");
    ImGui::SameLine();
    field("##continuity.curvature", tol_.curvaturePct, "%.3g%%",
          "Curvature tolerance (percent): the largest curvature deviation across the seam (C2, G2)");
    if (edited && tol_ != doc.tolerances) {
        char line[160];
        std::snprintf(line, sizeof line, "tolerances %.17g %.17g %.17g", tol_.position, tol_.angleDeg, tol_.curvaturePct);
        ctx.runLine(line);
    }

    ImGui::Text("%zu of %zu joins out of tolerance", watch.outOfTolerance(), doc.joins.size());
    tip("Shown in red below, and drawn thick in orange in the viewport when Display > Boundaries is on (live while dragging)");
    ImGui::Text("Max constraint residual %.3g", !ctx.interacting() ? residual_ : 0.0);
    tip("Largest violation of the join constraints (should be <= 1e-6 x model size)");
    widget::Checkbox("Only out of tolerance##continuity.only", &onlyFailing_);
    if (ImGui::BeginTable("cont", 5, ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg, ImVec2(0, 220))) {
        ImGui::TableSetupColumn("join", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("00.u0-00.u0").x);
        ImGui::TableSetupColumn("kind", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("kind").x + ImGui::GetFrameHeight());
        ImGui::TableSetupColumn("gap");
        ImGui::TableSetupColumn("angle");
        ImGui::TableSetupColumn("curv");
        ImGui::TableHeadersRow();
        for (const JoinContinuity& c : watch.report()) {
            if (c.join >= doc.joins.size()) continue;
            const uint8_t f = watch.failures(c.join);
            if (onlyFailing_ && !f) continue;
            const Join& jn = doc.joins[c.join];
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%s %s", joinSideRef(jn, false).c_str(), joinSideRef(jn, true).c_str());
            ImGui::TableNextColumn();
            // The join's continuity, changed in place (`join A:e B:f C` on the joined pair; a refused
            // change leaves the join as it was and says why in the status line).
            ImGui::PushID(int(c.join));
            ImGui::SetNextItemWidth(-FLT_MIN);
            if (ImGui::BeginCombo("##kind", continuityName(jn.continuity).data())) {
                for (Continuity k : {Continuity::C0, Continuity::C1, Continuity::G1, Continuity::C2, Continuity::G2})
                    if ((!joinHasTriangle(jn) || k == Continuity::C0 || k == Continuity::G1) &&  // a triangle's seam: C0 or G1
                        ImGui::Selectable(continuityName(k).data(), k == jn.continuity) && k != jn.continuity)
                        ctx.runLine("join " + joinSideRef(jn, false) + " " + joinSideRef(jn, true) + " " + std::string(continuityName(k)));
                ImGui::EndCombo();
            }
            if (jn.fitted && ImGui::IsItemHovered())
                ImGui::SetTooltip(
                    "Fitted G1: a fill's side whose tangent ratio runs along it. No bicubic fill meets that exactly; "
                    "its rows hold and its angle is kept within 0.1 degrees");
            ImGui::PopID();
            ImGui::TableNextColumn();
            cell("%.2g", c.c0Gap, f & kPositionOut);
            ImGui::TableNextColumn();
            cell("%.3g°", c.normalAngleDeg, f & kAngleOut);
            ImGui::TableNextColumn();
            cell("%.3g%%", c.curvatureDeviationPct, f & kCurvatureOut);
        }
        ImGui::EndTable();
    }
    tip("Measured continuity of every join: gap, largest normal angle and curvature deviation across the seam (red: out of tolerance)");
}

}  // namespace panels
}  // namespace pw::ui

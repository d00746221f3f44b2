// Continuity (right panel): the measured C0 gap, C1 residual and normal angle of every join
// (core/continuity_report.hpp), recomputed when the document changed and no drag is under way.
#include <imgui.h>

#include "core/constraint_solver.hpp"
#include "ui/imgui_tip.hpp"
#include "ui/side_panels.hpp"
#include "ui/test_trace.hpp"

namespace pw::ui {

namespace {

const char* kEdgeNames[] = {"u0", "v0", "u1", "v1"};

}  // namespace

void ContinuityPanel::draw(PanelContext& ctx) {
    const bool open = ImGui::CollapsingHeader("Continuity");
    traceItem("panel.continuity");
    if (!open) return;
    const Document& doc = ctx.session().doc;
    if (version_ != ctx.documentVersion() && !ctx.interacting()) {
        continuity_ = continuityReport(doc, 16);
        residual_ = maxConstraintResidual(doc);
        version_ = ctx.documentVersion();
    }
    ImGui::Text("Max constraint residual %.3g", !ctx.interacting() ? residual_ : 0.0);
    tip("Largest violation of the join constraints (should be <= 1e-6 x model size)");
    if (ImGui::BeginTable("cont", 5, ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg, ImVec2(0, 220))) {
        ImGui::TableSetupColumn("join", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("00.u0-00.u0").x);
        ImGui::TableSetupColumn("kind", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("kind").x);
        ImGui::TableSetupColumn("C0 gap");
        ImGui::TableSetupColumn("C1 res");
        ImGui::TableSetupColumn("angle");
        ImGui::TableHeadersRow();
        for (const JoinContinuity& c : continuity_) {
            if (c.join >= doc.joins.size()) continue;
            const Join& jn = doc.joins[c.join];
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%u.%s-%u.%s", jn.patchA, kEdgeNames[int(jn.edgeA)], jn.patchB, kEdgeNames[int(jn.edgeB)]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(continuityName(jn.continuity).data());
            ImGui::TableNextColumn();
            ImGui::Text("%.2g", c.c0Gap);
            ImGui::TableNextColumn();
            ImGui::Text("%.2g", c.c1Residual);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f°", c.normalAngleDeg);
        }
        ImGui::EndTable();
    }
    tip("Measured continuity of every join (continuityReport)");
}

}  // namespace pw::ui

// Patch operations (left panel): buttons that run the model commands (core/commands/commands_model.cpp) —
// add, duplicate, delete, flip, extrude and split, unjoin, curves, Bézier triangles — and the
// inputs of a join between two boundary edges.
#include <imgui.h>

#include <string>

#include <algorithm>

#include "core/ops/patch_ops.hpp"
#include "ui/panels/side_panels.hpp"
#include "ui/platform/imgui_tip.hpp"

namespace pw::ui {
inline namespace panels {

namespace {

const char* kEdgeNames[] = {"u0", "v0", "u1", "v1"};

}  // namespace

void PatchOpsPanel::draw(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Patch operations", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const EditSession& s = ctx.session();
    const Document& doc = s.doc;
    const Selection& sel = s.sel;
    // Each button runs its command: disabled when the command is.
    commandButton(ctx, "Add flat patch", "add-patch", "op.addPatch");
    sameLineIfFits("Add curve");
    commandButton(ctx, "Add curve", "add-curve", "op.addCurve");
    sameLineIfFits("Duplicate");
    commandButton(ctx, "Duplicate", "duplicate");
    sameLineIfFits("Delete");
    commandButton(ctx, "Delete", "delete");
    commandButton(ctx, "Flip", "flip");
    ImGui::SameLine();
    const std::string edge(edgeName(s.activeEdge));
    commandButton(ctx, ("Extrude edge " + edge).c_str(), "extrude", "op.extrude");
    ImGui::SliderFloat("t", &splitT_, 0.05f, 0.95f, "%.2f");
    tip("Split parameter");
    commandButton(ctx, "Split at u", "split u " + std::to_string(splitT_));
    ImGui::SameLine();
    commandButton(ctx, "Split at v", "split v " + std::to_string(splitT_));
    const bool joined = sel.patch >= 0 && sel.patch < int(doc.patches.size()) && findJoin(doc, uint32_t(sel.patch), s.activeEdge) >= 0;
    ImGui::BeginDisabled(!joined);
    commandButton(ctx, "Unjoin highlighted edge", "unjoin");
    ImGui::EndDisabled();
    commandButton(ctx, ("Curve from edge " + edge).c_str(), "curve-from-edge", "op.curveFromEdge");
    ImGui::SameLine();
    ImGui::BeginDisabled(sel.curve < 0);
    commandButton(ctx, "Delete curve", "delete", "op.deleteCurve");
    ImGui::EndDisabled();
    commandButton(ctx, "Add triangle", "add-triangle", "op.addTriangle");
    ImGui::SameLine();
    ImGui::BeginDisabled(sel.triangle < 0);
    commandButton(ctx, "Delete triangle", "delete", "op.deleteTriangle");
    ImGui::EndDisabled();
    ImGui::Separator();
    commandButton(ctx, "Join by picking (J)", "join-pick", "op.joinPick");
    ImGui::TextUnformatted("or join two boundary edges by number");
    const int np = int(doc.patches.size());
    auto patchAndEdge = [](const char* ab, int& patch, int& edge) {
        const std::string id(ab);
        ImGui::SetNextItemWidth(60);
        ImGui::InputInt(("##j" + id).c_str(), &patch, 0);
        tip(("Patch " + id).c_str());
        ImGui::SameLine();
        ImGui::SetNextItemWidth(60);
        ImGui::Combo(("##je" + id).c_str(), &edge, kEdgeNames, 4);
        tip(("Edge of patch " + id).c_str());
    };
    patchAndEdge("A", joinA_, joinEdgeA_);
    ImGui::SameLine();
    patchAndEdge("B", joinB_, joinEdgeB_);
    joinA_ = std::clamp(joinA_, 0, std::max(np - 1, 0));
    joinB_ = std::clamp(joinB_, 0, std::max(np - 1, 0));
    const char* kinds[] = {"C0", "C1", "G1", "C2", "G2"};
    ImGui::SetNextItemWidth(80);
    ImGui::Combo("Continuity", &joinKind_, kinds, 5);
    tip("C0: shared edge; C1: equal tangents; G1: tangents in a fixed ratio; C2: equal first and second derivatives; "
        "G2: equal tangent planes and curvature (shape parameters fixed when joining)");
    ImGui::SameLine();
    commandButton(ctx, "Join",
                  "join " + std::to_string(joinA_) + ":" + kEdgeNames[joinEdgeA_] + " " + std::to_string(joinB_) + ":" +
                      kEdgeNames[joinEdgeB_] + " " + kinds[joinKind_]);
}

}  // namespace panels
}  // namespace pw::ui

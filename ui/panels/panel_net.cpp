// The "Net surfaces" panel (left panel): add a net (flat, tube, torus), edit the active net's rows
// and columns, close a direction, switch its basis live, keep C1 on Bézier nets, and convert between
// nets and Bézier patches. Every change is a net command (core/commands/commands_net.cpp): one undo step; errors name
// the problem in a dialog.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>

#include "core/base/limits.hpp"
#include "core/ops/net_ops.hpp"
#include "core/select/selection.hpp"
#include "core/solve/constraint_solver.hpp"
#include "ui/panels/side_panels.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

namespace {

// Row and column of pool point p in net s, or nullopt.
std::optional<std::pair<uint32_t, uint32_t>> netCell(const Surface& s, uint32_t p) {
    for (size_t k = 0; k < s.idx.size(); ++k)
        if (s.idx[k] == p) return std::pair{uint32_t(k / s.cols), uint32_t(k % s.cols)};
    return std::nullopt;
}

const char* kBasisNames[] = {"Bézier", "B-spline", "Catmull-Rom"};
const Basis kBases[] = {Basis::Bezier, Basis::BSpline, Basis::CatmullRom};
const char* kBasisWords[] = {"bezier", "bspline", "catmull-rom"};

// The selected net, or the net of the selected point; -1 when none.
int activeNet(const Document& doc, const Selection& sel) {
    if (sel.surface >= 0 && sel.surface < int(doc.surfaces.size())) return sel.surface;
    if (sel.points.size() == 1)
        for (size_t s = 0; s < doc.surfaces.size(); ++s)
            if (netCell(doc.surfaces[s], sel.points.front())) return int(s);
    return -1;
}

}  // namespace

void NetPanel::draw(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Net surfaces", ImGuiTreeNodeFlags_DefaultOpen)) return;
    drawCreate(ctx);
    const int s = activeNet(ctx.session().doc, ctx.session().sel);
    if (s < 0) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("Select a net (outliner, its surface or one of its points) to edit it");
        ImGui::PopTextWrapPos();
        return;
    }
    drawActive(ctx, uint32_t(s));
}

void NetPanel::drawCreate(PanelContext& ctx) {
    const Document& doc = ctx.session().doc;
    const Selection& sel = ctx.session().sel;
    const float uiScale = ctx.uiScale();

    // Add a net.
    ImGui::SetNextItemWidth(50 * uiScale);
    ImGui::InputInt("##netrows", &rows_, 0);
    tip("Rows of the new net (v direction), at least 4");
    ImGui::SameLine();
    ImGui::TextUnformatted("x");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(50 * uiScale);
    ImGui::InputInt("##netcols", &cols_, 0);
    tip("Columns of the new net (u direction), at least 4");
    rows_ = std::clamp(rows_, 4, int(limits::kMaxNetSide));
    cols_ = std::clamp(cols_, 4, int(limits::kMaxNetSide));
    ImGui::SameLine();
    const char* shapes[] = {"flat", "tube", "torus"};
    ImGui::SetNextItemWidth(70 * uiScale);
    ImGui::Combo("##netshape", &shape_, shapes, 3);
    tip("Flat sheet; tube (columns closed around the up axis); torus (both directions closed)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(95 * uiScale);
    ImGui::Combo("##netbasis", &basis_, kBasisNames, 3);
    tip("Basis of the new net (Bézier nets need 3k + 1 open or 3k closed rows and columns)");
    if (widget::Button("Add net##net.add"))
        ctx.runCommand({"add-net", std::to_string(rows_), std::to_string(cols_), shapes[shape_], kBasisWords[basis_]});
    tip("Add a net of that size, shape and basis at the 3D cursor (the add-net command)");

    // Patches -> net.
    const bool hasPatch = sel.patch >= 0 && sel.patch < int(doc.patches.size());
    ImGui::SameLine();
    ImGui::BeginDisabled(!hasPatch);
    if (widget::Button("Patches to B-spline net##net.fromPatches")) ctx.runCommand({"patches-to-net", std::to_string(sel.patch)});
    ImGui::EndDisabled();
    tip("Replace the selected patch and the patches joined to it by one uniform B-spline net: exact when they form a "
        "regular C2 grid (for example a converted B-spline net), refused otherwise");
}

void NetPanel::drawActive(PanelContext& ctx, uint32_t si) {
    const Document& doc = ctx.session().doc;
    const Selection& sel = ctx.session().sel;
    const float uiScale = ctx.uiScale();
    ImGui::Separator();
    const Surface& net = doc.surfaces[si];
    ImGui::Text("Net %d  %s: %u x %u, %s%s%s", int(si), net.name.c_str(), net.rows, net.cols, basisName(net.basis).data(),
                net.closedU ? ", closed u" : "", net.closedV ? ", closed v" : "");
    // What the rows below show, read before any of them runs a command (a command replaces the
    // document's arrays, `net` with them).
    const Basis netBasis = net.basis;
    const float netTension = float(net.tension);
    bool keep = net.keepC1, cu = net.closedU, cv = net.closedV;
    const auto problem = netLayoutProblem(net);
    const auto cell = sel.points.size() == 1 ? netCell(net, sel.points.front()) : std::nullopt;
    const uint32_t row = cell ? cell->first : net.rows - 1, col = cell ? cell->second : net.cols - 1;

    // Basis, tension, continuity: the net commands.
    const std::string n = std::to_string(si);
    int basis = netBasis == Basis::Bezier ? 0 : netBasis == Basis::BSpline ? 1 : 2;
    ImGui::SetNextItemWidth(120 * uiScale);
    if (ImGui::Combo("Basis##net", &basis, kBasisNames, 3)) ctx.runCommand({"net-basis", n, kBasisWords[basis]});
    tip("The same net under another basis: Bézier (windows step by 3, C0 or kept C1), uniform B-spline (C2, "
        "approximating) or Catmull-Rom (C1, through its inner points)");
    if (netBasis == Basis::CatmullRom) {
        float tension = netTension;
        ImGui::SetNextItemWidth(120 * uiScale);
        const bool moved = ImGui::SliderFloat("Tension", &tension, 0.0f, 1.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
        if (moved) ctx.previewCommand({"net-tension", n, commandWord(tension)});
        if (ImGui::IsItemDeactivatedAfterEdit()) ctx.runCommand({"net-tension", n, commandWord(tension)});
        tip("Catmull-Rom tension: 0.5 is the classic spline, 0 gives straight segments");
    }
    if (netBasis == Basis::Bezier) {
        if (ImGui::Checkbox("Keep C1 across windows", &keep)) ctx.runCommand({"net-keep-c1", n, keep ? "on" : "off"});
        tip("Hold every seam point midway between its neighbours while you drag (otherwise the windows only meet C0)");
    }
    if (problem) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", problem->c_str());

    // Closing.
    if (ImGui::Checkbox("Closed u", &cu)) ctx.runCommand({"net-closed", n, "u", cu ? "on" : "off"});
    tip("Columns wrap around: the last window joins the first (tubes, rings)");
    ImGui::SameLine();
    if (ImGui::Checkbox("Closed v", &cv)) ctx.runCommand({"net-closed", n, "v", cv ? "on" : "off"});
    tip("Rows wrap around");

    // Rows and columns at the selected point (else at the end).
    if (ImGui::Button("Insert row")) ctx.runCommand({"net-insert", n, "row", std::to_string(row + 1)});
    tip("A new row after the selected point's row (or at the end): midway between its neighbours");
    ImGui::SameLine();
    if (ImGui::Button("Insert column")) ctx.runCommand({"net-insert", n, "column", std::to_string(col + 1)});
    tip("A new column after the selected point's column (or at the end)");
    if (ImGui::Button("Delete row")) ctx.runCommand({"net-delete", n, "row", std::to_string(row)});
    tip("Remove the selected point's row (or the last); a net keeps at least 4");
    ImGui::SameLine();
    if (ImGui::Button("Delete column")) ctx.runCommand({"net-delete", n, "column", std::to_string(col)});
    tip("Remove the selected point's column (or the last)");
    if (widget::Button("Convert to Bézier patches##net.toPatches")) ctx.runCommand({"net-to-patches", n});
    tip("Replace the net by independent Bézier patches describing the same surface exactly, joined as the basis "
        "implies (C1 for splines and kept-C1 Bézier nets, C0 otherwise)");
}

}  // namespace panels
}  // namespace pw::ui

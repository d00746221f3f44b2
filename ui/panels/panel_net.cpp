// The "Net surfaces" panel (left panel): add a net (flat, tube, torus), edit the active net's rows
// and columns, close a direction, switch its basis live, keep C1 on Bézier nets, and convert between
// nets and Bézier patches. Every change is one undo step (patchOp); errors name the problem in a dialog.
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
#include "ui/platform/item_trace.hpp"

namespace pw::ui {

namespace {

// Row and column of pool point p in net s, or nullopt.
std::optional<std::pair<uint32_t, uint32_t>> netCell(const Surface& s, uint32_t p) {
    for (size_t k = 0; k < s.idx.size(); ++k)
        if (s.idx[k] == p) return std::pair{uint32_t(k / s.cols), uint32_t(k % s.cols)};
    return std::nullopt;
}

// The patches joined to patch p, directly or through others (the grid a conversion takes).
std::vector<uint32_t> joinedComponent(const Document& doc, uint32_t p) {
    std::set<uint32_t> seen{p};
    std::vector<uint32_t> todo{p};
    while (!todo.empty()) {
        const uint32_t q = todo.back();
        todo.pop_back();
        for (const Join& j : doc.joins) {
            if (!quadJoin(j)) continue;
            const uint32_t other = j.patchA == q ? j.patchB : j.patchB == q ? j.patchA : q;
            if (other != q && other < doc.patches.size() && seen.insert(other).second) todo.push_back(other);
        }
    }
    return {seen.begin(), seen.end()};
}

const char* kBasisNames[] = {"Bézier", "B-spline", "Catmull-Rom"};
const Basis kBases[] = {Basis::Bezier, Basis::BSpline, Basis::CatmullRom};

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
    EditSession& session = ctx.session();
    Document& doc = session.doc;
    Selection& sel = session.sel;
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
    if (ImGui::Button("Add net")) {
        const double size = std::max(0.5 * modelSize(doc), 1.0);
        const Vec3 c = selectionCentroid(doc, sel);
        int created = -1;
        patchOp(ctx, "Add net", [&](Document& d) {
            created =
                int(addNetSurface(d, uint32_t(rows_), uint32_t(cols_), NetShape(shape_), kBases[basis_], c, size, session.camera.zUp));
        });
        if (created >= 0) {
            sel.clear();
            sel.surface = created;
        }
    }
    traceItem("net.add");
    tip("Add a net of that size, shape and basis at the selection (or the origin)");

    // Patches -> net.
    const bool hasPatch = sel.patch >= 0 && sel.patch < int(doc.patches.size());
    ImGui::SameLine();
    ImGui::BeginDisabled(!hasPatch);
    if (ImGui::Button("Patches to B-spline net")) {
        const std::vector<uint32_t> grid = joinedComponent(doc, uint32_t(sel.patch));
        int created = -1;
        patchOp(ctx, "Convert patches to net", [&](Document& d) { created = int(convertPatchesToNet(d, grid)); });
        if (created >= 0) {
            sel.clear();
            sel.surface = created;
        }
    }
    ImGui::EndDisabled();
    traceItem("net.fromPatches");
    tip("Replace the selected patch and the patches joined to it by one uniform B-spline net: exact when they form a "
        "regular C2 grid (for example a converted B-spline net), refused otherwise");
}

void NetPanel::drawActive(PanelContext& ctx, uint32_t si) {
    EditSession& session = ctx.session();
    Document& doc = session.doc;
    Selection& sel = session.sel;
    const float uiScale = ctx.uiScale();
    ImGui::Separator();
    const Surface& net = doc.surfaces[si];
    ImGui::Text("Net %d  %s: %u x %u, %s%s%s", int(si), net.name.c_str(), net.rows, net.cols, basisName(net.basis).data(),
                net.closedU ? ", closed u" : "", net.closedV ? ", closed v" : "");

    // Basis, tension, continuity.
    int basis = net.basis == Basis::Bezier ? 0 : net.basis == Basis::BSpline ? 1 : 2;
    ImGui::SetNextItemWidth(120 * uiScale);
    if (ImGui::Combo("Basis##net", &basis, kBasisNames, 3)) {
        const Basis b = kBases[basis];
        const double t = net.tension;
        patchOp(ctx, "Net basis", [&](Document& d) {
            setNetBasis(d, si, b, t);
            if (b == Basis::Bezier && d.surfaces[si].keepC1) projectConstraints(d, {});
        });
    }
    tip("The same net under another basis: Bézier (windows step by 3, C0 or kept C1), uniform B-spline (C2, "
        "approximating) or Catmull-Rom (C1, through its inner points)");
    if (net.basis == Basis::CatmullRom) {
        float tension = float(net.tension);
        ImGui::SetNextItemWidth(120 * uiScale);
        if (ImGui::SliderFloat("Tension", &tension, 0.0f, 1.0f, "%.2f")) {
            doc.surfaces[si].tension = tension;
            ctx.documentChanged(true);
        }
        if (ImGui::IsItemDeactivatedAfterEdit()) session.commit("Net tension");
        tip("Catmull-Rom tension: 0.5 is the classic spline, 0 gives straight segments");
    }
    if (net.basis == Basis::Bezier) {
        bool keep = net.keepC1;
        if (ImGui::Checkbox("Keep C1 across windows", &keep))
            patchOp(ctx, "Net continuity", [&](Document& d) {
                d.surfaces[si].keepC1 = keep;
                if (keep) projectConstraints(d, {});
            });
        tip("Hold every seam point midway between its neighbours while you drag (otherwise the windows only meet C0)");
    }
    if (auto problem = netLayoutProblem(net)) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", problem->c_str());

    // Closing.
    bool cu = net.closedU, cv = net.closedV;
    if (ImGui::Checkbox("Closed u", &cu)) patchOp(ctx, "Close net", [&](Document& d) { setNetClosed(d, si, true, cu); });
    tip("Columns wrap around: the last window joins the first (tubes, rings)");
    ImGui::SameLine();
    if (ImGui::Checkbox("Closed v", &cv)) patchOp(ctx, "Close net", [&](Document& d) { setNetClosed(d, si, false, cv); });
    tip("Rows wrap around");

    // Rows and columns at the selected point (else at the end).
    const auto cell = sel.points.size() == 1 ? netCell(net, sel.points.front()) : std::nullopt;
    const uint32_t row = cell ? cell->first : net.rows - 1, col = cell ? cell->second : net.cols - 1;
    if (ImGui::Button("Insert row")) patchOp(ctx, "Insert net row", [&](Document& d) { insertNetRow(d, si, row + 1); });
    tip("A new row after the selected point's row (or at the end): midway between its neighbours");
    ImGui::SameLine();
    if (ImGui::Button("Insert column")) patchOp(ctx, "Insert net column", [&](Document& d) { insertNetColumn(d, si, col + 1); });
    tip("A new column after the selected point's column (or at the end)");
    if (ImGui::Button("Delete row")) {
        patchOp(ctx, "Delete net row", [&](Document& d) { deleteNetRow(d, si, row); });
        sel.points.clear();
    }
    tip("Remove the selected point's row (or the last); a net keeps at least 4");
    ImGui::SameLine();
    if (ImGui::Button("Delete column")) {
        patchOp(ctx, "Delete net column", [&](Document& d) { deleteNetColumn(d, si, col); });
        sel.points.clear();
    }
    tip("Remove the selected point's column (or the last)");
    if (ImGui::Button("Convert to Bézier patches")) {
        patchOp(ctx, "Convert net to patches", [&](Document& d) { convertNetToPatches(d, si); });
        sel.clear();
    }
    traceItem("net.toPatches");
    tip("Replace the net by independent Bézier patches describing the same surface exactly, joined as the basis "
        "implies (C1 for splines and kept-C1 Bézier nets, C0 otherwise)");
}

}  // namespace pw::ui

// The Inspector (left panel): the transform pivot and snap target, the selected point's position (dragged or typed, the joins held by
// core/edit/drag_controller.hpp's HeldPointEdit), the selected patch's or triangle's name and own
// tessellation levels, and the selected points' weight.
#include <imgui.h>
#include <imgui_internal.h>  // ImGui::GetActiveID: is the Name field still being edited

#include <cstdio>
#include <initializer_list>
#include <string>
#include <string_view>

#include "core/base/limits.hpp"
#include "ui/panels/side_panels.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

namespace {

struct OwnLevelsText {
    const char* what;     // "patch", "triangle": the item in the `rename` command
    const char* command;  // "patch-levels", "triangle-levels"
    const char* id;       // ImGui id suffix and trace name part
    const char *overrideTip, *outerTip, *innerTip;
};

// The name row and the own-levels rows of item `index`, a patch (4 outer + 2 inner) or a triangle
// (3 + 1): the `rename` and `patch-levels` / `triangle-levels` commands (previewed while a slider
// moves, one undo step on release). `name` and `levels` are copies: a command replaces the
// document's arrays. `typed` keeps the name being typed, and for which item, between frames.
template <size_t N>
void ownLevelsRows(PanelContext& ctx, const OwnLevelsText& t, uint32_t index, const std::string name,
                   const std::optional<std::array<float, N>> levels, int outerCount, std::optional<TypedName>& typed) {
    const std::string id = t.id, item = std::to_string(index);
    char buf[128];
    std::snprintf(buf, sizeof buf, "%s", name.c_str());
    ImGui::PushID(int(index));  // each item's own field: a name typed for one never lands on another
    if (widget::InputText(("Name##inspector." + id + "Name").c_str(), buf, sizeof buf))
        typed = TypedName{t.what, index, buf, ImGui::GetItemID()};
    const bool done = ImGui::IsItemDeactivatedAfterEdit();
    ImGui::PopID();
    if (done && typed) {
        ctx.runCommand({"rename", typed->what, std::to_string(typed->index), typed->text});
        typed.reset();
    }
    tip("Name shown in the outliner");
    bool ov = levels.has_value();
    if (widget::Checkbox(("Override tessellation##inspector." + id + "Override").c_str(), &ov)) {
        std::vector<std::string> words{t.command, item};
        if (ov)
            words.insert(words.end(), N, "8");
        else
            words.push_back("off");
        ctx.runCommand(words);
    }
    tip(t.overrideTip);
    if (!levels) return;
    std::array<float, N> edited = *levels;
    const float lo = 1.0f, hi = limits::kMaxTessLevel;
    const int counts[2] = {outerCount, int(N) - outerCount};
    const char* labels[2] = {"Outer##ov", "Inner##ov"};
    const char* tips[2] = {t.outerTip, t.innerTip};
    for (int k = 0; k < 2; ++k) {
        float* data = edited.data() + (k == 0 ? 0 : outerCount);
        const bool moved = ImGui::SliderScalarN((labels[k] + id).c_str(), ImGuiDataType_Float, data, counts[k], &lo, &hi, "%.0f",
                                                ImGuiSliderFlags_AlwaysClamp);
        std::vector<std::string> words{t.command, item};
        for (float v : edited) words.push_back(commandWord(v));
        if (moved) ctx.previewCommand(words);
        if (ImGui::IsItemDeactivatedAfterEdit()) ctx.runCommand(words);
        tip(tips[k]);
    }
}

}  // namespace

void InspectorPanel::setPoint(PanelContext& ctx, uint32_t p, const Vec3& position) {
    const std::string error = held_.set(ctx.session(), p, position);
    if (!error.empty()) return ctx.showError(error);
    ctx.documentChanged(false);
    if (!held_.projection().ok()) ctx.showError(conflictMessage(held_.projection()));
}

namespace {
// Pivot and snap target (one row), symmetry (the next): the `pivot`, `snap` and `symmetry` commands as combos.
void transformRow(PanelContext& ctx) {
    const EditSession& s = ctx.session();
    const float w = ImGui::GetContentRegionAvail().x * 0.5f - ImGui::GetStyle().ItemSpacing.x;
    const auto combo = [&](const char* id, const char* label, std::string_view current, std::initializer_list<std::string_view> names,
                           const char* command, const char* help) {
        ImGui::SetNextItemWidth(
            std::max(40.0f, w - ImGui::CalcTextSize(label).x - ImGui::GetStyle().ItemSpacing.x));  // the label stays whole
        if (widget::BeginCombo(id, std::string(current).c_str())) {
            for (std::string_view n : names)
                if (ImGui::Selectable(std::string(n).c_str(), n == current)) ctx.runCommand({command, std::string(n)});
            widget::EndCombo(id);
        }
        tip(help);
        ImGui::SameLine();
        ImGui::TextUnformatted(label);
    };
    combo("##inspector.pivot", "Pivot", pivotName(s.pivot), {"median", "active", "cursor"}, "pivot",
          "What R (rotate) and S (scale) turn about: the selection's median, the active point or item, or the 3D cursor");
    ImGui::SameLine();
    combo("##inspector.snap", "Snap", snapTargetName(s.snap), {"grid", "points", "edges", "surfaces"}, "snap",
          "What a move snaps to while Ctrl is held");
    const std::string sym = symmetryName(s.symmetry);
    combo("##inspector.symmetry", "Symmetry", sym, {"off", "X", "Y", "Z"}, "symmetry",
          "Live symmetry: each moved point's mirror partner follows across the plane through the 3D cursor (set when chosen)");
    if (s.symmetry.on()) {
        ImGui::SameLine();
        ImGui::TextDisabled("%c = %.4g", char('x' + s.symmetry.axis), s.symmetry.offset);
    }
}
// The weight of the selected points (rational patches): shown, and set for all of them with Enter
// through the `weight` command (its checks and its undo step).
void weightRow(PanelContext& ctx, const std::vector<uint32_t>& points) {
    const Document& doc = ctx.session().doc;
    double w = pointWeight(doc, points.front());
    bool mixed = false;
    for (uint32_t p : points) mixed = mixed || pointWeight(doc, p) != w;
    if (widget::InputDouble(mixed ? "Weight (mixed)##inspector.weight" : "Weight##inspector.weight", &w, 0.0, 0.0, "%.6g",
                            ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CharsScientific)) {
        ctx.runCommand({"weight", commandWord(w)});
    }
    tip("The weight of the selected control points (rational patches): above 1 pulls the surface towards them, below 1 lets it go; "
        "1 = polynomial. Exact circles need 1/√2 at the corners of quadratic arcs (add-sphere builds them). Type and press Enter");
}

}  // namespace

void InspectorPanel::draw(PanelContext& ctx) {
    // A name typed into a field that is no longer being edited (another item was clicked, the
    // selection cleared) is applied to the item it was typed for, as a click elsewhere applies it.
    if (typedName_ && ImGui::GetActiveID() != typedName_->field) {
        ctx.runCommand({"rename", typedName_->what, std::to_string(typedName_->index), typedName_->text});
        typedName_.reset();
    }
    if (!ImGui::CollapsingHeader("Inspector", ImGuiTreeNodeFlags_DefaultOpen)) return;
    EditSession& s = ctx.session();
    const Document& doc = s.doc;
    const Selection& sel = s.sel;
    transformRow(ctx);
    if (sel.points.size() == 1) {
        // The same rows while a drag runs (read-only then): the panel keeps its layout.
        ImGui::BeginDisabled(ctx.interacting());
        const uint32_t p = sel.points.front();
        ImGui::Text("Point %u", p);
        double v[3] = {doc.points[p].x, doc.points[p].y, doc.points[p].z};
        const double step = 0.001 * modelSize(doc);
        if (widget::DragScalarN("Position##inspector.position", ImGuiDataType_Double, v, 3, float(step), nullptr, nullptr, "%.4f")) {
            setPoint(ctx, p, Vec3(v[0], v[1], v[2]));
        }
        if (ImGui::IsItemDeactivatedAfterEdit()) {
            held_.finish(s);
            ctx.documentChanged(false);
        }
        tip("Drag to change; joins are held (the solver moves the neighbours)");
        // Exact entry: applied when Enter is pressed.
        double typed[3] = {doc.points[p].x, doc.points[p].y, doc.points[p].z};
        if (widget::InputScalarN("Set##inspector.set", ImGuiDataType_Double, typed, 3, nullptr, nullptr, "%.6g",
                                 ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CharsScientific)) {
            std::vector<std::string> words{"point", std::to_string(p)};
            for (double v : typed) words.push_back(commandWord(v));
            ctx.runCommand(words);
        }
        tip("Type exact coordinates and press Enter; joins are held");
        weightRow(ctx, sel.points);
        ImGui::EndDisabled();
    } else if (sel.points.size() > 1) {
        const Vec3 c = selectionCentroid(doc, sel);
        ImGui::Text("%zu points selected", sel.points.size());
        ImGui::Text("Centre %.4f %.4f %.4f", c.x, c.y, c.z);
        ImGui::BeginDisabled(ctx.interacting());
        weightRow(ctx, sel.points);
        ImGui::EndDisabled();
    } else if (sel.points.empty()) {
        ImGui::TextDisabled("No point selected");
    }
    if (sel.patch >= 0 && sel.patch < int(doc.patches.size())) {
        ImGui::Separator();
        const Patch& pt = doc.patches[size_t(sel.patch)];
        ImGui::Text("Patch %d  (%s)", sel.patch, basisName(pt.basis).data());
        ownLevelsRows(ctx,
                      {"patch", "patch-levels", "patch", "Give this patch its own outer/inner levels",
                       "Outer levels of edges u0, v0, u1, v1", "Inner levels along u and v"},
                      uint32_t(sel.patch), pt.name, pt.tessOverride, 4, typedName_);
    }
    if (sel.triangle >= 0 && sel.triangle < int(doc.triangles.size())) {
        ImGui::Separator();
        const TrianglePatch& tri = doc.triangles[size_t(sel.triangle)];
        ImGui::Text("Bézier triangle %d  (10 points)", sel.triangle);
        ownLevelsRows(ctx,
                      {"triangle", "triangle-levels", "tri", "Give this triangle its own three outer levels and inner level",
                       "Outer levels of edges u = 0, v = 0, w = 0", "Inner level"},
                      uint32_t(sel.triangle), tri.name, tri.tessOverride, 3, typedName_);
    }
}

}  // namespace panels
}  // namespace pw::ui

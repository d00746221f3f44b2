// Surfaces from curves (left panel, issue 39): the selected curve's constructions (revolve about
// X, Y or Z through the 3D cursor by an angle, extrude along an axis) and those of a list of curves
// collected from the selection (loft, edge surface, sweep1, sweep2, network) as buttons that run the commands of
// core/commands/commands_construct.cpp, and the selected patch's construction (its inputs, whether
// they still fit, Bake). While the mouse is over a button (or the angle slider moves) the view shows
// what it would make (Editor's construction preview).
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/model/construction_refs.hpp"
#include "ui/panels/side_panels.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

namespace {
const char* kAxes[] = {"X", "Y", "Z"};
const char* kEnds[] = {"G0", "G1", "G2"};
}  // namespace

void SurfacesPanel::draw(PanelContext& ctx) {
    if (!ImGui::CollapsingHeader("Surfaces from curves", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const EditSession& s = ctx.session();
    const Document& doc = s.doc;
    const int curve = s.sel.curve >= 0 && size_t(s.sel.curve) < doc.curves.size() ? s.sel.curve : -1;
    const std::string c = curve >= 0 ? "c" + std::to_string(curve) : "";
    if (curve < 0)
        ImGui::TextDisabled("Select a curve (Outliner) to build from it");
    else
        ImGui::Text("Curve %s: %zu segment%s%s", c.c_str(), curveSegmentCount(doc.curves[size_t(curve)]),
                    curveSegmentCount(doc.curves[size_t(curve)]) == 1 ? "" : "s", curveClosed(doc.curves[size_t(curve)]) ? ", closed" : "");
    // A button that runs its command, and while the mouse is over it shows what it would make.
    const auto button = [&](const char* label, const std::string& line, const char* trace) {
        commandButton(ctx, label, line, trace);
        if (ImGui::IsItemHovered()) ctx.previewConstruction(splitCommandWords(line));  // (disabled: not hovered)
    };
    ImGui::BeginDisabled(curve < 0);
    ImGui::SetNextItemWidth(50 * ctx.uiScale());
    ImGui::Combo("##axis", &axis_, kAxes, 3);
    tip("The axis: revolve about it (through the 3D cursor), extrude along it");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90 * ctx.uiScale());
    ImGui::SliderFloat("Angle", &degrees_, 1.0f, 360.0f, "%.0f°");
    const std::string revolve = "revolve " + c + " " + kAxes[axis_] + " " + std::to_string(degrees_);
    if (ImGui::IsItemActive() && curve >= 0) ctx.previewConstruction(splitCommandWords(revolve));
    button("Revolve", revolve, "op.revolve");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70 * ctx.uiScale());
    ImGui::InputFloat("##len", &length_, 0.0f, 0.0f, "%.3g");
    tip("Extrusion length along the axis");
    ImGui::SameLine();
    std::string d[3] = {"0", "0", "0"};
    d[axis_] = std::to_string(length_);
    button("Extrude", "extrude " + c + " " + d[0] + " " + d[1] + " " + d[2], "op.extrudeCurve");
    if (widget::Button("Add to list##surfaces.addCurve")) sections_.push_back(c);
    tip("Add the selected curve to the list the buttons below build from, in order: loft sections, edge-surface sides, "
        "sweep rails then the profile, network U curves then / then V curves");
    ImGui::EndDisabled();
    ImGui::SameLine();
    const bool patch =
        s.sel.patch >= 0 && size_t(s.sel.patch) < doc.patches.size() && doc.patches[size_t(s.sel.patch)].basis == Basis::Bezier;
    ImGui::BeginDisabled(!patch);
    if (widget::Button("Add edge##surfaces.addEdge"))
        sections_.push_back(std::to_string(s.sel.patch) + ":" + std::string(edgeName(s.activeEdge)));
    tip("Add the selected patch's highlighted edge (the one Extrude edge uses): a loft from it can leave it G1 or G2, an edge "
        "surface continues it G1");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("/")) sections_.push_back("/");
    tip("Between a network's U curves and its V curves");
    std::string list;
    for (const std::string& w : sections_) list += " " + w;
    const size_t n = sections_.size();
    const bool slash = std::find(sections_.begin(), sections_.end(), "/") != sections_.end();
    const auto build = [&](const char* label, const std::string& name, bool ok, const char* trace, const std::string& options = "") {
        ImGui::BeginDisabled(!ok);
        button(label, name + list + options, trace);
        ImGui::EndDisabled();
    };
    // The loft's and the sweep's options.
    ImGui::Checkbox("Closed", &loftClosed_);
    tip("Loft: back to the first section");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(50 * ctx.uiScale());
    widget::Combo("Start##surfaces.loftStart", &loftEnds_[0], kEnds, 3);
    tip("Loft: how the surface leaves a first section that is a patch edge (G0: position only)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(50 * ctx.uiScale());
    ImGui::Combo("End", &loftEnds_[1], kEnds, 3);
    std::string loftOptions = loftClosed_ ? " closed" : "";
    for (int e = 0; e < 2 && !loftClosed_; ++e)
        if (loftEnds_[e] > 0) loftOptions += std::string(e == 0 ? " start=" : " end=") + kEnds[loftEnds_[e]];
    build("Loft", "loft", n >= 2 && !slash, "op.loft", loftOptions);
    ImGui::SameLine();
    build("Edge surface", "edge-surface", n >= 2 && n <= 4 && !slash, "op.edgeSurface");
    ImGui::SetNextItemWidth(70 * ctx.uiScale());
    ImGui::InputDouble("##tol", &sweepTolerance_, 0.0, 0.0, "%.2g");
    tip("Sweep1: how far from the exact sweep it may be between the rail's segment ends (0: 1e-4 of the profile's size)");
    ImGui::SameLine();
    char tol[32];
    std::snprintf(tol, sizeof tol, " %.17g", sweepTolerance_);
    build("Sweep1", "sweep1", n == 2 && !slash, "op.sweep1", sweepTolerance_ > 0.0 ? tol : "");
    ImGui::SameLine();
    build("Sweep2", "sweep2", n == 3 && !slash, "op.sweep2");
    ImGui::SameLine();
    build("Network", "network", n >= 5 && slash, "op.network");
    // Blends take two patch edges from the list (Add edge).
    const bool twoEdges = n == 2 && !slash && list.find(':') != std::string::npos && list.find(" c") == std::string::npos;
    build("Blend G1", "blend", twoEdges, "op.blendG1", " G1");
    tip("Bridge the two listed patch edges, G1 at both ends; it follows both patches while they are edited");
    ImGui::SameLine();
    build("Blend G2", "blend", twoEdges, "op.blendG2", " G2");
    tip("Bridge the two listed patch edges, G2 at both ends (three spans joined C2)");
    // A hole's sides: 3 to 6 listed edges, a side of two edges end to end made with "+".
    const auto isEdge = [](const std::string& w) { return w.find(':') != std::string::npos && w[0] != 'c'; };
    const bool allEdges = std::all_of(sections_.begin(), sections_.end(), isEdge);
    build("Fill hole", "fill-hole", n >= 3 && n <= 6 && allEdges, "op.fillHole");
    tip("Fill the hole the listed edges go round, in order (3 to 6 sides): one patch per hole corner, G1 to every patch around "
        "and at its centre, held while you drag");
    ImGui::SameLine();
    const bool threeSingle = n == 3 && allEdges && std::none_of(sections_.begin(), sections_.end(), [](const std::string& w) {
                                 return w.find('+') != std::string::npos;
                             });
    build("Triangle", "fill-hole", threeSingle, "op.fillTriangle", " triangle");
    tip("Fill a hole of three listed edges with one Bézier triangle, G1 to all three, held while you drag");
    ImGui::SameLine();
    ImGui::BeginDisabled(n < 2 || !isEdge(n >= 2 ? sections_[n - 2] : "") || !isEdge(n >= 1 ? sections_[n - 1] : ""));
    if (widget::SmallButton("Join last two##surfaces.pairEdges")) {
        sections_[n - 2] += "+" + sections_[n - 1];
        sections_.pop_back();
    }
    tip("Make the last two listed edges one side of a hole (they meet end to end)");
    ImGui::EndDisabled();
    if (!sections_.empty()) {
        if (ImGui::SmallButton("Clear")) sections_.clear();
        ImGui::SameLine();
        ImGui::TextWrapped("List:%s", list.c_str());
    }
    drawTrims(ctx, button);
    // The selected patch's construction.
    const int k = s.sel.patch >= 0 ? constructionOfPatch(doc, uint32_t(s.sel.patch)) : -1;
    if (k < 0) return;
    ImGui::Separator();
    ImGui::TextWrapped("Made by %s", constructionLabel(doc, size_t(k)).c_str());
    const std::string& error = doc.constructions[size_t(k)].error;
    if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "Inputs do not fit: %s", error.c_str());
    commandButton(ctx, "Bake", "bake k" + std::to_string(k), "op.bake");
}

// Trims, holes and intersections (issue 64): the selected patch or net cut by the selected curve, and
// the intersection of two listed surfaces. Each button previews what it would make while the mouse
// is over it (the trim loops and new curves drawn over the view).
void SurfacesPanel::drawTrims(PanelContext& ctx, const std::function<void(const char*, const std::string&, const char*)>& button) {
    const EditSession& s = ctx.session();
    const Document& doc = s.doc;
    ImGui::Separator();
    ImGui::TextUnformatted("Trims, holes and intersections");
    std::string surface;  // "3" or "n0"
    if (s.sel.patch >= 0 && size_t(s.sel.patch) < doc.patches.size())
        surface = std::to_string(s.sel.patch);
    else if (s.sel.surface >= 0 && size_t(s.sel.surface) < doc.surfaces.size())
        surface = "n" + std::to_string(s.sel.surface);
    const int curve = s.sel.curve >= 0 && size_t(s.sel.curve) < doc.curves.size() ? s.sel.curve : -1;
    // The surface stays the one last selected, so a curve can be selected after it.
    if (!surface.empty()) trimSurface_ = surface;
    if (!trimSurface_.empty() && curve < 0 && surface.empty() && s.sel.empty()) trimSurface_.clear();
    const std::string c = curve >= 0 ? "c" + std::to_string(curve) : "";
    ImGui::TextDisabled("Surface %s, curve %s", trimSurface_.empty() ? "(select a patch or net)" : trimSurface_.c_str(),
                        c.empty() ? "(select one)" : c.c_str());
    const bool both = !trimSurface_.empty() && !c.empty();
    ImGui::BeginDisabled(!both);
    button("Trim", "trim " + trimSurface_ + " " + c + " keep", "op.trim");
    tip("Keep what the closed curve encloses on the surface (the curve is laid on it by closest points); the trim follows the "
        "curve and the surface live");
    ImGui::SameLine();
    button("Hole", "trim " + trimSurface_ + " " + c + " remove", "op.hole");
    tip("Cut out what the closed curve encloses on the surface");
    ImGui::SameLine();
    button("Split", "split-by " + trimSurface_ + " " + c, "op.splitBy");
    tip("Cut the surface in two along the closed curve: two trimmed surfaces that share the cut");
    ImGui::SameLine();
    button("Project", "project " + c + " " + trimSurface_, "op.project");
    tip("Lay the curve on the surface (closest points) as a new curve that follows both");
    ImGui::EndDisabled();
    ImGui::BeginDisabled(trimSurface_.empty());
    if (widget::Button("Add surface##surfaces.addSurface")) sections_.push_back(trimSurface_);
    tip("Add the selected patch or net to the list; Intersect takes two");
    ImGui::SameLine();
    ImGui::EndDisabled();
    const auto isSurface = [](const std::string& w) { return !w.empty() && w.find(':') == std::string::npos && w[0] != 'c' && w != "/"; };
    const bool two = sections_.size() == 2 && isSurface(sections_[0]) && isSurface(sections_[1]) && sections_[0] != sections_[1];
    ImGui::BeginDisabled(!two);
    button("Intersect", two ? "intersect " + sections_[0] + " " + sections_[1] : "intersect", "op.intersect");
    tip("The intersection curves of the two listed surfaces (OpenCASCADE), as new curves that follow both surfaces live; then "
        "Hole and Trim cut each surface along them");
    ImGui::EndDisabled();
    ImGui::SameLine();
    const bool trimmed = !trimSurface_.empty() && [&] {
        try {
            const bool net = trimSurface_[0] == 'n';
            const size_t i = std::stoul(trimSurface_.substr(net ? 1 : 0));
            return net ? i < doc.surfaces.size() && !doc.surfaces[i].trims.empty()
                       : i < doc.patches.size() && !doc.patches[i].trims.empty();
        } catch (const std::exception&) {
            return false;
        }
    }();
    ImGui::BeginDisabled(!trimmed);
    button("Untrim", "untrim " + trimSurface_, "op.untrim");
    tip("Remove every trim loop of the surface");
    ImGui::EndDisabled();
    if (!c.empty() && doc.curves[size_t(curve)].link) {
        const CurveLink& l = *doc.curves[size_t(curve)].link;
        if (!l.error.empty())
            ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s keeps its last shape: %s", c.c_str(), l.error.c_str());
        button("Bake curve", "bake " + c, "op.bakeCurve");
        tip("Fix the live curve (and the trims made from it): it no longer follows the surfaces");
    }
}

}  // namespace panels
}  // namespace pw::ui

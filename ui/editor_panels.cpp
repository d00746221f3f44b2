// The side panels (Outliner, Inspector, patch operations, Tessellation, Display, Stats, Continuity).
// Every control has a tooltip; buttons of editing actions run commands (core/command_table.hpp).
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <imgui.h>

#include "core/camera_math.hpp"
#include "render/device.hpp"
#include "core/document_io.hpp"
#include "ui/editor.hpp"
#include "core/limits.hpp"
#include "ui/imgui_tip.hpp"
#include "core/patch_ops.hpp"
#include "render/renderer.hpp"

namespace pw::ui {

namespace fs = std::filesystem;

namespace {

const char* kEdgeNames[] = {"u0", "v0", "u1", "v1"};

}  // namespace

void Editor::patchOp(const std::string& label, const std::function<void(Document&)>& op, bool topology) {
    try {
        session_.apply(label, op, topology);
    } catch (const std::exception& e) {
        showError(label + " failed: " + e.what());
        return;
    }
    documentChanged(topology);
}

void Editor::traceItem(const std::string& name) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    traceItems_[name] = {0.5f * (a.x + b.x), 0.5f * (a.y + b.y)};
}

void Editor::drawUi() {
    traceItems_.clear();
    openModal_.clear();
    if (presentation_) {
        drawPresentationOverlay();
    } else {
        drawMenuBar();
        drawLeftPanel();
        drawRightPanel();
    }
    drawTeachingWindow();
    drawShaderWindow();
    drawFileDialog();
    drawModals();
    if (showHelp_) drawHelp();
    if (showPalette_) drawPalette();
    // Status line.
    const ImGuiIO& io = ImGui::GetIO();
    if (!status_.empty() && std::chrono::steady_clock::now() - statusTime_ < std::chrono::seconds(6))
        ImGui::GetForegroundDrawList()->AddText(ImVec2(leftPanelWidth_ + 12.0f, io.DisplaySize.y - 24.0f), IM_COL32(220, 220, 220, 255),
                                                status_.c_str());
}

void Editor::beginSidePanel(const char* name, float x, float width) {
    const ImGuiIO& io = ImGui::GetIO();
    const float top = ImGui::GetFrameHeight();
    const std::array<float, 4> rect{x, top, width, io.DisplaySize.y - top};
    ImGui::SetNextWindowPos(ImVec2(rect[0], rect[1]));
    ImGui::SetNextWindowSize(ImVec2(rect[2], rect[3]));
    ImGui::SetNextWindowBgAlpha(0.0f);  // the overlay pass fills it (panelRects_)
    panelRects_.push_back(rect);
    ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
}

void Editor::drawLeftPanel() {
    const ImGuiIO& io = ImGui::GetIO();
    const float w = std::min(300.0f * uiScale_, io.DisplaySize.x * 0.3f);
    leftPanelWidth_ = w;
    beginSidePanel("Scene", 0.0f, w);

    // Outliner.
    if (ImGui::CollapsingHeader("Outliner", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::BeginChild("outliner", ImVec2(0, 200), true);
        for (size_t i = 0; i < doc_.patches.size(); ++i) {
            const Patch& p = doc_.patches[i];
            char label[160];
            std::snprintf(label, sizeof label, "%zu  %s", i, p.name.empty() ? "patch" : p.name.c_str());
            if (ImGui::Selectable(label, sel_.patch == int(i))) {
                sel_.clear();
                sel_.patch = int(i);
            }
        }
        for (size_t i = 0; i < doc_.surfaces.size(); ++i) {
            char label[160];
            std::snprintf(label, sizeof label, "net %zu  %s (%ux%u, %s)", i, doc_.surfaces[i].name.c_str(), doc_.surfaces[i].rows,
                          doc_.surfaces[i].cols, basisName(doc_.surfaces[i].basis).data());
            if (ImGui::Selectable(label, sel_.surface == int(i))) {
                sel_.clear();
                sel_.surface = int(i);
            }
        }
        for (size_t i = 0; i < doc_.triangles.size(); ++i) {
            char label[160];
            std::snprintf(label, sizeof label, "triangle %zu  %s", i, doc_.triangles[i].name.c_str());
            if (ImGui::Selectable(label, sel_.triangle == int(i))) {
                sel_.clear();
                sel_.triangle = int(i);
            }
        }
        for (size_t i = 0; i < doc_.curves.size(); ++i) {
            char label[160];
            std::snprintf(label, sizeof label, "curve %zu  %s", i, doc_.curves[i].name.c_str());
            if (ImGui::Selectable(label, sel_.curve == int(i))) {
                sel_.clear();
                sel_.curve = int(i);
                applyBox(sel_, {doc_.curves[i].idx.begin(), doc_.curves[i].idx.end()}, false);
            }
        }
        ImGui::EndChild();
        tip("Patches, net surfaces, Bézier triangles and curves of the document; click to select one");
        ImGui::Text("%zu points, %zu patches, %zu joins", doc_.points.size(), doc_.patches.size(), doc_.joins.size());
        if (!doc_.curves.empty() || !doc_.triangles.empty()) ImGui::Text("%zu triangles, %zu curves", doc_.triangles.size(), doc_.curves.size());
    }

    // Inspector.
    if (ImGui::CollapsingHeader("Inspector", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (sel_.points.size() == 1 && mode_ == Interaction::None) {
            const uint32_t p = sel_.points.front();
            ImGui::Text("Point %u", p);
            double v[3] = {doc_.points[p].x, doc_.points[p].y, doc_.points[p].z};
            const double step = 0.001 * modelSize(doc_);
            if (ImGui::DragScalarN("Position", ImGuiDataType_Double, v, 3, float(step), nullptr, nullptr, "%.4f")) {
                setPointHeld(p, Vec3(v[0], v[1], v[2]));
            }
            traceItem("inspector.position");
            if (ImGui::IsItemDeactivatedAfterEdit()) commit("Edit point");
            tip("Drag to change; joins are held (the solver moves the neighbours)");
            // Exact entry: applied when Enter is pressed.
            double typed[3] = {doc_.points[p].x, doc_.points[p].y, doc_.points[p].z};
            if (ImGui::InputScalarN("Set", ImGuiDataType_Double, typed, 3, nullptr, nullptr, "%.6g",
                                    ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CharsScientific)) {
                setPointHeld(p, Vec3(typed[0], typed[1], typed[2]));
                commit("Set point");
            }
            traceItem("inspector.set");
            tip("Type exact coordinates and press Enter; joins are held");
        } else if (sel_.points.size() > 1) {
            const Vec3 c = selectionCentroid(doc_, sel_);
            ImGui::Text("%zu points selected", sel_.points.size());
            ImGui::Text("Centre %.4f %.4f %.4f", c.x, c.y, c.z);
        } else if (sel_.points.empty()) {
            ImGui::TextDisabled("No point selected");
        }
        if (sel_.patch >= 0 && sel_.patch < int(doc_.patches.size())) {
            ImGui::Separator();
            Patch& pt = doc_.patches[size_t(sel_.patch)];
            ImGui::Text("Patch %d  (%s)", sel_.patch, basisName(pt.basis).data());
            char name[128];
            std::snprintf(name, sizeof name, "%s", pt.name.c_str());
            if (ImGui::InputText("Name", name, sizeof name)) pt.name = name;
            if (ImGui::IsItemDeactivatedAfterEdit()) commit("Rename patch");
            tip("Name shown in the outliner");
            bool ov = pt.tessOverride.has_value();
            if (ImGui::Checkbox("Override tessellation", &ov)) {
                if (ov) pt.tessOverride = std::array<float, 6>{8, 8, 8, 8, 8, 8};
                else pt.tessOverride.reset();
                commit("Patch tessellation override");
                documentChanged(false);
            }
            tip("Give this patch its own outer/inner levels");
            if (pt.tessOverride) {
                if (ImGui::SliderFloat4("Outer##ov", pt.tessOverride->data(), 1.0f, 64.0f, "%.0f")) documentChanged(false);
                if (ImGui::IsItemDeactivatedAfterEdit()) commit("Patch tessellation override");
                tip("Outer levels of edges u0, v0, u1, v1");
                if (ImGui::SliderFloat2("Inner##ov", pt.tessOverride->data() + 4, 1.0f, 64.0f, "%.0f")) documentChanged(false);
                if (ImGui::IsItemDeactivatedAfterEdit()) commit("Patch tessellation override");
                tip("Inner levels along u and v");
            }
        }
        if (sel_.triangle >= 0 && sel_.triangle < int(doc_.triangles.size())) {
            ImGui::Separator();
            TrianglePatch& tri = doc_.triangles[size_t(sel_.triangle)];
            ImGui::Text("Bézier triangle %d  (10 points)", sel_.triangle);
            char name[128];
            std::snprintf(name, sizeof name, "%s", tri.name.c_str());
            if (ImGui::InputText("Name##tri", name, sizeof name)) tri.name = name;
            if (ImGui::IsItemDeactivatedAfterEdit()) commit("Rename triangle");
            tip("Name shown in the outliner");
            bool ov = tri.tessOverride.has_value();
            if (ImGui::Checkbox("Override tessellation##tri", &ov)) {
                if (ov) tri.tessOverride = std::array<float, 4>{8, 8, 8, 8};
                else tri.tessOverride.reset();
                commit("Triangle tessellation override");
                documentChanged(false);
            }
            traceItem("inspector.triOverride");
            tip("Give this triangle its own three outer levels and inner level");
            if (tri.tessOverride) {
                if (ImGui::SliderFloat3("Outer##triov", tri.tessOverride->data(), 1.0f, 64.0f, "%.0f")) documentChanged(false);
                if (ImGui::IsItemDeactivatedAfterEdit()) commit("Triangle tessellation override");
                tip("Outer levels of edges u = 0, v = 0, w = 0");
                if (ImGui::SliderFloat("Inner##triov", tri.tessOverride->data() + 3, 1.0f, 64.0f, "%.0f")) documentChanged(false);
                if (ImGui::IsItemDeactivatedAfterEdit()) commit("Triangle tessellation override");
                tip("Inner level");
            }
        }
    }

    // Patch operations.
    if (ImGui::CollapsingHeader("Patch operations", ImGuiTreeNodeFlags_DefaultOpen)) {
        // Each button runs its command (core/commands_model.cpp): disabled when the command is.
        commandButton("Add flat patch", "add-patch");
        sameLineIfFits("Add curve");
        commandButton("Add curve", "add-curve", "op.addCurve");
        sameLineIfFits("Duplicate");
        commandButton("Duplicate", "duplicate");
        sameLineIfFits("Delete");
        commandButton("Delete", "delete");
        commandButton("Flip", "flip");
        ImGui::SameLine();
        const std::string edge(edgeName(lastEdge_));
        commandButton(("Extrude edge " + edge).c_str(), "extrude", "op.extrude");
        ImGui::SliderFloat("t", &splitT_, 0.05f, 0.95f, "%.2f");
        tip("Split parameter");
        commandButton("Split at u", "split u " + std::to_string(splitT_));
        ImGui::SameLine();
        commandButton("Split at v", "split v " + std::to_string(splitT_));
        const bool joined = sel_.patch >= 0 && sel_.patch < int(doc_.patches.size()) && findJoin(doc_, uint32_t(sel_.patch), lastEdge_) >= 0;
        ImGui::BeginDisabled(!joined);
        commandButton("Unjoin highlighted edge", "unjoin");
        ImGui::EndDisabled();
        commandButton(("Curve from edge " + edge).c_str(), "curve-from-edge", "op.curveFromEdge");
        ImGui::SameLine();
        ImGui::BeginDisabled(sel_.curve < 0);
        commandButton("Delete curve", "delete", "op.deleteCurve");
        ImGui::EndDisabled();
        commandButton("Add triangle", "add-triangle", "op.addTriangle");
        ImGui::SameLine();
        ImGui::BeginDisabled(sel_.triangle < 0);
        commandButton("Delete triangle", "delete", "op.deleteTriangle");
        ImGui::EndDisabled();
        ImGui::Separator();
        ImGui::TextUnformatted("Join two boundary edges");
        const int np = int(doc_.patches.size());
        ImGui::SetNextItemWidth(60);
        ImGui::InputInt("##ja", &joinA_, 0);
        tip("Patch A");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(60);
        ImGui::Combo("##jea", &joinEdgeA_, kEdgeNames, 4);
        tip("Edge of patch A");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(60);
        ImGui::InputInt("##jb", &joinB_, 0);
        tip("Patch B");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(60);
        ImGui::Combo("##jeb", &joinEdgeB_, kEdgeNames, 4);
        tip("Edge of patch B");
        joinA_ = std::clamp(joinA_, 0, std::max(np - 1, 0));
        joinB_ = std::clamp(joinB_, 0, std::max(np - 1, 0));
        const char* kinds[] = {"C0", "C1", "G1"};
        ImGui::SetNextItemWidth(80);
        ImGui::Combo("Continuity", &joinKind_, kinds, 3);
        tip("C0: shared edge; C1: equal tangents; G1: tangents in a fixed ratio");
        ImGui::SameLine();
        commandButton("Join", "join " + std::to_string(joinA_) + ":" + kEdgeNames[joinEdgeA_] + " " + std::to_string(joinB_) + ":" +
                                  kEdgeNames[joinEdgeB_] + " " + kinds[joinKind_]);
    }
    drawNetPanel();
    ImGui::End();
}

void Editor::drawRightPanel() {
    const ImGuiIO& io = ImGui::GetIO();
    const float w = std::min(330.0f * uiScale_, io.DisplaySize.x * 0.3f);
    rightPanelWidth_ = w;
    beginSidePanel("Properties", io.DisplaySize.x - w, w);
    TessSettings& ts = doc_.tess;
    DisplaySettings& ds = doc_.display;
    auto edited = [&](bool changed, const char* label) {
        if (changed) ++docVersion_;  // settings travel in the render options: nothing to upload
        if (ImGui::IsItemDeactivatedAfterEdit() || (changed && !ImGui::IsItemActive())) commit(label);
    };

    if (ImGui::CollapsingHeader("Tessellation", ImGuiTreeNodeFlags_DefaultOpen)) {
        bool linked = ts.linked;
        if (ImGui::Checkbox("Link levels", &linked)) {
            ts.linked = linked;
            commit("Link levels");
        }
        tip("One slider drives all four outer and both inner levels");
        if (ts.linked) {
            float l = ts.outer[0];
            const bool c = ImGui::SliderFloat("Level", &l, 1.0f, 64.0f, "%.1f");
            if (c) {
                ts.outer = {l, l, l, l};
                ts.inner = {l, l};
            }
            edited(c, "Tessellation level");
            tip("Outer and inner tessellation level (1-64)");
        } else {
            edited(ImGui::SliderFloat4("Outer", ts.outer.data(), 1.0f, 64.0f, "%.1f"), "Outer levels");
            tip("Outer levels: edge u=0, v=0, u=1, v=1");
            edited(ImGui::SliderFloat2("Inner", ts.inner.data(), 1.0f, 64.0f, "%.1f"), "Inner levels");
            tip("Inner levels along u and v");
        }
        const char* spacings[] = {"equal", "fractional odd", "fractional even", "pow2"};
        int sp = int(ts.spacing);
        if (ImGui::Combo("Partitioning", &sp, spacings, 4)) {
            ts.spacing = Spacing(sp);
            commit("Partitioning");
        }
        tip("Spacing of the tessellator: equal, fractional odd/even (smooth level changes), pow2 (rounded up)");
        const char* modes[] = {"none", "distance", "screen space", "orientation"};
        int am = int(ts.adaptive);
        if (ImGui::Combo("Adaptive", &am, modes, 4)) {
            ts.adaptive = AdaptiveMode(am);
            commit("Adaptive mode");
        }
        tip("Per-edge levels from the distance to the eye, the projected edge length, or the silhouette");
        if (ts.adaptive == AdaptiveMode::Distance) {
            edited(ImGui::DragFloat("Near", &ts.distanceNear, 0.05f, 0.0f, 1e6f), "Adaptive near");
            tip("Full level at or below this distance");
            edited(ImGui::DragFloat("Far", &ts.distanceFar, 0.1f, 0.0f, 1e6f), "Adaptive far");
            tip("Level 1 at or beyond this distance");
        }
        if (ts.adaptive == AdaptiveMode::ScreenSpace) {
            edited(ImGui::SliderFloat("Pixels/segment", &ts.targetPixels, 1.0f, 64.0f, "%.1f"), "Target pixels");
            tip("Target length of one segment on screen (about 8 px is the lecture advice)");
        }
        edited(ImGui::SliderFloat("Max level", &ts.maxLevel, 1.0f, 64.0f, "%.0f"), "Max level");
        tip("Upper clamp of every level");
        edited(ImGui::SliderFloat2("Isolines", ts.isolineLevels.data(), 1.0f, 64.0f, "%.2f"), "Isoline levels");
        traceItem("tess.isolines");
        tip("Isoline domain: lines (always rounded up to an integer) and segments per line (under the partitioning). "
            "Curves draw one line; the isocurve overlay draws this many per direction, the first and last on the boundary");
        bool cb = ts.cullBackfaces, co = ts.cullOffscreen;
        if (ImGui::Checkbox("Cull back faces", &cb)) {
            ts.cullBackfaces = cb;
            commit("Culling");
        }
        tip("Skip patches whose control net faces away from the eye");
        ImGui::SameLine();
        if (ImGui::Checkbox("Cull off-screen", &co)) {
            ts.cullOffscreen = co;
            commit("Culling");
        }
        tip("Skip patches outside the view frustum");
    }

    if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) {
        const char* shadings[] = {"lit", "normal", "patch id", "uv checker", "zebra", "gaussian curvature", "mean curvature"};
        int sh = int(ds.shading);
        if (ImGui::Combo("Shading", &sh, shadings, 7)) {
            ds.shading = ShadingMode(sh);
            commit("Shading");
        }
        tip("How the surface is coloured");
        auto flag = [&](const char* label, bool& v, const char* help) {
            bool b = v;
            if (ImGui::Checkbox(label, &b)) {
                v = b;
                commit(label);
            }
            tip(help);
        };
        flag("Control net", ds.showGrid, "Show the control points and net lines");
        ImGui::SameLine();
        flag("Wireframe", ds.showWireframe, "Show the tessellated triangles");
        flag("Normals", ds.showNormals, "Show surface normals");
        ImGui::SameLine();
        flag("Boundaries", ds.showBoundaries, "Patch boundaries coloured by continuity (grey open, red C0, green C1, blue G1)");
        traceItem("display.boundaries");
        flag("Isocurves", ds.showIsocurves, "Isoparametric curves of every patch through the isoline tessellator (levels in Tessellation)");
        traceItem("display.isocurves");
        edited(ImGui::SliderFloat("Normal length", &ds.normalLength, 0.001f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic), "Normal length");
        tip("Length of the drawn normals");
        edited(ImGui::SliderFloat3("Light", ds.lightDir.data(), -1.0f, 1.0f, "%.2f"), "Light direction");
        tip("Direction towards the light");
        edited(ImGui::ColorEdit3("Background", ds.background.data()), "Background");
        tip("Viewport clear colour");
    }

    if (ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("Frame       %.2f ms (work %.2f)", frameMs_, frameTimes_.total);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Time between the last two frames (paced to at most 60 fps; idle when nothing changes).\n"
                              "Work: the frame's own time, pacing excluded: UI %.2f ms (of it drag solve + upload %.3f),\n"
                              "swapchain image %.2f, 3D view %.2f, ImGui + present %.2f",
                              frameTimes_.ui, frameTimes_.drag, frameTimes_.acquire, frameTimes_.view, frameTimes_.present);
        ImGui::Text("Render      %.2f ms (CPU wall)", stats_.wallMs);
        tip("Record + submit + wait of the 3D view");
        if (stats_.gpuMs >= 0) ImGui::Text("GPU         %.2f ms", stats_.gpuMs);
        else ImGui::TextDisabled("GPU         (no timestamps)");
        tip("Timestamp queries around the frame");
        ImGui::Text("Triangles   %llu", (unsigned long long)stats_.triangles());
        tip("Triangles reaching the clipper in the surface pass");
        ImGui::Text("Evaluations %llu", (unsigned long long)stats_.tesInvocations);
        tip("Tessellation evaluation shader invocations");
        ImGui::Text("Patches     %u (culled %u)", stats_.patches, stats_.patchesCulled);
        tip("Patches drawn and patches culled by the control shader");
        ImGui::Text("Draws       %u", stats_.draws);
        tip("vkCmdDraw calls this frame");
    }

    const bool continuityOpen = ImGui::CollapsingHeader("Continuity");
    traceItem("panel.continuity");
    if (continuityOpen) {
        if (continuityVersion_ != docVersion_ && mode_ == Interaction::None) {
            continuity_ = continuityReport(doc_, 16);
            continuityResidual_ = maxConstraintResidual(doc_);
            continuityVersion_ = docVersion_;
        }
        ImGui::Text("Max constraint residual %.3g", mode_ == Interaction::None ? continuityResidual_ : 0.0);
        tip("Largest violation of the join constraints (should be <= 1e-6 x model size)");
        if (ImGui::BeginTable("cont", 5, ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg, ImVec2(0, 220))) {
            ImGui::TableSetupColumn("join", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("00.u0-00.u0").x);
            ImGui::TableSetupColumn("kind", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("kind").x);
            ImGui::TableSetupColumn("C0 gap");
            ImGui::TableSetupColumn("C1 res");
            ImGui::TableSetupColumn("angle");
            ImGui::TableHeadersRow();
            for (const JoinContinuity& c : continuity_) {
                if (c.join >= doc_.joins.size()) continue;
                const Join& jn = doc_.joins[c.join];
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
    drawTeachingControls();
    ImGui::End();
}

}  // namespace pw::ui

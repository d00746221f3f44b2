// Draw a curve by clicking (C, Add > Draw Curve): each click puts a point on the construction plane
// through the 3D cursor (the axis plane that faces the view, or XY, XZ, YZ as the panel says),
// snapped to the 3D cursor, else a control point, else a patch edge, else the grid; the curve through the points so
// far is shown live. Enter (Finish) makes it with `curve-through` (or `curve-control` when the
// points are control points) and selects it, ready to revolve, loft or sweep; Backspace takes the
// last point back; Esc drops the points, then closes the tool. Rhino's InterpCrv / Curve on the
// CPlane, with the commands' curves (core/construct/curves.hpp).
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/construct/curves.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/picking.hpp"
#include "core/select/selection.hpp"
#include "core/select/snapping.hpp"
#include "ui/editor/editor.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace editor {

namespace {
constexpr double kSnapPx = 10.0;
const char* kPlaneNames[] = {"Facing the view", "XY", "XZ", "YZ"};
const char* kAxisPlane[] = {"YZ", "XZ", "XY"};  // the plane normal to axis 0, 1, 2

std::string coordinates(const Vec3& p) {
    char b[96];
    std::snprintf(b, sizeof b, "%.17g,%.17g,%.17g", p.x, p.y, p.z);
    return b;
}
}  // namespace

void Editor::setCurveTool(bool on) {
    if (on && join_.state().on) setJoinTool(false);
    curve_.on = on;
    curve_.points.clear();
    curve_.hover.reset();
    if (on) status("Draw curve: click points on the plane through the 3D cursor; Enter makes the curve");
    wake();
}

void Editor::finishCurve() {
    const size_t need = curve_.controlPoints ? 4 : (curve_.closed ? 3 : 2);
    if (curve_.points.size() < need) {
        status("Draw curve: " + std::to_string(need) + " points or more, " + std::to_string(curve_.points.size()) + " so far");
        return;
    }
    std::vector<std::string> words{curve_.controlPoints ? "curve-control" : "curve-through"};
    for (const Vec3& p : curve_.points) words.push_back(coordinates(p));
    if (curve_.closed && !curve_.controlPoints) words.push_back("closed");
    const size_t before = doc_.curves.size();
    runCommand(words);
    if (doc_.curves.size() == before) return;  // refused: the message is shown, the points stay
    setCurveTool(false);
    status("Made curve c" + std::to_string(before) + ": revolve, extrude, loft or sweep it in Surfaces from curves");
}

void Editor::curveToolInput(double mx, double my, bool overUi) {
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureKeyboard) {
        if (keyPressed(GLFW_KEY_ESCAPE, 0)) {
            curve_.points.empty() ? setCurveTool(false) : curve_.points.clear();
            return;
        }
        if (keyPressed(GLFW_KEY_BACKSPACE, 0) && !curve_.points.empty()) curve_.points.pop_back();
        if (keyPressed(GLFW_KEY_ENTER, 0) || keyPressed(GLFW_KEY_KP_ENTER, 0)) {
            finishCurve();
            return;
        }
    }
    // The plane: through the cursor, normal to the axis nearest the view direction unless chosen.
    Vec3 r, u, f;
    cameraAxes(cam_, r, u, f);
    int axis = curve_.plane == 1 ? 2 : curve_.plane == 2 ? 1 : curve_.plane == 3 ? 0 : -1;
    if (axis < 0) {
        axis = 0;
        for (int a = 1; a < 3; ++a)
            if (std::abs(f[a]) > std::abs(f[axis])) axis = a;
    }
    curve_.planeAxis = axis;
    curve_.hover.reset();
    curve_.snapped.clear();
    if (overUi || !ImGui::IsMousePosValid()) return;
    const auto [W, H] = viewSize();
    const std::vector<bool> none;
    const auto cursorPx = projectToPixel(viewMatrices(cam_, double(W) / double(H)), session_.cursor, W, H);
    if (cursorPx && std::hypot(cursorPx->x - mx, cursorPx->y - my) <= kSnapPx) {
        curve_.hover = session_.cursor;
        curve_.snapped = "3D cursor";
    } else if ((curve_.hover = snapPoint(doc_, none, SnapTarget::Points, cam_, W, H, mx, my, kSnapPx))) {
        curve_.snapped = "point";
    } else if ((curve_.hover = snapPoint(doc_, none, SnapTarget::Edges, cam_, W, H, mx, my, kSnapPx))) {
        curve_.snapped = "edge";
    } else {
        Vec3 n(0.0);
        n[axis] = 1.0;
        curve_.hover = intersectPlane(rayThroughPixel(cam_, mx, my, W, H), session_.cursor, n);
        if (curve_.hover && curve_.gridSnap) {  // in the plane: its normal coordinate stays the cursor's
            *curve_.hover = snapToGrid(*curve_.hover, niceGridStep(std::max(modelSize(doc_), cam_.distance)) / 5.0);
            (*curve_.hover)[axis] = session_.cursor[axis];
            curve_.snapped = "grid";
        }
    }
    if (!curve_.hover || !ImGui::IsMouseClicked(ImGuiMouseButton_Left) || io.KeyAlt) return;
    if (!curve_.points.empty() && curve_.points.back() == *curve_.hover) return;  // a double click
    curve_.points.push_back(*curve_.hover);
    status("Draw curve: " + std::to_string(curve_.points.size()) + " point" + (curve_.points.size() == 1 ? "" : "s") +
           "; Enter makes the curve, Backspace takes the last back");
}

void Editor::drawCurvePanel() {
    if (!curve_.on) return;
    const ImGuiIO& io = ImGui::GetIO();
    const float left = sidePanels_.layout().left, right = io.DisplaySize.x - sidePanels_.layout().right;
    ImGui::SetNextWindowPos(ImVec2(0.5f * (left + right), ImGui::GetFrameHeight() + 8.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::Begin(
        "Draw curve", nullptr,
        ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove);
    ImGui::Text("Click points on the %s plane through the 3D cursor: %zu so far%s%s", kAxisPlane[curve_.planeAxis], curve_.points.size(),
                curve_.snapped.empty() ? "" : "; snapping to a ", curve_.snapped.c_str());
    ImGui::SetNextItemWidth(140 * uiScale());
    widget::Combo("Plane##curve.plane", &curve_.plane, kPlaneNames, 4);
    ImGui::SameLine();
    ImGui::Checkbox("Grid", &curve_.gridSnap);
    tip("Snap to the grid in the plane (points and edges always snap)");
    ImGui::SameLine();
    ImGui::Checkbox("Closed", &curve_.closed);
    ImGui::SameLine();
    ImGui::Checkbox("Control points", &curve_.controlPoints);
    tip("The points are the control points of a clamped cubic B-spline (4 or more), not points the curve passes through");
    if (widget::Button("Finish (Enter)##curve.finish")) finishCurve();
    ImGui::SameLine();
    ImGui::BeginDisabled(curve_.points.empty());
    if (ImGui::Button("Undo point (Backspace)")) curve_.points.pop_back();
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (widget::Button("Cancel (Esc)##curve.cancel")) setCurveTool(false);
    ImGui::End();
}

void Editor::drawCurveOverlay(const std::function<void(const Vec3&, const Vec3&, unsigned, float)>& line) const {
    if (!curve_.on) return;
    std::vector<Vec3> pts = curve_.points;
    if (curve_.hover) pts.push_back(*curve_.hover);
    const double mark = 0.01 * std::max(1e-9, cam_.distance);
    for (size_t i = 0; i < pts.size(); ++i) {  // a small cross at every point, the hover one yellow
        const ImU32 col = i < curve_.points.size() ? IM_COL32(90, 230, 255, 255) : IM_COL32(255, 220, 60, 255);
        for (int a = 0; a < 3; ++a) {
            Vec3 d(0.0);
            d[a] = mark;
            line(pts[i] - d, pts[i] + d, col, 2.0f);
        }
    }
    for (size_t i = 0; i + 1 < pts.size(); ++i) line(pts[i], pts[i + 1], IM_COL32(150, 150, 160, 140), 1.0f);
    // The curve those points make, as Enter would make it.
    try {
        if (pts.size() < (curve_.controlPoints ? 4u : curve_.closed ? 3u : 2u)) return;
        const CurveShape s = curve_.controlPoints ? curveControl(pts) : curveThrough(pts, curve_.closed);
        for (size_t seg = 0; seg < s.segments(); ++seg) {
            Vec3 prev = euclidean(s.points[3 * seg]);
            for (int k = 1; k <= 16; ++k) {
                const double t = k / 16.0, a = 1 - t;
                const HPoint h = a * a * a * s.points[3 * seg] + 3 * a * a * t * s.points[3 * seg + 1] +
                                 3 * a * t * t * s.points[3 * seg + 2] + t * t * t * s.points[3 * seg + 3];
                line(prev, euclidean(h), IM_COL32(90, 230, 255, 255), 2.5f);
                prev = euclidean(h);
            }
        }
    } catch (const std::exception&) {  // coincident points: no curve yet
    }
}

}  // namespace editor
}  // namespace pw::ui

// Viewport interaction (Blender conventions, DESIGN §6) and the overlays drawn with ImGui's
// background draw list: ground grid, axis gizmo, selection, box, axis-constraint line.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

#include <imgui.h>

#include "core/camera_math.hpp"
#include "core/bezier_triangle.hpp"
#include "ui/editor.hpp"
#include "core/patch_eval.hpp"
#include "core/net_ops.hpp"
#include "core/patch_ops.hpp"
#include "core/point_upload.hpp"
#include "render/renderer.hpp"

namespace pw::ui {

namespace {

constexpr double kPickRadiusPx = 9.0;
constexpr double kDragThresholdPx = 3.0;

Vec3 axisVector(int axis) {
    Vec3 a(0.0);
    a[axis] = 1.0;
    return a;
}


}  // namespace

bool Editor::keyPressed(int key, int mods) const {
    constexpr int kMask = GLFW_MOD_CONTROL | GLFW_MOD_SHIFT | GLFW_MOD_ALT | GLFW_MOD_SUPER;
    for (const auto& [k, m] : keyQueue_)
        if (k == key && (m & kMask) == mods) return true;
    return false;
}

void Editor::frameBox(const Bounds& box) {
    int W = 0, H = 0;
    glfwGetWindowSize(window_, &W, &H);
    W = std::max(W, 1), H = std::max(H, 1);
    if (viewSplit()) {  // every pane has the same size: fit the box into one
        const auto pane = viewPaneRects().front();
        cam_ = frameBounds(cam_, box, double(pane[2]) / std::max(double(pane[3]), 1.0));
        return;
    }
    // Fit the box into the part of the window between the side panels, then shift it there.
    const double left = std::min(300.0 * uiScale_, W * 0.3), right = std::min(330.0 * uiScale_, W * 0.3);
    const double visible = std::max(W - left - right, W * 0.25);
    cam_ = frameBounds(cam_, box, visible / H);
    panCamera(cam_, 0.5 * (left - right), 0.0, H);
}

std::array<int, 2> Editor::viewSize() const { return {std::max(int(viewArea_[2]), 1), std::max(int(viewArea_[3]), 1)}; }

void Editor::viewportInput() {
    ImGuiIO& io = ImGui::GetIO();
    // Mouse positions are relative to the pane the mouse works in (the whole window unless the
    // view is split): each pane is a view of its own size under the one camera.
    viewArea_ = interactionPane(io.MousePos.x, io.MousePos.y);
    const double mx = io.MousePos.x - viewArea_[0], my = io.MousePos.y - viewArea_[1];
    const auto [W, H] = viewSize();
    const bool overUi = io.WantCaptureMouse && mode_ == Interaction::None;
    const bool mouseValid = ImGui::IsMousePosValid();

    // Step 1: keyboard (unless a text field has focus). Shortcuts use the queued key events with
    // their own modifiers; held modifiers during a drag (Ctrl snap) use the live state.
    if (!io.WantCaptureKeyboard) {
        const bool dragging = mode_ == Interaction::DragPoints || mode_ == Interaction::Grab;
        if (!dragging) {
            if (mode_ == Interaction::None) runShortcuts();
            if (keyPressed(GLFW_KEY_G, 0) && !sel_.points.empty() && mode_ == Interaction::None) {
                pressX_ = mx;
                pressY_ = my;
                beginDrag(true);
            }
            if (mode_ == Interaction::None && keyPressed(GLFW_KEY_ESCAPE, 0) && !showPalette_) sel_.clear();
        } else {
            for (int a = 0; a < 3; ++a)
                if (keyPressed(GLFW_KEY_X + a, 0)) {
                    drag_.axis = drag_.axis == a ? -1 : a;
                    updateDrag(mx, my);
                }
            if (keyPressed(GLFW_KEY_ESCAPE, 0)) cancelDrag();
            if (mode_ == Interaction::Grab && (keyPressed(GLFW_KEY_ENTER, 0) || keyPressed(GLFW_KEY_KP_ENTER, 0))) finishDrag();
        }
    }

    // Step 2: hover highlight.
    if (mode_ == Interaction::None && !overUi && mouseValid)
        hovered_ = pickPoint(cam_, doc_.points, mx, my, W, H, kPickRadiusPx, &usedMask_);
    else if (mode_ == Interaction::None)
        hovered_ = -1;

    // Step 3: navigation — wheel zoom, middle orbit / Shift+middle pan, Alt+left orbit.
    if (!overUi && mouseValid && io.MouseWheel != 0.0f) zoomCamera(cam_, io.MouseWheel);
    if (mode_ == Interaction::None && !overUi && mouseValid) {
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) mode_ = io.KeyShift ? Interaction::Pan : Interaction::Orbit;
        else if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && io.KeyAlt) mode_ = Interaction::Orbit;
        if (mode_ != Interaction::None) lastX_ = mx, lastY_ = my;
    }
    if (mode_ == Interaction::Orbit || mode_ == Interaction::Pan) {
        const double dx = mx - lastX_, dy = my - lastY_;
        if (mode_ == Interaction::Orbit)
            orbitCamera(cam_, dx, dy);
        else
            panCamera(cam_, dx, dy, H);
        lastX_ = mx, lastY_ = my;
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Middle) && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) mode_ = Interaction::None;
        return;
    }

    // Step 4: selection and point drags.
    switch (mode_) {
        case Interaction::None:
            if (!overUi && mouseValid && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
                pressX_ = leftPressed_ ? leftPressX_ - viewArea_[0] : mx;
                pressY_ = leftPressed_ ? leftPressY_ - viewArea_[1] : my;
                pressShift_ = io.KeyShift;
                hovered_ = pickPoint(cam_, doc_.points, pressX_, pressY_, W, H, kPickRadiusPx, &usedMask_);
                if (hovered_ >= 0) {
                    const bool was = sel_.contains(uint32_t(hovered_));
                    if (pressShift_ || !was) applyClick(sel_, hovered_, pressShift_);
                    mode_ = sel_.contains(uint32_t(hovered_)) ? Interaction::PendingDrag : Interaction::None;
                    if (!pressShift_ && !was) sel_.patch = -1;
                } else {
                    mode_ = Interaction::BoxSelect;
                }
            }
            break;
        case Interaction::PendingDrag:
            if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
                // A plain click on an already selected point selects just that point.
                if (!pressShift_ && hovered_ >= 0) applyClick(sel_, hovered_, false);
                mode_ = Interaction::None;
            } else if (std::hypot(mx - pressX_, my - pressY_) > kDragThresholdPx) {
                beginDrag(false);
                updateDrag(mx, my);
            }
            break;
        case Interaction::DragPoints:
            if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
                cancelDrag();
            } else if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
                updateDrag(mx, my);
                finishDrag();
            } else if (mx != lastX_ || my != lastY_ || io.KeyCtrl != drag_.grab) {
                updateDrag(mx, my);
            }
            break;
        case Interaction::Grab:
            if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) cancelDrag();
            else if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) finishDrag();
            else updateDrag(mx, my);
            break;
        case Interaction::BoxSelect:
            if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
                mode_ = Interaction::None;
                if (std::hypot(mx - pressX_, my - pressY_) <= kDragThresholdPx) {
                    // A click on empty space: pick a patch by its surface, else clear.
                    const auto hit = pickSurface(doc_, rayThroughPixel(cam_, mx, my, W, H));
                    if (!pressShift_) sel_.points.clear();
                    if (hit && hit->patch >= 0) {
                        sel_.patch = hit->patch;
                        sel_.surface = sel_.triangle = -1;
                        lastEdge_ = nearestEdge(hit->u, hit->v);
                    } else if (hit && hit->surface >= 0) {
                        sel_.surface = hit->surface;
                        sel_.patch = sel_.triangle = -1;
                    } else if (hit && hit->triangle >= 0) {
                        sel_.triangle = hit->triangle;
                        sel_.patch = sel_.surface = -1;
                    } else if (!pressShift_) {
                        sel_.patch = sel_.surface = sel_.triangle = -1;
                    }
                } else {
                    applyBox(sel_, pointsInBox(cam_, doc_.points, {pressX_, pressY_}, {mx, my}, W, H, &usedMask_), pressShift_);
                }
            }
            break;
        default: break;
    }
    lastX_ = mx, lastY_ = my;
}

void Editor::beginDrag(bool grab) {
    if (sel_.points.empty()) return;
    drag_ = DragState{};
    drag_.grab = grab;
    drag_.start = doc_.points;
    drag_.uploaded = doc_.points;
    drag_.moved = sel_.points;
    drag_.solver = std::make_unique<DragSolver>(doc_, drag_.moved);  // factorised once per drag
    drag_.anchor = selectionCentroid(doc_, sel_);
    Vec3 r, u, f;
    cameraAxes(cam_, r, u, f);
    drag_.planeNormal = f;
    drag_.startX = pressX_;
    drag_.startY = pressY_;
    const auto [W, H] = viewSize();
    const Ray ray = rayThroughPixel(cam_, pressX_, pressY_, W, H);
    drag_.startHit = intersectPlane(ray, drag_.anchor, f).value_or(drag_.anchor);
    mode_ = grab ? Interaction::Grab : Interaction::DragPoints;
}

void Editor::updateDrag(double mx, double my) {
    const ImGuiIO& io = ImGui::GetIO();
    const auto [W, H] = viewSize();
    const Ray ray = rayThroughPixel(cam_, mx, my, W, H);
    Vec3 delta(0.0);
    if (drag_.axis < 0) {
        const auto hit = intersectPlane(ray, drag_.anchor, drag_.planeNormal);
        if (!hit) return;
        delta = *hit - drag_.startHit;
    } else {
        const Vec3 a = axisVector(drag_.axis);
        const Ray r0 = rayThroughPixel(cam_, drag_.startX, drag_.startY, W, H);
        delta = closestPointOnAxis(ray, drag_.anchor, a) - closestPointOnAxis(r0, drag_.anchor, a);
    }
    if (io.KeyCtrl) {  // snap the moved centre to the grid
        const Vec3 snapped = snapToGrid(drag_.anchor + delta, niceGridStep(modelSize(doc_)) / 5.0);
        if (drag_.axis < 0)
            delta = snapped - drag_.anchor;
        else
            delta[drag_.axis] = snapped[drag_.axis] - drag_.anchor[drag_.axis];
    }
    const auto t0 = std::chrono::steady_clock::now();
    doc_.points = drag_.start;
    for (uint32_t p : drag_.moved) doc_.points[p] = drag_.start[p] + delta;
    drag_.solver->project(doc_.points);
    // Partial upload: only the points that moved since the last frame.
    takeChangedPoints(drag_.uploaded, doc_.points, drag_.changed);
    renderer_->updatePoints(doc_.points, drag_.changed);
    dragMs_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    wake();
}

void Editor::finishDrag() {
    mode_ = Interaction::None;
    const size_t n = drag_.moved.size();
    drag_ = DragState{};
    if (doc_.points != session_.committed().points) commit(n == 1 ? "Move point" : "Move " + std::to_string(n) + " points");
    documentChanged(false);
}

void Editor::cancelDrag() {
    mode_ = Interaction::None;
    doc_.points = drag_.start;
    drag_ = DragState{};
    documentChanged(false);
}

void Editor::drawViewportOverlays() {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const auto rects = viewPaneRects();
    for (size_t i = 0; i < rects.size(); ++i) {
        const auto& r = rects[i];
        // Not under the side panels: their backgrounds are filled before ImGui draws this list.
        const float x0 = std::max(r[0], leftPanelWidth_), x1 = std::min(r[0] + r[2], ImGui::GetIO().DisplaySize.x - rightPanelWidth_);
        dl->PushClipRect(ImVec2(x0, r[1]), ImVec2(std::max(x0, x1), r[1] + r[3]), true);
        drawPaneOverlays(r, int(i) == activePane_ || !viewSplit());
        dl->PopClipRect();
    }

    // Mode line.
    const char* modeText = nullptr;
    char buf[160];
    if (mode_ == Interaction::Grab || mode_ == Interaction::DragPoints) {
        std::snprintf(buf, sizeof buf, "%s %zu point(s)%s   X/Y/Z axis · Ctrl snap · Esc/right click cancel%s",
                      mode_ == Interaction::Grab ? "Grab" : "Drag", drag_.moved.size(),
                      drag_.axis < 0 ? " in the view plane" : drag_.axis == 0 ? " along X" : drag_.axis == 1 ? " along Y" : " along Z",
                      mode_ == Interaction::Grab ? " · click/Enter confirm" : "");
        modeText = buf;
    }
    if (modeText) dl->AddText(ImVec2(float(leftPanelWidth_) + 12.0f, 30.0f), IM_COL32(255, 230, 120, 255), modeText);
}

void Editor::drawPaneOverlays(const std::array<float, 4>& pane, bool active) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const ImGuiIO& io = ImGui::GetIO();
    const int W = std::max(int(pane[2]), 1), H = std::max(int(pane[3]), 1);
    const ViewMatrices vm = viewMatrices(cam_, double(W) / H);
    auto proj = [&](const Vec3& p) -> std::optional<glm::dvec2> {
        auto s = projectToPixel(vm, p, W, H);
        if (s) *s += glm::dvec2(pane[0], pane[1]);
        return s;
    };
    auto line = [&](const Vec3& a, const Vec3& b, ImU32 col, float th) {
        const auto pa = proj(a), pb = proj(b);
        if (pa && pb) dl->AddLine(ImVec2(float(pa->x), float(pa->y)), ImVec2(float(pb->x), float(pb->y)), col, th);
    };

    // Selected patch: its boundary curves.
    if (sel_.patch >= 0 && sel_.patch < int(doc_.patches.size())) {
        const Patch& pt = doc_.patches[size_t(sel_.patch)];
        const Net16 net = gatherNet(doc_, pt.idx);
        const int n = 24;
        for (int e = 0; e < 4; ++e) {
            const bool hl = e == int(lastEdge_);
            for (int k = 0; k < n; ++k) {
                auto uv = [&](int s, double& u, double& v) {
                    const double t = double(s) / n;
                    switch (e) {
                        case 0: u = 0, v = t; break;
                        case 1: u = t, v = 0; break;
                        case 2: u = 1, v = t; break;
                        default: u = t, v = 1; break;
                    }
                };
                double u0, v0, u1, v1;
                uv(k, u0, v0);
                uv(k + 1, u1, v1);
                line(evaluateNet(net, pt.basis, pt.tension, u0, v0).p, evaluateNet(net, pt.basis, pt.tension, u1, v1).p,
                     hl ? IM_COL32(255, 120, 255, 255) : IM_COL32(80, 220, 255, 255), hl ? 4.0f : 2.5f);
            }
        }
    }

    // Selected Bézier triangle: its three boundary curves.
    if (sel_.triangle >= 0 && sel_.triangle < int(doc_.triangles.size())) {
        const Net10 net = gatherTriangleNet(doc_, doc_.triangles[size_t(sel_.triangle)].idx);
        const int n = 24;
        for (int e = 0; e < 3; ++e)
            for (int k = 0; k < n; ++k) {
                // Edge e runs from one corner to the next (u = 0: v to w, v = 0: w to u, w = 0: u to v).
                auto at = [&](int s) {
                    const double t = double(s) / n;
                    const double u = e == 0 ? 0.0 : e == 1 ? t : 1.0 - t, v = e == 0 ? 1.0 - t : e == 1 ? 0.0 : t;
                    return evaluateTriangle(net, u, v).p;
                };
                line(at(k), at(k + 1), IM_COL32(80, 220, 255, 255), 2.5f);
            }
    }

    // Selected and hovered points.
    for (uint32_t p : sel_.points)
        if (p < doc_.points.size())
            if (auto s = proj(doc_.points[p])) dl->AddCircleFilled(ImVec2(float(s->x), float(s->y)), 5.0f, IM_COL32(255, 140, 30, 255));
    if (hovered_ >= 0 && hovered_ < int(doc_.points.size()))
        if (auto s = proj(doc_.points[size_t(hovered_)]))
            dl->AddCircle(ImVec2(float(s->x), float(s->y)), 8.0f, IM_COL32(255, 255, 255, 255), 16, 2.0f);

    // Axis constraint line during a drag.
    if ((mode_ == Interaction::DragPoints || mode_ == Interaction::Grab) && drag_.axis >= 0) {
        const Vec3 a = axisVector(drag_.axis) * (2.0 * modelSize(doc_));
        const ImU32 col = drag_.axis == 0 ? IM_COL32(230, 60, 60, 220) : drag_.axis == 1 ? IM_COL32(60, 210, 60, 220) : IM_COL32(70, 120, 255, 220);
        line(drag_.anchor - a, drag_.anchor + a, col, 1.5f);
    }

    // Box selection rectangle.
    if (mode_ == Interaction::BoxSelect && active) {
        const ImVec2 a{float(pressX_) + pane[0], float(pressY_) + pane[1]}, b = io.MousePos;
        dl->AddRectFilled(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                          IM_COL32(100, 150, 255, 40));
        dl->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                    IM_COL32(120, 170, 255, 200));
    }

    // Axis gizmo (bottom left of the viewport, right of the left panel).
    {
        const ImVec2 c(pane[0] + (viewSplit() ? 0.0f : float(leftPanelWidth_)) + 60.0f, pane[1] + float(H) - 60.0f);
        const float len = 40.0f;
        struct Ax { glm::vec3 v; ImU32 col; const char* name; };
        Ax axes[3] = {{glm::vec3(vm.view * glm::vec4(1, 0, 0, 0)), IM_COL32(230, 70, 70, 255), "X"},
                      {glm::vec3(vm.view * glm::vec4(0, 1, 0, 0)), IM_COL32(80, 200, 80, 255), "Y"},
                      {glm::vec3(vm.view * glm::vec4(0, 0, 1, 0)), IM_COL32(80, 130, 255, 255), "Z"}};
        std::sort(axes, axes + 3, [](const Ax& a, const Ax& b) { return a.v.z < b.v.z; });
        dl->AddCircleFilled(c, len + 12.0f, IM_COL32(0, 0, 0, 60));
        for (const Ax& a : axes) {
            const ImVec2 e(c.x + a.v.x * len, c.y - a.v.y * len);
            dl->AddLine(c, e, a.col, 2.5f);
            dl->AddText(ImVec2(e.x - 3.0f, e.y - 7.0f), a.col, a.name);
        }
    }

}

}  // namespace pw::ui

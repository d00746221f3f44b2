// Viewport input (Blender conventions, DESIGN §6): hover, navigation (wheel zoom, middle orbit,
// Shift+middle pan, Alt+left orbit), click / Shift+click / box selection, surface picks, and point
// drags (a left drag on a selected point, or G) through core/drag_controller.hpp: X/Y/Z constrain,
// Ctrl snaps, Esc or right click cancels. Mouse positions are relative to the pane the mouse works
// in (ui/view_panes.cpp).
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/camera_math.hpp"
#include "core/patch_ops.hpp"
#include "core/picking.hpp"
#include "render/renderer.hpp"
#include "ui/app_window.hpp"
#include "ui/editor.hpp"

namespace pw::ui {

namespace {

constexpr double kPickRadiusPx = 9.0;
constexpr double kDragThresholdPx = 3.0;

}  // namespace

void Editor::frameBox(const Bounds& box) {
    auto [W, H] = window_.windowSize();
    W = std::max(W, 1), H = std::max(H, 1);
    if (teaching_.viewSplit()) {  // every pane has the same size: fit the box into one
        const auto pane = teaching_.viewPaneRects(sidePanels_.layout()).front();
        cam_ = frameBounds(cam_, box, double(pane[2]) / std::max(double(pane[3]), 1.0));
        return;
    }
    // Fit the box into the part of the window between the side panels, then shift it there.
    const double left = std::min(300.0 * window_.uiScale(), W * 0.3), right = std::min(330.0 * window_.uiScale(), W * 0.3);
    const double visible = std::max(W - left - right, W * 0.25);
    cam_ = frameBounds(cam_, box, visible / H);
    panCamera(cam_, 0.5 * (left - right), 0.0, H);
}

std::array<int, 2> Editor::viewSize() const { return {std::max(int(viewArea_[2]), 1), std::max(int(viewArea_[3]), 1)}; }

DragView Editor::dragView() const {
    const auto [W, H] = viewSize();
    return {cam_, W, H};
}

void Editor::viewportInput() {
    ImGuiIO& io = ImGui::GetIO();
    // Mouse positions are relative to the pane the mouse works in (the whole window unless the
    // view is split): each pane is a view of its own size under the one camera.
    viewArea_ = teaching_.interactionPane(sidePanels_.layout(), io.MousePos.x, io.MousePos.y, mode_ != Interaction::None);
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
            if (mode_ == Interaction::None && keyPressed(GLFW_KEY_ESCAPE, 0) && !palette_.open) sel_.clear();
        } else {
            for (int a = 0; a < 3; ++a)
                if (keyPressed(GLFW_KEY_X + a, 0)) {
                    drag_.toggleAxis(a);
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
                const auto press = window_.leftPress();
                pressX_ = press ? (*press)[0] - viewArea_[0] : mx;
                pressY_ = press ? (*press)[1] - viewArea_[1] : my;
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
            } else if (mx != lastX_ || my != lastY_ || io.KeyCtrl != drag_.grab()) {
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
    if (drag_.begin(doc_, sel_, dragView(), pressX_, pressY_, grab)) mode_ = grab ? Interaction::Grab : Interaction::DragPoints;
}

void Editor::updateDrag(double mx, double my) {
    const auto t0 = std::chrono::steady_clock::now();
    if (!drag_.update(doc_, dragView(), mx, my, ImGui::GetIO().KeyCtrl)) return;
    renderer_->updatePoints(doc_.points, drag_.changed());  // partial upload: what moved since the last frame
    dragMs_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    wake();
}

void Editor::finishDrag() {
    mode_ = Interaction::None;
    drag_.finish(session_);
    documentChanged(false);
}

void Editor::cancelDrag() {
    mode_ = Interaction::None;
    drag_.cancel(doc_);
    documentChanged(false);
}

}  // namespace pw::ui

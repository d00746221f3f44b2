// Viewport input (Blender conventions, DESIGN §6): hover, navigation (wheel zoom, middle orbit,
// Shift+middle pan, Alt+left orbit), click / Shift+click / box selection, surface picks, and point
// transforms (a left drag on a selected point or a gizmo handle; G / R / S) through
// core/edit/drag_controller.hpp: X/Y/Z constrain to an axis, Shift+X/Y/Z to a plane, U/V/N slide, digits type a value,
// Ctrl snaps, Esc or right click cancels. Mouse positions are relative to the pane the mouse works
// in (ui/editor/view_panes.cpp). Shift+right click places the 3D cursor.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/eval/occlusion.hpp"
#include "core/model/camera_math.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/select/picking.hpp"
#include "core/select/snapping.hpp"
#include "core/trim/trim_edits.hpp"
#include "render/scene/renderer.hpp"
#include "ui/editor/editor.hpp"
#include "ui/platform/app_window.hpp"

namespace pw::ui {
inline namespace editor {

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
            if (mode_ == Interaction::None && grabAfterShortcut_ && mouseValid) {
                pressX_ = mx;
                pressY_ = my;
                beginDrag(true, TransformKind::Move);
            }
            grabAfterShortcut_ = false;
            if (mode_ == Interaction::None && join_.state().on) joinToolInput(mx, my, overUi);
            if (mode_ == Interaction::None && curve_.on) curveToolInput(mx, my, overUi);
            if (mode_ == Interaction::None && !session_.selectedPoints().empty()) {
                const int keys[3] = {GLFW_KEY_G, GLFW_KEY_R, GLFW_KEY_S};
                const TransformKind kinds[3] = {TransformKind::Move, TransformKind::Rotate, TransformKind::Scale};
                for (int k = 0; k < 3 && mode_ == Interaction::None; ++k)
                    if (keyPressed(keys[k], 0)) {
                        pressX_ = mx;
                        pressY_ = my;
                        beginDrag(true, kinds[k]);
                    }
            }
            if (mode_ == Interaction::None && !join_.state().on && !curve_.on && keyPressed(GLFW_KEY_ESCAPE, 0) && !palette_.open)
                sel_.clear();
        } else {
            transformKeys(mx, my);
        }
    }

    // Step 2: hover highlight.
    if (mode_ == Interaction::None && !overUi && mouseValid) {
        // The gizmo's arrows come before points; a point under its centre ring comes first.
        hoveredGizmo_ = gizmoHit(mx, my);
        hovered_ = hoveredGizmo_ >= 0 && hoveredGizmo_ < 3 ? -1 : pickPoint(cam_, doc_.points, mx, my, W, H, kPickRadiusPx, &usedMask_);
        if (hovered_ >= 0) hoveredGizmo_ = -1;
    } else if (mode_ == Interaction::None) {
        hovered_ = hoveredGizmo_ = -1;
    }

    // Step 3: navigation — wheel zoom, middle orbit / Shift+middle pan, Alt+left orbit.
    // While a transform runs with soft selection, the wheel sets its radius (Blender's); else it zooms.
    const bool transforming = mode_ == Interaction::Grab || mode_ == Interaction::DragPoints;
    if (!overUi && mouseValid && io.MouseWheel != 0.0f && transforming && drag_.soft().on) {
        drag_.setSoftRadius(doc_, drag_.soft().radius * std::pow(1.15, -double(io.MouseWheel)));
        session_.soft.radius = drag_.soft().radius;  // the next transform starts with it
        updateDrag(mx, my);
    } else if (!overUi && mouseValid && io.MouseWheel != 0.0f) {
        zoomCamera(cam_, io.MouseWheel);
    }
    if (mode_ == Interaction::None && !overUi && mouseValid) {
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle))
            mode_ = io.KeyShift ? Interaction::Pan : Interaction::Orbit;
        else if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && io.KeyAlt)
            mode_ = Interaction::Orbit;
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
            if (!overUi && mouseValid && io.KeyShift && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
                placeCursor(mx, my);
                break;
            }
            if (!overUi && mouseValid && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && (join_.state().on || curve_.on) && !io.KeyAlt)
                break;  // the join or curve tool's
            if (!overUi && mouseValid && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
                const auto press = window_.leftPress();
                pressX_ = press ? (*press)[0] - viewArea_[0] : mx;
                pressY_ = press ? (*press)[1] - viewArea_[1] : my;
                pressShift_ = io.KeyShift;
                const int g = pressShift_ ? -1 : gizmoHit(pressX_, pressY_);
                hovered_ = g >= 0 && g < 3 ? -1 : pickPoint(cam_, doc_.points, pressX_, pressY_, W, H, kPickRadiusPx, &usedMask_);
                if (g >= 0 && hovered_ < 0) {  // a gizmo handle: its arrow's axis, or the centre's view plane
                    beginDrag(false, TransformKind::Move, g < 3 ? g : -1);
                    break;
                }
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
            if (ImGui::IsMouseClicked(ImGuiMouseButton_Right))
                cancelDrag();
            else if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
                finishDrag();
            else
                updateDrag(mx, my);
            break;
        case Interaction::BoxSelect:
            if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
                mode_ = Interaction::None;
                if (std::hypot(mx - pressX_, my - pressY_) <= kDragThresholdPx) {
                    // A click on empty space: pick a patch by its surface, else clear.
                    const auto hit = pickSurface(doc_, rayThroughPixel(cam_, mx, my, W, H));
                    if (!pressShift_) sel_.points.clear();
                    if (hit && hit->patch >= 0 && teaching_.math.on) {  // Teaching's Bézier math: this patch at this (u, v)
                        teaching_.math.patch = hit->patch;
                        teaching_.math.u = float(hit->u);
                        teaching_.math.v = float(hit->v);
                    }
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
                    // Only the points you can see, unless X-ray (Alt+Z) selects through.
                    std::vector<uint32_t> boxed = pointsInBox(cam_, doc_.points, {pressX_, pressY_}, {mx, my}, W, H, &usedMask_);
                    if (!xray_) boxed = unoccludedPoints(doc_, cam_, W, H, boxed);
                    applyBox(sel_, boxed, pressShift_);
                }
            }
            break;
        default:
            break;
    }
    lastX_ = mx, lastY_ = my;
}

void Editor::beginDrag(bool grab, TransformKind kind, int axis) {
    // An on-curve point carries its tangent handles (core/model/document.hpp: withCurveHandles).
    TransformStart start{withCurveHandles(doc_, session_.selectedPoints()),
                         session_.transformPivot(),
                         kind,
                         grab,
                         session_.snap,
                         session_.symmetry,
                         session_.soft};
    // A move started on a point carries that point (it is what snaps); G moves the pivot.
    if (kind == TransformKind::Move && !grab && hovered_ >= 0 && size_t(hovered_) < doc_.points.size())
        start.pivot = doc_.points[size_t(hovered_)];
    if (!drag_.begin(doc_, start, dragView(), pressX_, pressY_)) {
        if (!drag_.refusal().empty()) status(drag_.refusal());
        return;
    }
    mode_ = grab ? Interaction::Grab : Interaction::DragPoints;
    if (axis >= 0) drag_.setAxis(axis);
}

void Editor::placeCursor(double mx, double my) {
    // Shift+right click (Blender): on the control point under the mouse, else where the mouse ray
    // meets a surface, else in the plane through the cursor facing the view. It runs the `cursor`
    // command, so the status line and scripts agree.
    const auto [W, H] = viewSize();
    const std::vector<bool> none;
    std::optional<Vec3> at = snapPoint(doc_, none, SnapTarget::Points, cam_, W, H, mx, my, kPickRadiusPx);
    const bool onPoint = at.has_value();
    if (!at) at = snapPoint(doc_, none, SnapTarget::Surfaces, cam_, W, H, mx, my);
    if (!at) {
        Vec3 r, u, f;
        cameraAxes(cam_, r, u, f);
        at = intersectPlane(rayThroughPixel(cam_, mx, my, W, H), session_.cursor, f);
    }
    if (!at) return;
    // Ctrl (Blender): on the grid of a move's Ctrl snap, unless it landed on a point.
    if (ImGui::GetIO().KeyCtrl && !onPoint) at = snapToGrid(*at, niceGridStep(modelSize(doc_)) / 5.0);
    char x[32], y[32], z[32];
    std::snprintf(x, sizeof x, "%.17g", at->x), std::snprintf(y, sizeof y, "%.17g", at->y), std::snprintf(z, sizeof z, "%.17g", at->z);
    runCommand({"cursor", x, y, z});
}

void Editor::transformKeys(double mx, double my) {
    bool changed = false;
    for (int a = 0; a < 3; ++a) {
        if (keyPressed(GLFW_KEY_X + a, 0)) drag_.toggleAxis(a), changed = true;
        if (keyPressed(GLFW_KEY_X + a, GLFW_MOD_SHIFT)) drag_.toggleAxis(a, true), changed = true;
    }
    // U / V / N while moving: slide along each point's own control polygon or the normal.
    static const std::pair<int, SlideAxis> kSlideKeys[3] = {
        {GLFW_KEY_U, SlideAxis::U}, {GLFW_KEY_V, SlideAxis::V}, {GLFW_KEY_N, SlideAxis::N}};
    for (const auto& [key, axis] : kSlideKeys)
        if (drag_.kind() == TransformKind::Move && keyPressed(key, 0)) {
            if (drag_.toggleSlide(doc_, axis))
                changed = true;
            else
                status(drag_.refusal());
        }
    if (mode_ == Interaction::Grab)  // typed values: "G X 2 Enter", the keys in the order they came
        for (const auto& [key, mods] : window_.queuedKeys()) {
            if (mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER)) continue;
            char c = 0;
            if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9 && !(mods & GLFW_MOD_SHIFT))
                c = char('0' + key - GLFW_KEY_0);
            else if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9)
                c = char('0' + key - GLFW_KEY_KP_0);
            else if (key == GLFW_KEY_PERIOD || key == GLFW_KEY_KP_DECIMAL)
                c = '.';
            else if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT)
                c = '-';
            if (c)
                drag_.typeChar(c), changed = true;
            else if (key == GLFW_KEY_BACKSPACE)
                drag_.backspace(), changed = true;
        }
    if (changed) updateDrag(mx, my);
    if (keyPressed(GLFW_KEY_ESCAPE, 0))
        cancelDrag();
    else if (mode_ == Interaction::Grab && (keyPressed(GLFW_KEY_ENTER, 0) || keyPressed(GLFW_KEY_KP_ENTER, 0)))
        finishDrag();
}

void Editor::updateDrag(double mx, double my) {
    const auto t0 = std::chrono::steady_clock::now();
    if (!drag_.update(doc_, dragView(), mx, my, ImGui::GetIO().KeyCtrl)) return;
    if (hasLiveTrims(doc_))
        documentChanged(false);  // intersections and trims followed the move: their loops go up with the scene
    else
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

}  // namespace editor
}  // namespace pw::ui

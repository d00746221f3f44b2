// Point drags and held point edits: the projection of the mouse onto the drag plane or axis, and
// the solver that keeps the joins (core/drag_controller.hpp).
#include "core/drag_controller.hpp"

#include <cmath>
#include <cstdio>

#include "core/limits.hpp"
#include "core/picking.hpp"
#include "core/point_upload.hpp"

namespace pw {

namespace {

Vec3 axisVector(int axis) {
    Vec3 a(0.0);
    a[axis] = 1.0;
    return a;
}

}  // namespace

bool DragController::begin(const Document& doc, const Selection& sel, const DragView& view, double x, double y, bool grab) {
    *this = DragController{};
    if (sel.points.empty()) return false;
    grab_ = grab;
    start_ = doc.points;
    uploaded_ = doc.points;
    moved_ = sel.points;
    solver_ = std::make_unique<DragSolver>(doc, moved_);  // factorised once per drag
    anchor_ = selectionCentroid(doc, sel);
    Vec3 r, u, f;
    cameraAxes(view.camera, r, u, f);
    planeNormal_ = f;
    startX_ = x;
    startY_ = y;
    const Ray ray = rayThroughPixel(view.camera, x, y, view.width, view.height);
    startHit_ = intersectPlane(ray, anchor_, f).value_or(anchor_);
    return true;
}

bool DragController::update(Document& doc, const DragView& view, double x, double y, bool snap) {
    if (!active()) return false;
    const Ray ray = rayThroughPixel(view.camera, x, y, view.width, view.height);
    Vec3 delta(0.0);
    if (axis_ < 0) {
        const auto hit = intersectPlane(ray, anchor_, planeNormal_);
        if (!hit) return false;
        delta = *hit - startHit_;
    } else {
        const Vec3 a = axisVector(axis_);
        const Ray r0 = rayThroughPixel(view.camera, startX_, startY_, view.width, view.height);
        delta = closestPointOnAxis(ray, anchor_, a) - closestPointOnAxis(r0, anchor_, a);
    }
    if (snap) {  // the moved centre on the grid
        const Vec3 snapped = snapToGrid(anchor_ + delta, niceGridStep(modelSize(doc)) / 5.0);
        if (axis_ < 0)
            delta = snapped - anchor_;
        else
            delta[axis_] = snapped[axis_] - anchor_[axis_];
    }
    doc.points = start_;
    for (uint32_t p : moved_) doc.points[p] = start_[p] + delta;
    solver_->project(doc.points);
    takeChangedPoints(uploaded_, doc.points, changed_);
    return true;
}

void DragController::finish(EditSession& session) {
    const size_t n = moved_.size();
    *this = DragController{};
    if (session.doc.points != session.committed().points) session.commit(n == 1 ? "Move point" : "Move " + std::to_string(n) + " points");
}

void DragController::cancel(Document& doc) {
    if (!start_.empty()) doc.points = start_;
    *this = DragController{};
}

std::string HeldPointEdit::set(EditSession& session, uint32_t point, const Vec3& position) {
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(position[k]) || std::abs(position[k]) > limits::kMaxCoordinate) {
            char msg[160];
            std::snprintf(msg, sizeof msg, "A point coordinate must be a finite number within ±%g; %g was not applied.",
                          limits::kMaxCoordinate, position[k]);
            return msg;
        }
    if (!solver_ || point_ != point || generation_ != session.generation()) {
        solver_ = std::make_unique<DragSolver>(session.committed(), std::vector<uint32_t>{point});
        point_ = point;
        generation_ = session.generation();
    }
    std::vector<Vec3> pts = session.committed().points;
    pts[point] = position;
    solver_->project(pts);
    session.doc.points = std::move(pts);
    return "";
}

}  // namespace pw

// Moving control points with the joins held, without a window: the editor's point drags (in the
// view plane, or along an axis after X/Y/Z; Ctrl snaps) and its numeric point edits. Mouse
// positions are pixels of a view (camera + size); the solver (core/constraint_solver.hpp) is
// factorised once per drag and moves the neighbours so that every join holds; a finished drag is
// one undo step of the session. The editor (ui/viewport.cpp) feeds it the mouse; tests drive it
// directly (tests/test_drag_controller.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/constraint_solver.hpp"
#include "core/document.hpp"
#include "core/edit_session.hpp"
#include "core/selection.hpp"

namespace pw {

// The view a drag is seen in: mouse positions are pixels of a width x height image of `camera`.
struct DragView {
    Camera camera;
    int width = 1, height = 1;
};

class DragController {
public:
    // Starts moving the selection's points (sel.points) from the mouse at (x, y): they move in the
    // plane through their centroid facing the camera. `grab`: started by the G key (no button
    // held). Returns false, starting nothing, when no point is selected.
    bool begin(const Document& doc, const Selection& sel, const DragView& view, double x, double y, bool grab);
    bool active() const { return solver_ != nullptr; }
    bool grab() const { return grab_; }

    // -1: free (the view plane); 0, 1, 2: along X, Y, Z through the centroid.
    int axis() const { return axis_; }
    void setAxis(int axis) { axis_ = axis < 0 || axis > 2 ? -1 : axis; }
    void toggleAxis(int axis) { setAxis(axis_ == axis ? -1 : axis); }

    // Moves the points to follow the mouse at (x, y): the moved points by the mouse's offset on
    // the plane (or axis) from where the drag started, every other point by the solver. `snap`:
    // the centroid lands on a grid of a fifth of niceGridStep(modelSize). Returns false and leaves
    // `doc` alone when the mouse ray misses the drag plane.
    bool update(Document& doc, const DragView& view, double x, double y, bool snap);
    // The pool entries update() changed since the one before (a partial GPU upload).
    const std::vector<uint32_t>& changed() const { return changed_; }

    // Ends the drag: one undo step ("Move point", "Move N points") when any point moved.
    void finish(EditSession& session);
    // Ends the drag with every point where it was at begin().
    void cancel(Document& doc);

    const Vec3& anchor() const { return anchor_; }  // the moved points' centroid at begin()
    size_t movedCount() const { return moved_.size(); }

private:
    std::vector<Vec3> start_;      // the whole pool at begin()
    std::vector<uint32_t> moved_;  // the points the user moves (fixed in the solver)
    std::unique_ptr<DragSolver> solver_;
    Vec3 anchor_{0.0};
    Vec3 planeNormal_{0.0, 0.0, 1.0};
    Vec3 startHit_{0.0};           // where the start ray met the drag plane
    double startX_ = 0, startY_ = 0;
    int axis_ = -1;
    bool grab_ = false;
    std::vector<Vec3> uploaded_;   // the pool as of the last changed() list
    std::vector<uint32_t> changed_;
};

// Numeric edits of one point (the inspector's fields) with the joins held: the point goes where it
// is typed, its neighbours as the solver moves them from the committed document. The
// factorisation is kept while the same point is edited against the same committed state.
class HeldPointEdit {
public:
    // Writes session.doc.points; commit() is the caller's. Returns "" or, for a coordinate that is
    // not finite or beyond limits::kMaxCoordinate, the message (and changes nothing).
    std::string set(EditSession& session, uint32_t point, const Vec3& position);
    void reset() { solver_.reset(); }  // another document

private:
    std::unique_ptr<DragSolver> solver_;
    uint32_t point_ = 0;
    uint64_t generation_ = 0;
};

}  // namespace pw

// Transforms of the selection with the joins held, without a window: the editor's G / R / S and
// point drags (in the view plane, along X/Y/Z, or in the plane normal to one after Shift+X/Y/Z;
// typed values; Ctrl snaps to the grid, to points, edges or surfaces) and its numeric point edits.
// Mouse positions are pixels of a view (camera + size); the solver (core/solve/constraint_solver.hpp) is
// factorised once per transform and moves the neighbours so that every join holds (a whole joined
// group moved rigidly needs no correction); a finished transform is one undo step of the session.
// The editor (ui/editor/viewport.cpp) feeds it the mouse and keys; tests drive it directly
// (tests/test_drag_controller.cpp, tests/test_transforms.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/edit/edit_session.hpp"
#include "core/model/document.hpp"
#include "core/select/selection.hpp"
#include "core/select/slide.hpp"
#include "core/select/snapping.hpp"
#include "core/select/soft_selection.hpp"
#include "core/select/symmetry.hpp"
#include "core/solve/constraint_solver.hpp"

namespace pw {
inline namespace edit {

// The view a drag is seen in: mouse positions are pixels of a width x height image of `camera`.
struct DragView {
    Camera camera;
    int width = 1, height = 1;
};

enum class TransformKind { Move, Rotate, Scale };

struct TransformStart {
    std::vector<uint32_t> points;  // the points the transform moves (fixed in the solver)
    Vec3 pivot{0.0};               // rotate / scale about this point; moves keep it as the anchor
    TransformKind kind = TransformKind::Move;
    bool grab = false;                   // started by a key (G/R/S, no button held): click or Enter confirms
    SnapTarget snap = SnapTarget::Grid;  // what Ctrl snaps a move to
    Symmetry symmetry;                   // on: each point's mirror partner follows (core/select/symmetry.hpp)
    SoftSelection soft;                  // on: the points around follow partly (core/select/soft_selection.hpp)
};

// What a transform of `moved` drives, for drags and the transform commands alike: the soft points
// around it and their shares, the mirror pairs of both under symmetry, the points the solver holds
// (the moved ones and their own partners, sorted) and the solver, factorised once, whose local
// region the soft points seed.
struct TransformSetup {
    SoftWeights soft;
    SymmetryPairs pairs;
    std::vector<uint32_t> driven;
    std::unique_ptr<DragSolver> solver;
};
TransformSetup setUpTransform(const Document& doc, const std::vector<uint32_t>& moved, const SoftSelection& soft, const Symmetry& sym);

class DragController {
public:
    // Starts the transform with the mouse at (x, y). Returns false, starting nothing, when no point
    // is given or a point is made by a live construction (refusal() says so).
    bool begin(const Document& doc, const TransformStart& start, const DragView& view, double x, double y);
    // A move of sel.points about their centroid (a left drag on a selected point).
    bool begin(const Document& doc, const Selection& sel, const DragView& view, double x, double y, bool grab);
    bool active() const { return solver_ != nullptr; }
    const std::string& refusal() const { return refusal_; }  // why the last begin() started nothing
    bool grab() const { return grab_; }
    TransformKind kind() const { return kind_; }

    // The constraint: axis() -1 is free (the view plane for moves, the view axis for rotations,
    // uniform for scales); 0, 1, 2 is X, Y, Z. plane(): Shift+key, the plane normal to that axis
    // (moves and scales in the other two).
    int axis() const { return axis_; }
    bool plane() const { return plane_; }
    void setAxis(int axis, bool plane = false);     // also ends a slide
    void toggleAxis(int axis, bool plane = false);  // the same key again frees the transform

    // Slide (U / V / N while moving; Rhino's UVN move, the `slide` command as a drag): each moved
    // point, and each soft point by its share, moves along its own control polygon in u or v or
    // along the surface normal, by one distance: the mouse along the points' mean direction, or
    // the typed value. Directions come from the shape at begin(). False, leaving the move as it
    // was, when a moved point has no polygon to slide along (refusal() says which); the same key
    // again ends the slide.
    bool toggleSlide(const Document& doc, SlideAxis axis);
    std::optional<SlideAxis> slide() const { return slide_; }

    // Typed value (Blender's "G X 2 Enter"): digits, '.', '-' and Backspace edit it; while it reads
    // as a number it replaces the mouse: a distance along the axis (X when free, the plane's first
    // axis), degrees, or a factor.
    const std::string& typed() const { return typed_; }
    void typeChar(char c);
    void backspace();

    SnapTarget snapTarget() const { return snapTarget_; }

    // Moves the points for the mouse at (x, y): the moved points by the transform, every other
    // point by the solver. `snap` (Ctrl): moves land on the snap target (the grid of a fifth of
    // niceGridStep(modelSize), a point, an edge or a surface of the unmoved items), rotations on
    // 5° steps, scales on 0.1 steps. Returns false and leaves `doc` alone when the mouse ray misses
    // the drag plane.
    bool update(Document& doc, const DragView& view, double x, double y, bool snap);
    // The pool entries update() changed since the one before (a partial GPU upload).
    const std::vector<uint32_t>& changed() const { return changed_; }

    // Ends the transform: one undo step ("Move point", "Rotate 16 points", ...) when any point moved.
    void finish(EditSession& session);
    // Ends the transform with every point where it was at begin().
    void cancel(Document& doc);

    const Vec3& anchor() const { return anchor_; }  // the pivot (moves: the moved points' centroid)
    size_t movedCount() const { return moved_.size(); }
    // Soft selection: the radius changed during the transform (the wheel), the shares measured
    // again; the points the last update moved, the moved points, soft points and solver together.
    void setSoftRadius(const Document& doc, double radius);
    const SoftSelection& soft() const { return soft_; }
    size_t softCount() const { return softPoints_.points.size(); }
    size_t lastMovedCount() const { return lastMoved_; }
    // One line for the editor's mode line: "Move 16 points along X: 2.5 (typed)".
    std::string status() const;
    // What the solver reached on the last update: conflicting joins are named in status() too.
    const Projection& projection() const { return projection_; }
    // The last applied offset, angle (degrees) and factors.
    const Vec3& lastOffset() const { return lastOffset_; }
    double lastAngle() const { return lastAngle_; }
    const Vec3& lastScale() const { return lastScale_; }

private:
    std::vector<Vec3> start_;  // the whole pool at begin()
    std::vector<uint32_t> moved_;
    std::vector<bool> movedMask_;  // what the transform drives: the moved points and their mirror partners
    Symmetry symmetry_;
    SymmetryPairs pairs_;
    void setUp(const Document& doc);  // soft points, pairs, moved mask and solver from setUpTransform
    SoftSelection soft_;
    SoftWeights softPoints_;
    size_t lastMoved_ = 0;
    std::unique_ptr<DragSolver> solver_;
    Projection projection_;
    // The fill's fitted seams (core/ops/fitted_sides) the last update took past 0.1°: named in
    // status(), and finish() then puts every point back instead of committing.
    std::string fittedOut_;
    std::vector<size_t> fittedJoins_;  // the document's fitted joins, found at the start
    double fittedWorstAtStart_ = 0.0;  // their worst angle then
    std::string fittedSeamsPast(const Document& doc) const;
    TransformKind kind_ = TransformKind::Move;
    Vec3 anchor_{0.0};
    Vec3 planeNormal_{0.0, 0.0, 1.0};
    Vec3 startHit_{0.0};  // where the start ray met the drag plane
    double startX_ = 0, startY_ = 0;
    int axis_ = -1;
    bool plane_ = false;
    std::optional<SlideAxis> slide_;
    std::vector<Vec3> slideDirs_;    // per pool point: its slide direction (0 where it has none)
    Vec3 slideMean_{1.0, 0.0, 0.0};  // the moved points' mean direction, which the mouse follows
    double lastSlide_ = 0.0;
    bool grab_ = false;
    std::string typed_;
    std::string refusal_;
    SnapTarget snapTarget_ = SnapTarget::Grid;
    Vec3 lastOffset_{0.0}, lastScale_{1.0};
    double lastAngle_ = 0.0;
    double prevMouseAngle_ = 0.0, accumAngle_ = 0.0;  // rotations: the mouse's turn about the pivot
    std::vector<Vec3> uploaded_;                      // the pool as of the last changed() list
    std::vector<uint32_t> changed_;
    std::optional<double> typedValue() const;
    std::optional<Vec3> moveOffset(const Document& doc, const DragView& view, double x, double y, bool snap) const;
};

// Numeric edits of one point (the inspector's fields) with the joins held: the point goes where it
// is typed, its neighbours as the solver moves them from the committed document. The
// factorisation is kept while the same point is edited against the same committed state.
class HeldPointEdit {
public:
    // Writes session.doc.points (the point's mirror partner too under the session's symmetry);
    // finish() commits it when the drag ends. Returns "" or, for a coordinate that is
    // not finite or beyond limits::kMaxCoordinate, the message (and changes nothing).
    std::string set(EditSession& session, uint32_t point, const Vec3& position);
    // The drag let go: what set() did is one undo step ("Edit point"), or, when the joins could
    // not follow the last position, nothing: the document goes back to its committed state.
    void finish(EditSession& session);
    void reset() { solver_.reset(); }                             // another document
    const Projection& projection() const { return projection_; }  // of the last set()

private:
    std::unique_ptr<DragSolver> solver_;
    Projection projection_;
    uint32_t point_ = 0;
    uint64_t generation_ = 0;
    Symmetry symmetry_;
    SymmetryPairs pairs_;
};

}  // namespace edit
}  // namespace pw

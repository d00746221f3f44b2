// Transforms of whole selections (core/edit/drag_controller.hpp, core/select/selection.hpp, core/select/snapping.hpp):
// G / R / S by mouse and by typed value, axis and plane constraints, the three pivots, snapping to
// points, edges and surfaces, joins held (rigid moves of a joined group exact), view-direction
// axis drags bounded, and the same transforms as script commands.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/model_builders.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/model/camera_math.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/select/picking.hpp"
#include "core/solve/constraint_solver.hpp"

#include "support.hpp"

using namespace pw;

namespace {

constexpr int kW = 800, kH = 600;

DragView viewOf(double yaw, double pitch, const Vec3& target, double distance = 8.0) {
    DragView v;
    v.camera.target = {target.x, target.y, target.z};
    v.camera.distance = distance;
    v.camera.yawDeg = yaw;
    v.camera.pitchDeg = pitch;
    v.width = kW;
    v.height = kH;
    return v;
}

glm::dvec2 pixel(const DragView& v, const Vec3& p) {
    return *projectToPixel(viewMatrices(v.camera, double(v.width) / v.height), p, v.width, v.height);
}

// A C1-joined 2x2 grid with patch 0 selected as a whole (its points come through selectedPoints()).
struct Grid {
    EditSession s;
    DragView view = viewOf(0.0, 89.0, Vec3(1.0, 1.0, 0.0));  // from above
    Grid() {
        s.reset(makePatchGrid(2, 2, Continuity::C1), "");
        s.sel.patch = 0;
    }
    TransformStart start(TransformKind kind, bool grab = true) const {
        return TransformStart{s.selectedPoints(), s.transformPivot(), kind, grab};
    }
};

Vec3 rotatedAbout(const Vec3& p, const Vec3& c, const Vec3& axis, double deg) {
    return c + Vec3(glm::rotate(glm::dmat4(1.0), glm::radians(deg), axis) * glm::dvec4(p - c, 0.0));
}

void run(EditSession& s, const std::string& script) { test::runEditScript(s, script); }

}  // namespace

TEST(Transforms, SelectedPatchMovesAsAWholeAndTheJoinsHold) {
    Grid g;
    const std::vector<uint32_t> moved = g.s.selectedPoints();
    ASSERT_EQ(moved.size(), 16u);
    const std::vector<Vec3> before = g.s.doc.points;
    DragController d;
    const glm::dvec2 c = pixel(g.view, g.s.transformPivot());
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Move), g.view, c.x, c.y));
    d.setAxis(2, true);  // Shift+Z: in the XY plane
    ASSERT_TRUE(d.update(g.s.doc, g.view, c.x + 40.0, c.y + 25.0, false));
    const Vec3 off = g.s.doc.points[moved[0]] - before[moved[0]];
    EXPECT_EQ(off.z, 0.0);
    EXPECT_GT(glm::length(off), 0.1);
    for (uint32_t p : moved) EXPECT_NEAR(glm::length(g.s.doc.points[p] - before[p] - off), 0.0, 1e-12);
    EXPECT_LT(maxConstraintResidual(g.s.doc), 1e-9);
    // The pivot follows the mouse on the plane (exact up to the float projection).
    const glm::dvec2 now = pixel(g.view, g.s.transformPivot());
    EXPECT_NEAR(now.x, c.x + 40.0, 1e-3);
    EXPECT_NEAR(now.y, c.y + 25.0, 1e-3);
    d.finish(g.s);
    EXPECT_EQ(g.s.history().undoLabel(), "Move 16 points");
}

TEST(Transforms, TypedValuesReplaceTheMouse) {
    Grid g;
    const std::vector<uint32_t> moved = g.s.selectedPoints();
    const std::vector<Vec3> before = g.s.doc.points;
    DragController d;
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Move), g.view, 400, 300));
    d.toggleAxis(0);  // G X 2 Enter
    d.typeChar('2');
    ASSERT_TRUE(d.update(g.s.doc, g.view, 555, 123, false));
    for (uint32_t p : moved) EXPECT_EQ(g.s.doc.points[p], before[p] + Vec3(2.0, 0.0, 0.0));
    // Backspace back to the mouse; "-0.5" along Y.
    d.backspace();
    EXPECT_EQ(d.typed(), "");
    d.toggleAxis(1);
    for (char ch : std::string("-0.5")) d.typeChar(ch);
    EXPECT_EQ(d.typed(), "-0.5");
    ASSERT_TRUE(d.update(g.s.doc, g.view, 10, 10, false));
    for (uint32_t p : moved) EXPECT_EQ(g.s.doc.points[p], before[p] + Vec3(0.0, -0.5, 0.0));
    d.typeChar('x');  // not part of a number: ignored
    EXPECT_EQ(d.typed(), "-0.5");
    EXPECT_LT(maxConstraintResidual(g.s.doc), 1e-9);
    d.cancel(g.s.doc);
    EXPECT_EQ(g.s.doc.points, before);

    // R Z 90 about the 3D cursor.
    g.s.pivot = PivotMode::Cursor;
    g.s.cursor = Vec3(-1.0, 0.5, 0.0);
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Rotate), g.view, 400, 300));
    d.setAxis(2);
    d.typeChar('9'), d.typeChar('0');
    ASSERT_TRUE(d.update(g.s.doc, g.view, 401, 300, false));
    for (uint32_t p : moved)
        EXPECT_NEAR(glm::length(g.s.doc.points[p] - rotatedAbout(before[p], g.s.cursor, Vec3(0, 0, 1), 90.0)), 0.0, 1e-12);
    EXPECT_NEAR(d.lastAngle(), 90.0, 0.0);
    d.finish(g.s);
    EXPECT_EQ(g.s.history().undoLabel(), "Rotate 16 points");
    EXPECT_LT(maxConstraintResidual(g.s.doc), 1e-9);

    // S 0.5 along X (median pivot).
    g.s.pivot = PivotMode::Median;
    const std::vector<Vec3> rotated = g.s.doc.points;
    const Vec3 c = g.s.transformPivot();
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Scale), g.view, 400, 300));
    d.setAxis(0);
    d.typeChar('.'), d.typeChar('5');
    ASSERT_TRUE(d.update(g.s.doc, g.view, 420, 300, false));
    for (uint32_t p : moved) {
        EXPECT_NEAR(g.s.doc.points[p].x, c.x + 0.5 * (rotated[p].x - c.x), 1e-12);
        EXPECT_EQ(g.s.doc.points[p].y, rotated[p].y);
    }
    EXPECT_LT(maxConstraintResidual(g.s.doc), 1e-9);
}

TEST(Transforms, RotationFollowsTheMouseAroundThePivot) {
    Grid g;
    g.s.sel.patch = -1;
    g.s.sel.points = g.s.selectedPoints();
    for (const Patch& p : g.s.doc.patches) g.s.sel.points.insert(g.s.sel.points.end(), p.idx.begin(), p.idx.end());
    std::sort(g.s.sel.points.begin(), g.s.sel.points.end());
    g.s.sel.points.erase(std::unique(g.s.sel.points.begin(), g.s.sel.points.end()), g.s.sel.points.end());
    const std::vector<uint32_t> moved = g.s.selectedPoints();  // the whole joined grid
    const std::vector<Vec3> before = g.s.doc.points;
    const Vec3 c = g.s.transformPivot();
    const glm::dvec2 cp = pixel(g.view, c);
    DragController d;
    // The mouse starts right of the pivot and turns a quarter counter-clockwise on screen (up).
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Rotate), g.view, cp.x + 100.0, cp.y));
    // Through the top half in small steps (the angle accumulates), ending above the pivot.
    for (int k = 1; k <= 9; ++k) {
        const double a = glm::radians(10.0 * k);
        ASSERT_TRUE(d.update(g.s.doc, g.view, cp.x + 100.0 * std::cos(a), cp.y - 100.0 * std::sin(a), false));
    }
    // Seen from above (camera looking down -Z, the view axis is +Z towards the viewer): a quarter
    // turn counter-clockwise on screen is +90° about +Z.
    EXPECT_NEAR(d.lastAngle(), 90.0, 0.2);
    // A rigid rotation of the whole joined group: exactly the rotation, the joins untouched.
    const double deg = d.lastAngle();
    Vec3 right, up, fwd;
    cameraAxes(g.view.camera, right, up, fwd);
    for (uint32_t p : moved) EXPECT_NEAR(glm::length(g.s.doc.points[p] - rotatedAbout(before[p], c, -fwd, deg)), 0.0, 1e-12);
    EXPECT_LT(maxConstraintResidual(g.s.doc), 1e-12);
    // Snapped: 5° steps.
    ASSERT_TRUE(d.update(g.s.doc, g.view, cp.x + 100.0 * std::cos(0.75), cp.y - 100.0 * std::sin(0.75), true));
    EXPECT_DOUBLE_EQ(d.lastAngle(), 45.0);
}

TEST(Transforms, PartialRotationAndScaleGoThroughTheSolver) {
    Grid g;  // patch 0 only: its neighbours follow
    const std::vector<Vec3> before = g.s.doc.points;
    DragController d;
    const glm::dvec2 cp = pixel(g.view, g.s.transformPivot());
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Rotate), g.view, cp.x + 80.0, cp.y));
    d.setAxis(0);
    ASSERT_TRUE(d.update(g.s.doc, g.view, cp.x + 60.0, cp.y - 50.0, false));
    EXPECT_NE(d.lastAngle(), 0.0);
    EXPECT_LT(maxConstraintResidual(g.s.doc), 1e-9);
    bool neighbourMoved = false;
    for (uint32_t p : g.s.doc.patches[1].idx)
        if (g.s.doc.points[p] != before[p] && !std::count(g.s.doc.patches[0].idx.begin(), g.s.doc.patches[0].idx.end(), p))
            neighbourMoved = true;
    EXPECT_TRUE(neighbourMoved);
    d.cancel(g.s.doc);
    EXPECT_EQ(g.s.doc.points, before);

    // Scale by the mouse: twice as far from the pivot is twice the size; Shift+Z keeps z.
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Scale), g.view, cp.x + 50.0, cp.y));
    d.setAxis(2, true);
    ASSERT_TRUE(d.update(g.s.doc, g.view, cp.x + 100.0, cp.y, false));
    EXPECT_NEAR(d.lastScale().x, 2.0, 1e-12);
    EXPECT_EQ(d.lastScale().z, 1.0);
    const Vec3 c = d.anchor();
    const uint32_t corner = g.s.doc.patches[0].idx[0];
    EXPECT_NEAR(g.s.doc.points[corner].x, c.x + 2.0 * (before[corner].x - c.x), 1e-12);
    EXPECT_EQ(g.s.doc.points[corner].z, before[corner].z);
    EXPECT_LT(maxConstraintResidual(g.s.doc), 1e-9);
    ASSERT_TRUE(d.update(g.s.doc, g.view, cp.x + 77.0, cp.y, true));
    EXPECT_NEAR(d.lastScale().x, 1.5, 1e-12);  // 1.54 snapped to 0.1 steps
}

TEST(Transforms, PivotsMedianActiveAndCursor) {
    EditSession s;
    s.reset(makePatchGrid(1, 2, Continuity::C0), "");
    const uint32_t a = s.doc.patches[0].idx[0], b = s.doc.patches[1].idx[15];
    applyClick(s.sel, int(a), false);
    applyClick(s.sel, int(b), true);
    EXPECT_EQ(s.sel.active, int(b));
    s.pivot = PivotMode::Median;
    EXPECT_EQ(s.transformPivot(), 0.5 * (s.doc.points[a] + s.doc.points[b]));
    s.pivot = PivotMode::Active;
    EXPECT_EQ(s.transformPivot(), s.doc.points[b]);
    applyClick(s.sel, int(b), true);  // toggled off: no active point, the median of what is left
    EXPECT_EQ(s.sel.active, -1);
    EXPECT_EQ(s.transformPivot(), s.doc.points[a]);
    s.pivot = PivotMode::Cursor;
    s.cursor = Vec3(3.0, -2.0, 1.0);
    EXPECT_EQ(s.transformPivot(), s.cursor);
    // A whole patch: "active" is its centre.
    s.sel.clear();
    s.sel.patch = 1;
    s.pivot = PivotMode::Active;
    Vec3 centre(0.0);
    for (uint32_t p : s.doc.patches[1].idx) centre += s.doc.points[p];
    EXPECT_NEAR(glm::length(s.transformPivot() - centre / 16.0), 0.0, 1e-15);
}

TEST(Transforms, AxisDragsAlongTheViewDirectionAreDepthBounded) {
    Grid g;
    g.s.sel.patch = -1;
    g.s.sel.points = {g.s.doc.patches[0].idx[5]};
    // From the front, nearly along +Y: Y points into the screen.
    const DragView front = viewOf(0.0, 2.0, Vec3(1.0, 1.0, 0.0));
    const glm::dvec2 at = pixel(front, g.s.doc.points[g.s.sel.points[0]]);
    DragController d;
    // The view-plane rate: a free move of 120 px.
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Move, false), front, at.x, at.y));
    ASSERT_TRUE(d.update(g.s.doc, front, at.x, at.y - 120.0, false));
    const double free = glm::length(d.lastOffset());
    d.cancel(g.s.doc);
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Move, false), front, at.x, at.y));
    d.setAxis(1);
    ASSERT_TRUE(d.update(g.s.doc, front, at.x, at.y - 120.0, false));
    const double along = std::abs(d.lastOffset().y);
    EXPECT_EQ(d.lastOffset().x, 0.0);
    EXPECT_GT(along, 0.5 * free);         // it moves
    EXPECT_LE(along, 4.0 * free + 1e-9);  // but at most four times as fast as the view plane
    EXPECT_LT(maxConstraintResidual(g.s.doc), 1e-9);
    // An axis across the view still follows the mouse exactly.
    d.cancel(g.s.doc);
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Move, false), front, at.x, at.y));
    d.setAxis(0);
    const glm::dvec2 target = pixel(front, g.s.doc.points[g.s.sel.points[0]] + Vec3(0.4, 0.0, 0.0));
    ASSERT_TRUE(d.update(g.s.doc, front, target.x, target.y, false));
    EXPECT_NEAR(d.lastOffset().x, 0.4, 1e-5);
}

TEST(Transforms, SnapsToPointsEdgesAndSurfacesOfOtherItems) {
    EditSession s;
    Document doc;
    addFlatPatch(doc, Vec3(0.0, 0.0, 0.0), 2.0);  // patch 0: moved
    addFlatPatch(doc, Vec3(3.0, 0.0, 0.5), 2.0);  // patch 1: the target, raised 0.5
    s.reset(doc, "");
    s.sel.patch = 0;
    const DragView view = viewOf(0.0, 89.0, Vec3(1.5, 0.0, 0.0), 10.0);
    const uint32_t grabbed = s.doc.patches[0].idx[15];          // the (+1, +1) corner
    const Vec3 target = s.doc.points[s.doc.patches[1].idx[0]];  // patch 1's (2, -1) corner
    const glm::dvec2 from = pixel(view, s.doc.points[grabbed]);
    const glm::dvec2 to = pixel(view, target);
    TransformStart start{s.selectedPoints(), s.doc.points[grabbed], TransformKind::Move, false};
    const std::vector<Vec3> before = s.doc.points;

    DragController d;
    start.snap = SnapTarget::Points;
    ASSERT_TRUE(d.begin(s.doc, start, view, from.x, from.y));
    ASSERT_TRUE(d.update(s.doc, view, to.x + 5.0, to.y - 4.0, true));  // near, not on it
    EXPECT_EQ(s.doc.points[grabbed], target);
    // Away from every point: the mouse, unsnapped.
    ASSERT_TRUE(d.update(s.doc, view, to.x + 60.0, to.y + 40.0, true));
    EXPECT_NE(s.doc.points[grabbed], target);
    // A constraint keeps its axis: only the x of the target.
    d.setAxis(0);
    ASSERT_TRUE(d.update(s.doc, view, to.x + 3.0, to.y + 3.0, true));
    EXPECT_DOUBLE_EQ(s.doc.points[grabbed].x, target.x);
    EXPECT_EQ(s.doc.points[grabbed].y, before[grabbed].y);
    d.cancel(s.doc);

    // Edges: the mouse near the middle of patch 1's v = 0 edge lands on that curve.
    start.snap = SnapTarget::Edges;
    ASSERT_TRUE(d.begin(s.doc, start, view, from.x, from.y));
    const glm::dvec2 edgeMid = pixel(view, Vec3(3.3, -1.0, 0.5));
    ASSERT_TRUE(d.update(s.doc, view, edgeMid.x, edgeMid.y + 6.0, true));
    EXPECT_NEAR(s.doc.points[grabbed].y, -1.0, 1e-9);
    EXPECT_NEAR(s.doc.points[grabbed].z, 0.5, 1e-9);
    EXPECT_NEAR(s.doc.points[grabbed].x, 3.3, 0.02);
    d.cancel(s.doc);

    // Surfaces: where the ray meets patch 1 (z = 0.5), not the moved patch 0 under the mouse.
    start.snap = SnapTarget::Surfaces;
    ASSERT_TRUE(d.begin(s.doc, start, view, from.x, from.y));
    const glm::dvec2 onSurface = pixel(view, Vec3(2.6, 0.3, 0.5));
    ASSERT_TRUE(d.update(s.doc, view, onSurface.x, onSurface.y, true));
    EXPECT_NEAR(s.doc.points[grabbed].z, 0.5, 1e-9);
    EXPECT_NEAR(s.doc.points[grabbed].x, 2.6, 1e-3);
    EXPECT_NEAR(s.doc.points[grabbed].y, 0.3, 1e-3);
    // Over the moved patch only: nothing to snap to, the mouse in the view plane.
    ASSERT_TRUE(d.update(s.doc, view, from.x - 40.0, from.y, true));
    EXPECT_NEAR(s.doc.points[grabbed].z, before[grabbed].z, 1e-6);
}

TEST(Transforms, ScriptCommandsUseThePivotAndSnapSettings) {
    EditSession s;
    s.reset(makePatchGrid(2, 2, Continuity::C1), "");
    const std::vector<Vec3> before = s.doc.points;
    run(s, "select patch 0; pivot cursor; cursor 0 0 0; rotate Z 15");  // 90 would fold the C1 neighbours: refused
    EXPECT_EQ(s.pivot, PivotMode::Cursor);
    for (uint32_t p : s.doc.patches[0].idx)
        EXPECT_NEAR(glm::length(s.doc.points[p] - rotatedAbout(before[p], Vec3(0.0), Vec3(0, 0, 1), 15.0)), 0.0, 1e-12);
    EXPECT_LT(maxConstraintResidual(s.doc), 1e-9);
    run(s, "undo; select all; pivot median; scale 2");
    EXPECT_LT(maxConstraintResidual(s.doc), 1e-12);  // the whole joined grid: no correction needed
    run(s, "snap edges");
    EXPECT_EQ(s.snap, SnapTarget::Edges);
    EXPECT_THROW(run(s, "pivot centre"), InputError);
    EXPECT_THROW(run(s, "snap vertices"), InputError);
}

// U / V / N while grabbing: the drag is the `slide` command under the mouse. A typed distance
// moves the points as `slide u D` does; the mouse moves them along their mean direction; the same
// key again is a plain move, X ends the slide; a point with no polygon refuses it.
TEST(Transforms, SlideWhileGrabbingIsTheSlideCommand) {
    Grid g;
    const std::vector<Vec3> before = g.s.doc.points;
    g.s.sel = Selection{};
    g.s.sel.points = {g.s.doc.patches[0].idx[5], g.s.doc.patches[0].idx[6]};
    DragController d;
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Move), g.view, 400, 300));
    ASSERT_TRUE(d.toggleSlide(g.s.doc, SlideAxis::U));
    EXPECT_EQ(d.slide(), SlideAxis::U);
    for (char ch : std::string("0.25")) d.typeChar(ch);
    ASSERT_TRUE(d.update(g.s.doc, g.view, 555, 123, false));
    EXPECT_NE(d.status().find("Slide 2 points along U: 0.25"), std::string::npos) << d.status();
    const std::vector<Vec3> dragged = g.s.doc.points;
    d.finish(g.s);
    EXPECT_EQ(g.s.history().undoLabel(), "Slide 2 points");
    g.s.undo();
    ASSERT_EQ(g.s.doc.points, before);
    run(g.s, "slide u 0.25");
    for (size_t i = 0; i < before.size(); ++i) EXPECT_LT(glm::length(g.s.doc.points[i] - dragged[i]), 1e-12) << i;
    g.s.undo();

    // By mouse: along the points' own direction, a positive distance to the right (+X from above).
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Move), g.view, 400, 300));
    ASSERT_TRUE(d.toggleSlide(g.s.doc, SlideAxis::U));
    ASSERT_TRUE(d.update(g.s.doc, g.view, 440, 300, false));
    const uint32_t p = g.s.sel.points[0];
    const Vec3 moved = g.s.doc.points[p] - before[p];
    const Vec3 dir = *slideDirection(g.s.committed(), p, SlideAxis::U);
    EXPECT_GT(glm::length(moved), 0.01);
    EXPECT_LT(glm::length(glm::cross(moved, dir)), 1e-9 * glm::length(moved));
    EXPECT_LT(maxConstraintResidual(g.s.doc), 1e-9);
    ASSERT_TRUE(d.toggleSlide(g.s.doc, SlideAxis::U));  // again: a plain move
    EXPECT_FALSE(d.slide());
    ASSERT_TRUE(d.toggleSlide(g.s.doc, SlideAxis::N));
    d.setAxis(0);  // X: a move along X
    EXPECT_FALSE(d.slide());
    d.cancel(g.s.doc);
    EXPECT_EQ(g.s.doc.points, before);

    // A point no patch uses has no polygon: the slide is refused and the move goes on.
    g.s.doc.points.push_back(Vec3(9.0));
    g.s.sel.points = {uint32_t(g.s.doc.points.size() - 1)};
    ASSERT_TRUE(d.begin(g.s.doc, g.start(TransformKind::Move), g.view, 400, 300));
    EXPECT_FALSE(d.toggleSlide(g.s.doc, SlideAxis::V));
    EXPECT_NE(d.refusal().find("no control polygon"), std::string::npos);
    EXPECT_FALSE(d.slide());
    d.cancel(g.s.doc);
}

// Point drags without a window (core/edit/drag_controller.hpp): the mouse moved by pixels moves the
// point in the view plane or along an axis, Ctrl snaps, the joins hold, Esc restores and a
// finished drag is one undo step. Numbers are checked by projecting back to pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/construct/model_builders.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/edit/edit_session.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/picking.hpp"
#include "core/solve/constraint_solver.hpp"

using namespace pw;

namespace {

constexpr int kW = 800, kH = 600;

struct Fixture {
    EditSession s;
    DragView view;
    uint32_t point = 0;  // an inner control point of patch 0, next to the C1 join with patch 1
    Fixture() {
        s.reset(makePatchGrid(2, 2, Continuity::C1), "");
        view.camera = Camera{};
        view.camera.target = {1.0, 1.0, 0.0};
        view.camera.distance = 8.0;
        view.width = kW;
        view.height = kH;
        point = s.doc.patches[0].idx[6];
        s.sel.points = {point};
    }
    glm::dvec2 pixel(const Vec3& p) const {
        const ViewMatrices vm = viewMatrices(view.camera, double(kW) / kH);
        return *projectToPixel(vm, p, kW, kH);
    }
};

}  // namespace

TEST(DragController, NothingSelectedStartsNothing) {
    Fixture f;
    f.s.sel.points.clear();
    DragController d;
    EXPECT_FALSE(d.begin(f.s.doc, f.s.sel, f.view, 100, 100, false));
    EXPECT_FALSE(d.active());
    EXPECT_FALSE(d.update(f.s.doc, f.view, 120, 100, false));
}

TEST(DragController, FreeDragFollowsTheMouseInTheViewPlane) {
    Fixture f;
    const Vec3 before = f.s.doc.points[f.point];
    const glm::dvec2 at = f.pixel(before);
    DragController d;
    ASSERT_TRUE(d.begin(f.s.doc, f.s.sel, f.view, at.x, at.y, false));
    EXPECT_TRUE(d.active());
    EXPECT_FALSE(d.grab());
    EXPECT_EQ(d.axis(), -1);
    EXPECT_EQ(d.movedCount(), 1u);
    EXPECT_EQ(d.anchor(), before);
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x + 40.0, at.y - 25.0, false));
    const Vec3 after = f.s.doc.points[f.point];
    // Under the mouse, in the plane through the start position facing the camera.
    const glm::dvec2 px = f.pixel(after);
    EXPECT_NEAR(px.x, at.x + 40.0, 1e-4);  // projectToPixel works in float matrices
    EXPECT_NEAR(px.y, at.y - 25.0, 1e-4);
    Vec3 r, u, fwd;
    cameraAxes(f.view.camera, r, u, fwd);
    EXPECT_NEAR(glm::dot(after - before, fwd), 0.0, 1e-9);
    EXPECT_GT(glm::length(after - before), 0.1);
    // The joins hold: the solver moved the neighbours.
    EXPECT_LT(maxConstraintResidual(f.s.doc), 1e-9);
    EXPECT_NE(f.s.doc.points, f.s.committed().points);
}

TEST(DragController, AxisConstraintMovesAlongThatAxisOnly) {
    Fixture f;
    const Vec3 before = f.s.doc.points[f.point];
    const glm::dvec2 at = f.pixel(before);
    DragController d;
    ASSERT_TRUE(d.begin(f.s.doc, f.s.sel, f.view, at.x, at.y, true));
    EXPECT_TRUE(d.grab());
    d.toggleAxis(0);
    EXPECT_EQ(d.axis(), 0);
    // The mouse over where the point would be 0.7 further along X: the point goes exactly there.
    const glm::dvec2 target = f.pixel(before + Vec3(0.7, 0.0, 0.0));
    ASSERT_TRUE(d.update(f.s.doc, f.view, target.x, target.y, false));
    const Vec3 after = f.s.doc.points[f.point];
    EXPECT_NEAR(after.x - before.x, 0.7, 1e-6);  // the target pixel came through float matrices
    EXPECT_EQ(after.y, before.y);
    EXPECT_EQ(after.z, before.z);
    // Off the axis's screen line the mouse still moves the point along X only.
    ASSERT_TRUE(d.update(f.s.doc, f.view, target.x + 15.0, target.y + 30.0, false));
    EXPECT_EQ(f.s.doc.points[f.point].y, before.y);
    EXPECT_EQ(f.s.doc.points[f.point].z, before.z);
    EXPECT_LT(maxConstraintResidual(f.s.doc), 1e-9);
    // Z: only z changes; the same key again frees the drag.
    d.toggleAxis(2);
    EXPECT_EQ(d.axis(), 2);
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x, at.y - 50.0, false));
    EXPECT_EQ(f.s.doc.points[f.point].x, before.x);
    EXPECT_EQ(f.s.doc.points[f.point].y, before.y);
    EXPECT_GT(f.s.doc.points[f.point].z, before.z);
    d.toggleAxis(2);
    EXPECT_EQ(d.axis(), -1);
}

TEST(DragController, SnapPutsTheCentreOnTheGrid) {
    Fixture f;
    const Vec3 before = f.s.doc.points[f.point];
    const glm::dvec2 at = f.pixel(before);
    const double step = niceGridStep(modelSize(f.s.doc)) / 5.0;
    DragController d;
    ASSERT_TRUE(d.begin(f.s.doc, f.s.sel, f.view, at.x, at.y, false));
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x + 33.0, at.y + 17.0, true));
    const Vec3 after = f.s.doc.points[f.point];
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(after[k] / step, std::round(after[k] / step), 1e-9) << k;
    // Along an axis only that coordinate snaps.
    d.setAxis(1);
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x + 5.0, at.y - 40.0, true));
    const Vec3 onAxis = f.s.doc.points[f.point];
    EXPECT_NEAR(onAxis.y / step, std::round(onAxis.y / step), 1e-9);
    EXPECT_EQ(onAxis.x, before.x);
    EXPECT_EQ(onAxis.z, before.z);
}

TEST(DragController, ChangedListsThePointsMovedSinceTheLastUpdate) {
    Fixture f;
    const std::vector<Vec3> before = f.s.doc.points;
    const glm::dvec2 at = f.pixel(before[f.point]);
    DragController d;
    ASSERT_TRUE(d.begin(f.s.doc, f.s.sel, f.view, at.x, at.y, false));
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x + 30.0, at.y, false));
    const std::vector<uint32_t> changed = d.changed();
    EXPECT_NE(std::find(changed.begin(), changed.end(), f.point), changed.end());
    EXPECT_GT(changed.size(), 1u);  // the neighbours across the join
    for (size_t i = 0; i < before.size(); ++i) {
        const bool listed = std::find(changed.begin(), changed.end(), uint32_t(i)) != changed.end();
        EXPECT_TRUE(listed || f.s.doc.points[i] == before[i]) << i;
    }
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x + 30.0, at.y, false));
    EXPECT_TRUE(d.changed().empty());
}

TEST(DragController, CancelRestoresEveryPoint) {
    Fixture f;
    const std::vector<Vec3> before = f.s.doc.points;
    const size_t steps = f.s.history().size();
    const glm::dvec2 at = f.pixel(before[f.point]);
    DragController d;
    ASSERT_TRUE(d.begin(f.s.doc, f.s.sel, f.view, at.x, at.y, false));
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x - 60.0, at.y + 10.0, false));
    ASSERT_NE(f.s.doc.points, before);
    d.cancel(f.s.doc);
    EXPECT_FALSE(d.active());
    EXPECT_EQ(f.s.doc.points, before);
    EXPECT_EQ(f.s.history().size(), steps);
    EXPECT_FALSE(f.s.isModified());
}

TEST(DragController, FinishIsOneUndoStep) {
    Fixture f;
    const std::vector<Vec3> before = f.s.doc.points;
    const size_t steps = f.s.history().size();
    const glm::dvec2 at = f.pixel(before[f.point]);
    DragController d;
    ASSERT_TRUE(d.begin(f.s.doc, f.s.sel, f.view, at.x, at.y, false));
    for (int i = 1; i <= 10; ++i) ASSERT_TRUE(d.update(f.s.doc, f.view, at.x + 4.0 * i, at.y + 2.0 * i, false));
    const std::vector<Vec3> dragged = f.s.doc.points;
    d.finish(f.s);
    EXPECT_FALSE(d.active());
    EXPECT_EQ(f.s.history().size(), steps + 1);
    EXPECT_EQ(f.s.history().undoLabel(), "Move point");
    EXPECT_TRUE(f.s.isModified());
    EXPECT_EQ(f.s.committed().points, dragged);
    ASSERT_TRUE(f.s.undo());
    EXPECT_EQ(f.s.doc.points, before);
    ASSERT_TRUE(f.s.redo());
    EXPECT_EQ(f.s.doc.points, dragged);
}

TEST(DragController, SeveralPointsMoveTogetherAndNoMoveCommitsNothing) {
    Fixture f;
    const uint32_t other = f.s.doc.patches[0].idx[5];
    f.s.sel.points = {std::min(f.point, other), std::max(f.point, other)};
    const std::vector<Vec3> before = f.s.doc.points;
    const glm::dvec2 at = f.pixel(selectionCentroid(f.s.doc, f.s.sel));
    DragController d;
    ASSERT_TRUE(d.begin(f.s.doc, f.s.sel, f.view, at.x, at.y, false));
    EXPECT_EQ(d.movedCount(), 2u);
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x, at.y + 30.0, false));
    const Vec3 a = f.s.doc.points[f.point] - before[f.point], b = f.s.doc.points[other] - before[other];
    EXPECT_NEAR(glm::length(a - b), 0.0, 1e-12);  // one offset for both
    d.finish(f.s);
    EXPECT_EQ(f.s.history().undoLabel(), "Move 2 points");

    // Back where it started: no undo step.
    const size_t steps = f.s.history().size();
    ASSERT_TRUE(d.begin(f.s.doc, f.s.sel, f.view, at.x, at.y, false));
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x + 20.0, at.y, false));
    ASSERT_TRUE(d.update(f.s.doc, f.view, at.x, at.y, false));
    d.finish(f.s);
    EXPECT_EQ(f.s.history().size(), steps);
}

TEST(HeldPointEdit, SetsThePointAndHoldsTheJoins) {
    Fixture f;
    HeldPointEdit edit;
    const Vec3 want = f.s.doc.points[f.point] + Vec3(0.1, -0.2, 0.3);
    EXPECT_EQ(edit.set(f.s, f.point, want), "");
    EXPECT_EQ(f.s.doc.points[f.point], want);
    EXPECT_LT(maxConstraintResidual(f.s.doc), 1e-9);
    // A second value starts again from the committed document.
    const Vec3 again = f.s.committed().points[f.point] + Vec3(0.0, 0.0, -0.4);
    EXPECT_EQ(edit.set(f.s, f.point, again), "");
    EXPECT_EQ(f.s.doc.points[f.point], again);
    f.s.commit("Edit point");
    EXPECT_EQ(f.s.history().undoLabel(), "Edit point");

    const std::vector<Vec3> kept = f.s.doc.points;
    const std::string msg = edit.set(f.s, f.point, Vec3(std::nan(""), 0.0, 0.0));
    EXPECT_NE(msg.find("finite"), std::string::npos) << msg;
    EXPECT_NE(edit.set(f.s, f.point, Vec3(0.0, 1e300, 0.0)), "");
    EXPECT_EQ(f.s.doc.points, kept);
}

// Mirror (core/ops/mirror.hpp and the `mirror` command): the copy is the reflection (points and
// normals), shares the points on the plane, is joined there (C1 where the rows meet the plane at a
// right angle, else C0), keeps the joins among the copies, and is one undo step.
#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/model_builders.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/ops/mirror.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/solve/constraint_solver.hpp"

#include "support.hpp"

using namespace pw;

namespace {

void run(EditSession& s, const std::string& script) { test::runEditScript(s, script); }

Vec3 reflect(Vec3 v, int axis) {
    v[axis] = -v[axis];
    return v;
}

// The mirrored patch is the reflection: its point at (1-u, v) is the original's at (u, v)
// reflected, and so is its normal (outward stays outward).
void expectReflection(const Document& d, uint32_t original, uint32_t copy, int axis, double at) {
    const Net16 a = gatherNet(d, d.patches[original].idx), b = gatherNet(d, d.patches[copy].idx);
    for (double u : {0.0, 0.3, 0.8})
        for (double v : {0.1, 0.5, 1.0}) {
            const SurfacePoint pa = evaluateNet(a, Basis::Bezier, 0.5, u, v), pb = evaluateNet(b, Basis::Bezier, 0.5, 1.0 - u, v);
            Vec3 want = pa.p;
            want[axis] = 2.0 * at - want[axis];
            EXPECT_NEAR(glm::length(pb.p - want), 0.0, 1e-12);
            EXPECT_NEAR(glm::length(pb.n - reflect(pa.n, axis)), 0.0, 1e-9) << u << " " << v;
        }
}

}  // namespace

TEST(Mirror, FlatPatchMeetsItsMirrorC1OnThePlane) {
    EditSession s;
    Document d;
    addFlatPatch(d, Vec3(0.5, 0.0, 0.0), 1.0);  // x in [0, 1]: edge u1 on x = 1
    s.reset(d, "");
    run(s, "select patch 0; cursor 1 0 0; mirror X");
    ASSERT_EQ(s.doc.patches.size(), 2u);
    EXPECT_EQ(s.doc.points.size(), 16u + 12u);  // the four points on the plane are shared
    ASSERT_EQ(s.doc.joins.size(), 1u);
    EXPECT_EQ(s.doc.joins[0].continuity, Continuity::C1);
    EXPECT_LT(maxConstraintResidual(s.doc), 1e-12);
    expectReflection(s.doc, 0, 1, 0, 1.0);
    EXPECT_EQ(s.sel.patch, 1);  // the copy is selected, ready to move
    EXPECT_EQ(s.history().undoLabel(), "Mirror X");
    run(s, "undo");
    EXPECT_EQ(s.doc.patches.size(), 1u);
}

TEST(Mirror, ARowAtAnAngleToThePlaneJoinsC0) {
    EditSession s;
    Document d;
    addFlatPatch(d, Vec3(0.5, 0.0, 0.0), 1.0);
    d.points[d.patches[0].idx[6]].z = 0.3;  // the tangent row next to edge u1 tilts up
    s.reset(d, "");
    run(s, "select patch 0; cursor 1 0 0; mirror X");
    ASSERT_EQ(s.doc.joins.size(), 1u);
    EXPECT_EQ(s.doc.joins[0].continuity, Continuity::C0);
    expectReflection(s.doc, 0, 1, 0, 1.0);
}

TEST(Mirror, AJoinedGridKeepsItsJoinsAndIsJoinedAcrossThePlane) {
    EditSession s;
    s.reset(makePatchGrid(2, 2, Continuity::C1), "");  // x in [0, 2]
    const size_t joins = s.doc.joins.size();
    run(s, "select all; cursor 2 0 0; mirror X");
    ASSERT_EQ(s.doc.patches.size(), 8u);
    // The copies' own joins, and the two seams on x = 2.
    EXPECT_EQ(s.doc.joins.size(), 2 * joins + 2);
    EXPECT_LT(maxConstraintResidual(s.doc), 1e-9);
    for (uint32_t p = 0; p < 4; ++p) expectReflection(s.doc, p, 4 + p, 0, 2.0);
    // Off the plane nothing is shared: mirroring across x = 5 makes a separate copy.
    EditSession t;
    t.reset(makePatchGrid(1, 1), "");
    run(t, "select patch 0; cursor 5 0 0; mirror X");
    EXPECT_EQ(t.doc.points.size(), 32u);
    EXPECT_TRUE(t.doc.joins.empty());
}

TEST(Mirror, TrianglesAndCurvesAreReflectedAndErrorsAreClear) {
    EditSession s;
    s.reset(makeTriangleDome(), "");
    run(s, "select triangle 0; cursor 0 0 0; mirror Y");
    ASSERT_EQ(s.doc.triangles.size(), 7u);
    const Net10 a = gatherTriangleNet(s.doc, s.doc.triangles[0].idx), b = gatherTriangleNet(s.doc, s.doc.triangles[6].idx);
    for (double u : {0.2, 0.5})
        for (double v : {0.1, 0.3}) {
            const TriPoint pa = evaluateTriangle(a, u, v), pb = evaluateTriangle(b, v, u);
            EXPECT_NEAR(glm::length(pb.p - reflect(pa.p, 1)), 0.0, 1e-12);
            EXPECT_NEAR(glm::length(pb.n - reflect(pa.n, 1)), 0.0, 1e-9);
        }
    run(s, "add-curve; select curve 0; mirror Z");
    EXPECT_EQ(s.doc.curves.size(), 2u);

    EditSession e;
    e.reset(makePatchGrid(1, 1), "");
    EXPECT_THROW(run(e, "select none; mirror X"), InputError);
    EXPECT_THROW(run(e, "select patch 0; mirror W"), InputError);
}

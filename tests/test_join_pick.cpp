// Join by picking: the orientation a join chooses (the patches end up on opposite sides of the
// seam with agreeing normals, never folded), Match when the edges do not meet (A stays, B's rows
// move), the refusal when B cannot be turned over, the same through the `join` command, and the
// boundary-edge picking the join tool hovers and clicks.
#include <gtest/gtest.h>

#include <cmath>

#include "core/edit/edit_session.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/model/camera_math.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/select/edge_pick.hpp"
#include "core/solve/constraint_solver.hpp"
#include "support.hpp"

using namespace pw;

namespace {

SurfacePoint at(const Document& doc, uint32_t p, double u, double v) {
    return evaluateNet(gatherNet(doc, doc.patches[p].idx), Basis::Bezier, 0.5, u, v);
}

// (u, v) of the point k/3 along edge e.
std::pair<double, double> onEdge(Edge e, double t) {
    switch (e) {
        case Edge::U0:
            return {0.0, t};
        case Edge::U1:
            return {1.0, t};
        case Edge::V0:
            return {t, 0.0};
        default:
            return {t, 1.0};
    }
}

// The normals of both sides of join j agree along the seam.
void expectNormalsAgree(const Document& doc, const Join& j) {
    for (double t : {0.1, 0.5, 0.9}) {
        const auto [ua, va] = onEdge(j.edgeA, t);
        const auto [ub, vb] = onEdge(j.edgeB, j.reversed ? 1.0 - t : t);
        const SurfacePoint a = at(doc, j.patchA, ua, va), b = at(doc, j.patchB, ub, vb);
        EXPECT_LT(glm::length(a.p - b.p), 1e-12);
        EXPECT_GT(glm::dot(a.n, b.n), 1.0 - 1e-9) << "t " << t;
    }
}

Camera topCamera() {
    Camera c;
    c.target = {0.5, 0.0, 0.0};
    c.distance = 5.0;
    c.yawDeg = 0.0;
    c.pitchDeg = 89.0;
    return c;
}

constexpr int kW = 800, kH = 600;

glm::dvec2 pixel(const Camera& cam, const Vec3& p) { return *projectToPixel(viewMatrices(cam, double(kW) / kH), p, kW, kH); }

}  // namespace

TEST(JoinPick, APatchLyingBackOverAIsTurnedOverNotFolded) {
    Document doc;
    addFlatPatch(doc, {0, 0, 0}, 1.0);    // A: x in [-0.5, 0.5]
    addFlatPatch(doc, {0.2, 0, 0}, 1.0);  // B overlaps A: x in [-0.3, 0.7]
    const std::vector<Vec3> aBefore = [&] {
        std::vector<Vec3> v;
        for (uint32_t i : doc.patches[0].idx) v.push_back(doc.points[i]);
        return v;
    }();
    // B's u1 edge (x = 0.7): B extends from it back over A.
    const JoinPlan plan = planJoin(doc, 0, Edge::U1, 1, Edge::U1);
    EXPECT_TRUE(plan.flipB);
    EXPECT_TRUE(plan.reflectB);
    EXPECT_TRUE(plan.match);
    const size_t j = joinEdges(doc, 0, Edge::U1, 1, Edge::U1, Continuity::C1);
    EXPECT_EQ(doc.joins[j].edgeB, Edge::U0);  // the same physical edge, renamed by the flip
    for (size_t s = 0; s < 16; ++s) EXPECT_EQ(doc.points[doc.patches[0].idx[s]], aBefore[s]);  // A stays
    for (uint32_t i : doc.patches[1].idx) EXPECT_GE(doc.points[i].x, 0.5 - 1e-12);             // B beyond the seam
    EXPECT_LE(maxConstraintResidual(doc), 1e-12);
    expectNormalsAgree(doc, doc.joins[j]);
}

TEST(JoinPick, AFreePatchIsFlippedSoNormalsAgree) {
    Document doc;
    addFlatPatch(doc, {0, 0, 0}, 1.0);
    addFlatPatch(doc, {1.0, 0, 0}, 1.0);
    flipPatch(doc, 1);  // its normal points down; its u1 edge lies at x = 0.5, on A's u1
    const Vec3 before = doc.points[doc.patches[1].idx[5]];
    const size_t j = joinEdges(doc, 0, Edge::U1, 1, Edge::U1, Continuity::C1);
    EXPECT_EQ(doc.joins[j].edgeB, Edge::U0);
    EXPECT_FALSE(doc.joins[j].reversed);
    expectNormalsAgree(doc, doc.joins[j]);
    // The edges met: nothing moved, B's interior is where it was.
    EXPECT_EQ(doc.points.size(), 28u);
    EXPECT_EQ(doc.points[doc.patches[1].idx[6]], before);  // slot 5 became slot 6 by the flip
}

TEST(JoinPick, AnAgreeingPairIsLeftAsItIs) {
    Document doc;
    addFlatPatch(doc, {0, 0, 0}, 1.0);
    addFlatPatch(doc, {1.0, 0, 0}, 1.0);
    const auto net = gatherNet(doc, doc.patches[1].idx);
    const JoinPlan plan = planJoin(doc, 0, Edge::U1, 1, Edge::U0);
    EXPECT_FALSE(plan.flipB || plan.reflectB || plan.match || plan.reversed);
    joinEdges(doc, 0, Edge::U1, 1, Edge::U0, Continuity::C1);
    EXPECT_EQ(gatherNet(doc, doc.patches[1].idx), net);  // the edges met: nothing moved or turned
    expectNormalsAgree(doc, doc.joins[0]);
}

TEST(JoinPick, MatchMovesOnlyBsBoundaryAndTangentRows) {
    for (Continuity c : {Continuity::C0, Continuity::C1, Continuity::G1}) {
        Document doc;
        addFlatPatch(doc, {0, 0, 0}, 1.0);
        doc.points[doc.patches[0].idx[6]].z += 0.4;  // A curved
        addFlatPatch(doc, {2.5, 0.3, 1.0}, 1.0);     // B away from A, its u0 edge facing A's u1
        const auto aBefore = gatherNet(doc, doc.patches[0].idx);
        const auto bBefore = gatherNet(doc, doc.patches[1].idx);
        const size_t j = joinEdges(doc, 0, Edge::U1, 1, Edge::U0, c);
        EXPECT_EQ(gatherNet(doc, doc.patches[0].idx), aBefore) << continuityName(c);
        const auto b = gatherNet(doc, doc.patches[1].idx);
        for (int k = 0; k < 4; ++k) {
            EXPECT_EQ(b[size_t(edgeSlot(Edge::U0, k, 0))], aBefore[size_t(edgeSlot(Edge::U1, k, 0))]);
            for (int d = 2; d < 4; ++d) EXPECT_EQ(b[size_t(edgeSlot(Edge::U0, k, d))], bBefore[size_t(edgeSlot(Edge::U0, k, d))]);
        }
        EXPECT_LE(maxConstraintResidual(doc), 1e-12) << continuityName(c);
        if (c != Continuity::C0) expectNormalsAgree(doc, doc.joins[j]);
    }
}

TEST(JoinPick, APatchThatCannotTurnOverIsRefusedAndNothingChanges) {
    Document doc;
    addFlatPatch(doc, {0, 0, 0}, 1.0);
    addFlatPatch(doc, {0.2, 0, 0.5}, 1.0);  // B, lying back over A from its u1 edge...
    extrudeEdge(doc, 1, Edge::V0);          // ...and joined to a third patch
    const Document before = doc;
    EXPECT_THROW(joinEdges(doc, 0, Edge::U1, 1, Edge::U1, Continuity::C1), EditError);
    EXPECT_EQ(doc.points, before.points);
    EXPECT_EQ(doc.joins.size(), before.joins.size());
}

TEST(JoinPick, TheJoinCommandMatchesAndOrientsTheSame) {
    EditSession s;
    test::runEditScript(s, "add-patch; cursor 3 0 1; add-patch");
    const auto a = gatherNet(s.doc, s.doc.patches[0].idx);
    // Patch 1's u1 edge is its far side: B is turned over towards A, then matched.
    test::runEditScript(s, "join 0:u1 1:u1 C1");
    ASSERT_EQ(s.doc.joins.size(), 1u);
    EXPECT_EQ(gatherNet(s.doc, s.doc.patches[0].idx), a);
    const double seamX = a[size_t(edgeSlot(Edge::U1, 0, 0))].x;
    for (uint32_t i : s.doc.patches[1].idx) EXPECT_GE(s.doc.points[i].x, seamX - 1e-12);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-12);
    expectNormalsAgree(s.doc, s.doc.joins[0]);
}

TEST(JoinPick, PicksTheOpenEdgeUnderTheMouse) {
    Document doc;
    addFlatPatch(doc, {0, 0, 0}, 1.0);
    addFlatPatch(doc, {1.0, 0, 0}, 1.0);  // edge to edge at x = 0.5, points not shared
    const Camera cam = topCamera();
    const glm::dvec2 mid = pixel(cam, {0.5, 0.0, 0.0});
    const double pxPerUnit = glm::length(pixel(cam, {1.5, 0.0, 0.0}) - mid);
    // Just inside each patch: its own edge, though both lie under the mouse.
    const auto a = pickBoundaryEdge(doc, cam, mid.x - 2.0, mid.y, kW, kH, 9.0);
    const auto b = pickBoundaryEdge(doc, cam, mid.x + 2.0, mid.y, kW, kH, 9.0);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(*a, (PatchEdge{0, Edge::U1}));
    EXPECT_EQ(*b, (PatchEdge{1, Edge::U0}));
    // The first pick's patch is left out for the second.
    EXPECT_EQ(pickBoundaryEdge(doc, cam, mid.x - 2.0, mid.y, kW, kH, 9.0, 0), (PatchEdge{1, Edge::U0}));
    // The far side of patch 1, and nothing in the middle of a patch.
    const glm::dvec2 far = pixel(cam, {1.5, 0.2, 0.0});
    EXPECT_EQ(pickBoundaryEdge(doc, cam, far.x + 3.0, far.y, kW, kH, 9.0), (PatchEdge{1, Edge::U1}));
    EXPECT_FALSE(pickBoundaryEdge(doc, cam, mid.x + 0.5 * pxPerUnit, mid.y, kW, kH, 9.0));
    // A joined edge is no longer offered; hidden patches are not either.
    joinEdges(doc, 0, Edge::U1, 1, Edge::U0, Continuity::C1);
    const auto after = pickBoundaryEdge(doc, cam, mid.x, mid.y, kW, kH, 9.0);
    EXPECT_TRUE(!after || (after->edge != Edge::U1 && after->edge != Edge::U0));
    doc.patches[1].hidden = true;
    EXPECT_FALSE(pickBoundaryEdge(doc, cam, far.x, far.y, kW, kH, 9.0));
    EXPECT_EQ(patchEdgeName({3, Edge::V1}), "3:v1");
}

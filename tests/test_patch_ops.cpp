// Editor patch operations: add, duplicate, delete (joins fixed up), flip, extrude (C1), split
// (exact), join (C0/C1/G1) and unjoin, pool compaction. After each, every join must hold.
#include <gtest/gtest.h>

#include <cmath>

#include "core/construct/model_builders.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/ops/split_ops.hpp"
#include "core/select/picking.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"

using namespace pw;

namespace {

void expectJoinsHold(const Document& doc) {
    EXPECT_LE(maxConstraintResidual(doc), 1e-6 * modelSize(doc));
    for (const Join& j : doc.joins) {
        ASSERT_LT(j.patchA, doc.patches.size());
        ASSERT_LT(j.patchB, doc.patches.size());
    }
    for (const JoinContinuity& c : continuityReport(doc, 8)) EXPECT_LE(c.c0Gap, 1e-9 * modelSize(doc));
}

void expectNoUnusedPoints(const Document& doc) {
    const auto used = usedPointMask(doc);
    EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
}

Vec3 evalAt(const Document& doc, uint32_t p, double u, double v) {
    return evaluateNet(gatherNet(doc, doc.patches[p].idx), Basis::Bezier, 0.5, u, v).p;
}

}  // namespace

TEST(EditorPatchOps, AddAndDuplicate) {
    Document doc;
    const uint32_t p = addFlatPatch(doc, {1, 2, 3}, 2.0);
    EXPECT_EQ(p, 0u);
    EXPECT_EQ(doc.points.size(), 16u);
    const Vec3 c = evalAt(doc, 0, 0.5, 0.5);
    EXPECT_NEAR(glm::length(c - Vec3(1, 2, 3)), 0.0, 1e-12);
    const uint32_t q = duplicatePatch(doc, 0, {5, 0, 0});
    EXPECT_EQ(doc.points.size(), 32u);
    EXPECT_NEAR(glm::length(evalAt(doc, q, 0.5, 0.5) - Vec3(6, 2, 3)), 0.0, 1e-12);
    for (uint32_t i : doc.patches[q].idx) EXPECT_GE(i, 16u);  // own points
    EXPECT_THROW(duplicatePatch(doc, 7, {}), EditError);
}

TEST(EditorPatchOps, DeleteFixesJoinsAndPool) {
    Document doc = makePatchGrid(2, 2);
    const size_t joins = doc.joins.size();
    ASSERT_EQ(joins, 4u);
    deletePatch(doc, 0);
    EXPECT_EQ(doc.patches.size(), 3u);
    EXPECT_EQ(doc.joins.size(), 2u);  // the two joins of patch 0 are gone
    expectJoinsHold(doc);
    expectNoUnusedPoints(doc);
}

TEST(EditorPatchOps, FlipReversesNormalKeepsJoins) {
    Document doc = makePatchGrid(1, 2);
    const Net16 before = gatherNet(doc, doc.patches[0].idx);
    const Vec3 n0 = evaluateNet(before, Basis::Bezier, 0.5, 0.3, 0.4).n;
    flipPatch(doc, 0);
    const Vec3 n1 = evaluateNet(gatherNet(doc, doc.patches[0].idx), Basis::Bezier, 0.5, 0.7, 0.4).n;
    EXPECT_NEAR(glm::dot(n0, n1), -1.0, 1e-9);
    expectJoinsHold(doc);
    flipPatch(doc, 0);
    EXPECT_EQ(gatherNet(doc, doc.patches[0].idx), before);
    expectJoinsHold(doc);
}

// flipPatches turns several patches in one pass over the joins, as flipPatch one after the other
// would: the same nets, the same joins (a .bpt import flips every patch this way).
TEST(EditorPatchOps, FlipPatchesIsFlipPatchOneByOne) {
    Document batch = makePatchGrid(3, 3, Continuity::C1);
    Document single = batch;
    flipPatches(batch, {0, 4, 5, 8, 4});  // 4 twice: flipped once
    for (uint32_t p : {0u, 4u, 5u, 8u}) flipPatch(single, p);
    EXPECT_EQ(batch.patches, single.patches);
    EXPECT_EQ(batch.joins, single.joins);
    expectJoinsHold(batch);
    EXPECT_THROW(flipPatches(batch, {9}), EditError);
}

TEST(EditorPatchOps, ExtrudeIsC1) {
    Document doc = makePatchGrid(1, 1);
    for (Edge e : {Edge::U0, Edge::U1, Edge::V0, Edge::V1}) {
        Document d = doc;
        const uint32_t q = extrudeEdge(d, 0, e);
        EXPECT_EQ(q, 1u);
        ASSERT_EQ(d.joins.size(), 1u);
        EXPECT_EQ(d.joins[0].continuity, Continuity::C1);
        expectJoinsHold(d);
        const auto rep = continuityReport(d, 16);
        ASSERT_EQ(rep.size(), 1u);
        EXPECT_LT(rep[0].c1Residual, 1e-9);
        EXPECT_LT(rep[0].normalAngleDeg, 1e-3);         // same orientation on both sides
        EXPECT_THROW(extrudeEdge(d, 0, e), EditError);  // already joined
    }
}

TEST(EditorPatchOps, SplitIsExactAndJoined) {
    for (bool alongU : {true, false})
        for (double t : {0.5, 0.3}) {
            Document doc = makePatchGrid(2, 2);
            const Document orig = doc;
            const auto [a, b] = splitPatch(doc, 3, alongU, t);
            EXPECT_EQ(a, 3u);
            // The cut crosses one joined edge of the corner patch: its neighbour is cut too (the
            // ring), that join becomes two, and each cut patch's halves are joined: 4 + 1 + 2.
            EXPECT_EQ(doc.patches.size(), 6u);
            EXPECT_EQ(doc.joins.size(), 7u);
            for (double s : {0.0, 0.25, 0.8, 1.0})
                for (double w : {0.1, 0.6}) {
                    const Vec3 pa = alongU ? evalAt(doc, a, s, w) : evalAt(doc, a, w, s);
                    const Vec3 po = alongU ? evalAt(orig, 3, s * t, w) : evalAt(orig, 3, w, s * t);
                    EXPECT_LT(glm::length(pa - po), 1e-12);
                    const Vec3 pb = alongU ? evalAt(doc, b, s, w) : evalAt(doc, b, w, s);
                    const Vec3 pob = alongU ? evalAt(orig, 3, t + s * (1 - t), w) : evalAt(orig, 3, w, t + s * (1 - t));
                    EXPECT_LT(glm::length(pb - pob), 1e-12);
                }
            const Join& seam = doc.joins.back();
            EXPECT_EQ(seam.continuity, t == 0.5 ? Continuity::C1 : Continuity::G1);
            expectJoinsHold(doc);
            expectNoUnusedPoints(doc);
        }
}

TEST(EditorPatchOps, JoinAndUnjoin) {
    for (Continuity c : {Continuity::C0, Continuity::C1, Continuity::G1}) {
        Document doc;
        addFlatPatch(doc, {0, 0, 0}, 1.0);
        addFlatPatch(doc, {1.05, 0, 0.02}, 1.0);     // a small gap to the right
        doc.points[doc.patches[1].idx[5]].z += 0.2;  // bend the second patch a little
        const size_t j = joinEdges(doc, 0, Edge::U1, 1, Edge::U0, c);
        EXPECT_EQ(j, 0u);
        EXPECT_EQ(doc.joins[0].continuity, c);
        for (int k = 0; k < 4; ++k)
            EXPECT_EQ(doc.patches[0].idx[size_t(edgeSlot(Edge::U1, k))], doc.patches[1].idx[size_t(edgeSlot(Edge::U0, k))]);
        EXPECT_EQ(doc.points.size(), 28u);  // four merged
        expectJoinsHold(doc);
        // The same pair again changes the join's continuity in place; another edge against a
        // joined one is refused.
        EXPECT_EQ(joinEdges(doc, 0, Edge::U1, 1, Edge::U0, Continuity::G1), 0u);
        EXPECT_EQ(doc.joins.size(), 1u);
        EXPECT_EQ(doc.joins[0].continuity, Continuity::G1);
        expectJoinsHold(doc);
        EXPECT_THROW(joinEdges(doc, 0, Edge::U1, 1, Edge::V0, c), EditError);

        unjoin(doc, 0);
        EXPECT_TRUE(doc.joins.empty());
        for (int k = 0; k < 4; ++k)
            EXPECT_NE(doc.patches[0].idx[size_t(edgeSlot(Edge::U1, k))], doc.patches[1].idx[size_t(edgeSlot(Edge::U0, k))]);
    }
}

TEST(EditorPatchOps, JoinFindsReversedDirection) {
    Document doc;
    addFlatPatch(doc, {0, 0, 0}, 1.0);
    addFlatPatch(doc, {1.0, 0, 0}, 1.0);
    flipPatch(doc, 1);  // its u0 edge now lies at x = 1.5, u1 at x = 0.5
    // Edge V0 of both: parallel but we pick patch 1's u1 edge (x=0.5 column) to meet patch 0's u1.
    const size_t j = joinEdges(doc, 0, Edge::U1, 1, Edge::U1, Continuity::C0);
    EXPECT_FALSE(doc.joins[j].reversed);
    expectJoinsHold(doc);
}

TEST(EditorPatchOps, NearestEdge) {
    EXPECT_EQ(nearestEdge(0.05, 0.5), Edge::U0);
    EXPECT_EQ(nearestEdge(0.5, 0.02), Edge::V0);
    EXPECT_EQ(nearestEdge(0.97, 0.5), Edge::U1);
    EXPECT_EQ(nearestEdge(0.5, 0.9), Edge::V1);
}

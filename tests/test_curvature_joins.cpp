// C2 and G2 joins (issue 21): β-constraints held by the drag solver. After random drags the
// cross-boundary first and second derivatives of C2 joins agree to 1e-9 and the curvature of G2
// joins (Gaussian, mean and normal across the seam, computed from the derivatives of each side
// on its own) to 1e-6 relative; over-constrained sets are reported with their joins; split keeps
// the β values right; files and the `join` command carry C2/G2; the continuity report's
// curvature deviation and tolerances.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/model_builders.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/gpu/curvature_math.h"
#include "core/io/patchwork_format.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/ops/split_ops.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"
#include "tests/support.hpp"

using namespace pw;
using namespace pw::test;

namespace {

// (u, v) of parameter t along edge e.
void edgeUv(Edge e, double t, double& u, double& v) {
    u = e == Edge::U0 ? 0.0 : e == Edge::U1 ? 1.0 : t;
    v = e == Edge::V0 ? 0.0 : e == Edge::V1 ? 1.0 : t;
}

SurfaceJet jetOn(const Document& doc, uint32_t p, Edge e, double t) {
    double u = 0, v = 0;
    edgeUv(e, t, u, v);
    const Patch& P = doc.patches[p];
    return evaluateJet(gatherNet(doc, P.idx), P.basis, P.tension, u, v);
}

// Largest relative mismatch of the first and second cross-boundary derivatives over every join of
// a grid (A's u1/v1 against B's u0/v0, same direction, alpha 1).
double worstC2Mismatch(const Document& doc) {
    double worst = 0;
    for (const Join& j : doc.joins)
        for (int s = 0; s <= 8; ++s) {
            const double t = s / 8.0;
            const SurfaceJet a = jetOn(doc, j.patchA, j.edgeA, t), b = jetOn(doc, j.patchB, j.edgeB, t);
            const bool alongU = j.edgeA == Edge::U1;  // the cross-boundary parameter
            const Vec3 d1a = alongU ? a.du : a.dv, d1b = alongU ? b.du : b.dv;
            const Vec3 d2a = alongU ? a.duu : a.dvv, d2b = alongU ? b.duu : b.dvv;
            worst = std::max(worst, glm::length(d1a - d1b) / (1.0 + glm::length(d1a)));
            worst = std::max(worst, glm::length(d2a - d2b) / (1.0 + glm::length(d2a)));
        }
    return worst;
}

// Drags `rounds` random single points by random offsets through the solver, as the editor does.
void randomDrags(Document& doc, int rounds, double size, uint32_t seed, const std::vector<uint32_t>& candidates = {}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> off(-size, size);
    for (int r = 0; r < rounds; ++r) {
        const uint32_t p = candidates.empty() ? uint32_t(rng() % doc.points.size()) : candidates[rng() % candidates.size()];
        const DragSolver solver(doc, {p});
        doc.points[p] += Vec3(off(rng), off(rng), off(rng));
        const Projection pr = solver.project(doc.points);
        ASSERT_TRUE(pr.ok()) << "round " << r << ": " << conflictMessage(pr);
    }
}

// Two bicubic patches that meet along x = 1 (A's u1, B's u0) with separate pool entries there, B
// wider (so alpha ≈ 1.5) and bent differently (so beta2 ≠ 0).
Document twoPatches() {
    Document doc;
    for (int side = 0; side < 2; ++side) {
        Patch p;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const double y = i / 3.0;
                const double x = side == 0 ? j / 3.0 : 1.0 + 1.5 * j / 3.0;
                const double z = side == 0 ? 0.4 * x * x + 0.1 * y * x : 0.4 + 0.9 * (x - 1.0) - 0.3 * (x - 1.0) * (x - 1.0) + 0.1 * y;
                p.idx[size_t(i * 4 + j)] = uint32_t(doc.points.size());
                doc.points.emplace_back(x, y, side == 1 && j == 0 ? 0.4 + 0.1 * y : z);
            }
        doc.patches.push_back(p);
    }
    // Make the shared edge coincide exactly (A's u1 column).
    for (int i = 0; i < 4; ++i) doc.points[doc.patches[1].idx[size_t(i * 4)]] = doc.points[doc.patches[0].idx[size_t(i * 4 + 3)]];
    return doc;
}

// Curvature of both sides at the seam agrees: normals, Gaussian and mean curvature, and the normal
// curvature in five directions, each side computed from its own derivatives (curvature_math.h's
// formulas, not the continuity report's).
void expectG2(const Document& doc, const Join& j) {
    for (int s = 0; s <= 10; ++s) {
        const double t = s / 10.0;
        const SurfaceJet a = jetOn(doc, j.patchA, j.edgeA, t), b = jetOn(doc, j.patchB, j.edgeB, t);
        ASSERT_LT(glm::length(a.p - b.p), 1e-12);
        EXPECT_LT(glm::length(glm::cross(a.n, b.n)), 1e-9) << "t " << t;
        const glm::dvec2 ka = gpu::gaussMeanCurvature<double>(a.du, a.dv, a.duu, a.duv, a.dvv, a.n);
        const glm::dvec2 kb = gpu::gaussMeanCurvature<double>(b.du, b.dv, b.duu, b.duv, b.dvv, b.n);
        const double scale = std::max({std::abs(ka.y), std::abs(kb.y), 1e-3});
        EXPECT_LE(std::abs(ka.x - kb.x), 1e-6 * scale * scale) << "Gaussian at t " << t;
        EXPECT_LE(std::abs(ka.y - kb.y), 1e-6 * scale) << "mean at t " << t;
        // Directions: the same 3D tangent on both sides, written in each side's (du, dv).
        for (double ang : {0.0, 0.6, 1.2, 1.9, 2.7}) {
            const Vec3 e1 = glm::normalize(a.dv), e2 = glm::normalize(glm::cross(a.n, e1));
            const Vec3 w = std::cos(ang) * e1 + std::sin(ang) * e2;
            auto kappa = [&](const SurfaceJet& q) {
                const double E = glm::dot(q.du, q.du), F = glm::dot(q.du, q.dv), G = glm::dot(q.dv, q.dv), det = E * G - F * F;
                const double wu = glm::dot(q.du, w), wv = glm::dot(q.dv, w);
                return gpu::normalCurvature<double>(q.du, q.dv, q.duu, q.duv, q.dvv, q.n, (G * wu - F * wv) / det, (E * wv - F * wu) / det);
            };
            EXPECT_LE(std::abs(kappa(a) - kappa(b)), 1e-6 * scale) << "direction " << ang << " at t " << t;
        }
    }
}

}  // namespace

TEST(CurvatureJoins, C2GridIsC2WhenBuilt) {
    const Document doc = makePatchGrid(4, 4, Continuity::C2);
    EXPECT_LE(maxConstraintResidual(doc), 1e-12);
    EXPECT_LE(worstC2Mismatch(doc), 1e-12);
    for (const JoinContinuity& c : continuityReport(doc)) {
        EXPECT_LE(c.c2Residual, 1e-12);
        EXPECT_LE(c.curvatureDeviationPct, 1e-6) << "join " << c.join;
        EXPECT_EQ(toleranceFailures(c, Continuity::C2, doc.tolerances), kWithinTolerance);
    }
}

TEST(CurvatureJoins, C2HeldAfterRandomDrags) {
    Document doc = makePatchGrid(4, 4, Continuity::C2);
    randomDrags(doc, 40, 0.3, 11);
    EXPECT_LE(maxConstraintResidual(doc), 1e-9 * modelSize(doc));
    EXPECT_LE(worstC2Mismatch(doc), 1e-9);
    // The surface did change: the drags were not all absorbed.
    EXPECT_GT(glm::length(doc.points[20] - makePatchGrid(4, 4, Continuity::C2).points[20]) +
                  glm::length(doc.points[90] - makePatchGrid(4, 4, Continuity::C2).points[90]),
              0.0);
}

TEST(CurvatureJoins, BreakingC2ShowsInTheReport) {
    Document doc = makePatchGrid(2, 2, Continuity::C2);
    // Lattice (1, 2): the third row of patch (0,0) from its u1 seam; only that join uses it.
    doc.points[size_t(1 * 7 + 1)].z += 0.05;
    const auto report = continuityReport(doc);
    size_t broken = 0;
    for (const JoinContinuity& c : report) {
        const bool mine = doc.joins[c.join].patchA == 0 && doc.joins[c.join].edgeA == Edge::U1;
        if (!mine) continue;
        ++broken;
        EXPECT_NEAR(c.c2Residual, 0.05, 1e-12);
        EXPECT_LE(c.c1Residual, 1e-12);
        EXPECT_GT(c.curvatureDeviationPct, 5.0);
        EXPECT_EQ(toleranceFailures(c, Continuity::C2, doc.tolerances), kCurvatureOut);
        // A C1 join with the same numbers is within its tolerances: curvature is not its business.
        EXPECT_EQ(toleranceFailures(c, Continuity::C1, doc.tolerances), kWithinTolerance);
    }
    EXPECT_EQ(broken, 1u);
}

TEST(CurvatureJoins, G2JoinKeepsMeasuredShapeParametersAndHoldsThroughDrags) {
    Document doc = twoPatches();
    const size_t j = joinEdges(doc, 0, Edge::U1, 1, Edge::U0, Continuity::G2);
    const Join join = doc.joins[j];
    EXPECT_EQ(join.continuity, Continuity::G2);
    EXPECT_GT(join.alpha, 1.4);  // B's tangent rows are about 1.5 times A's (their lengths' ratio)
    EXPECT_LT(join.alpha, 1.7);
    EXPECT_GT(std::abs(join.beta2), 1e-3);  // the two sides bend differently: a real β2
    EXPECT_LE(maxConstraintResidual(doc), 1e-12);
    expectG2(doc, join);
    randomDrags(doc, 30, 0.2, 5);
    EXPECT_EQ(doc.joins[j], join);  // the shape parameters stay as they were fixed
    EXPECT_LE(maxConstraintResidual(doc), 1e-9);
    expectG2(doc, doc.joins[j]);
    const auto report = continuityReport(doc, 32, {j});
    ASSERT_EQ(report.size(), 1u);
    EXPECT_LE(report[0].curvatureDeviationPct, 1e-4);
    EXPECT_LE(report[0].normalAngleDeg, 1e-6);
}

TEST(CurvatureJoins, MatchingG2MovesBOntoACurvature) {
    Document doc = twoPatches();
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k) doc.points[doc.patches[1].idx[size_t(i * 4 + k)]] += Vec3(0.3, 0.0, 0.2);  // a gap
    const std::vector<Vec3> before = doc.points;
    const size_t j = joinEdges(doc, 0, Edge::U1, 1, Edge::U0, Continuity::G2);
    // A stays where it was; B matched with A's curvature (β2 = 0).
    for (int s = 0; s < 16; ++s) EXPECT_EQ(doc.points[doc.patches[0].idx[size_t(s)]], before[size_t(s)]);
    EXPECT_EQ(doc.joins[j].beta2, 0.0);
    expectG2(doc, doc.joins[j]);
}

TEST(CurvatureJoins, OverConstrainedDragIsReportedWithItsJoins) {
    // Three patches in a row, C2: the middle one's four columns are all pinned by its neighbours.
    // Moving the first and last patches apart (both fixed) leaves no way to hold both joins.
    Document doc = makePatchGrid(1, 3, Continuity::C2);
    ASSERT_EQ(doc.joins.size(), 2u);
    std::vector<uint32_t> fixed;
    for (uint32_t p : {0u, 2u})
        for (uint32_t i : doc.patches[p].idx) fixed.push_back(i);
    const DragSolver solver(doc, fixed);
    for (uint32_t i : doc.patches[0].idx) doc.points[i].z += 0.5;
    const Projection pr = solver.project(doc.points);
    ASSERT_FALSE(pr.ok());
    EXPECT_EQ(pr.conflictingJoins, (std::vector<uint32_t>{0, 1}));
    EXPECT_GT(pr.residual, 1e-3);
    EXPECT_EQ(conflictMessage(pr).rfind("joins 0 and 1 cannot all hold", 0), 0u) << conflictMessage(pr);

    // A C1 row of three moved the same way is fine: the middle patch's inner columns are free.
    Document c1 = makePatchGrid(1, 3, Continuity::C1);
    const DragSolver s1(c1, fixed);
    for (uint32_t i : c1.patches[0].idx) c1.points[i].z += 0.5;
    EXPECT_TRUE(s1.project(c1.points).ok());
}

TEST(CurvatureJoins, SplitRescalesBeta) {
    Document doc = twoPatches();
    const size_t j = joinEdges(doc, 0, Edge::U1, 1, Edge::U0, Continuity::C2);
    ASSERT_EQ(doc.joins[j].continuity, Continuity::C2);
    EXPECT_LE(maxConstraintResidual(doc), 1e-12);
    splitPatch(doc, 1, true, 0.3);  // B's u0 half keeps the join, its tangent rows 0.3 as long
    const Join* kept = nullptr;
    for (const Join& k : doc.joins)
        if (k.patchA == 0 && k.edgeA == Edge::U1) kept = &k;
    ASSERT_NE(kept, nullptr);
    EXPECT_EQ(kept->continuity, Continuity::G2);
    EXPECT_NEAR(kept->alpha, 0.3, 1e-12);
    EXPECT_LE(maxConstraintResidual(doc), 1e-12);  // the rescaled β-constraint holds on the half
    expectG2(doc, *kept);
}

TEST(CurvatureJoins, FilesCarryC2G2AndTolerances) {
    Document doc = twoPatches();
    joinEdges(doc, 0, Edge::U1, 1, Edge::U0, Continuity::G2);
    doc.tolerances = ContinuityTolerances{0.01, 0.5, 2.0};
    const Document back = parseDocument(serializeDocument(doc), "g2.patchwork");
    EXPECT_EQ(back.joins, doc.joins);
    EXPECT_EQ(back.tolerances, doc.tolerances);
    // Defaults are not written (older readers and diffs see no change).
    EXPECT_EQ(serializeDocument(makePatchGrid(1, 2)).find("tolerances"), std::string::npos);
    std::string text = serializeDocument(doc);
    text.replace(text.find("\"beta2\""), 7, "\"beta2\":\"x\",\"_\"");
    try {
        parseDocument(text, "bad.patchwork");
        FAIL() << "accepted a string beta2";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("joins[0].beta2"), std::string::npos) << e.what();
    }
}

TEST(CurvatureJoins, JoinCommandTakesC2AndG2) {
    EditSession session;
    session.reset(twoPatches(), "");
    runEditScript(session, "join 0:u1 1:u0 G2");
    ASSERT_EQ(session.doc.joins.size(), 1u);
    EXPECT_EQ(session.doc.joins[0].continuity, Continuity::G2);
    runEditScript(session, "undo; join 0:u1 1:u0 C2");
    EXPECT_EQ(session.doc.joins[0].continuity, Continuity::C2);
    try {
        runEditScript(session, "undo; join 0:u1 1:u0 G3");
        FAIL() << "G3 accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("C0, C1, G1, C2 or G2"), std::string::npos) << e.what();
    }
}

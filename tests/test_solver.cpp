// Constraint solver: random drags keep every join constraint, fixed points stay put, tangent drags
// mirror the partner, boundary drags carry the tangents, corners of four patches, chains, rings,
// G1 ratios and unshared joins behave, and a satisfied model is left alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "core/base/embedded_data.hpp"
#include "core/construct/model_builders.hpp"
#include "core/io/bpt_format.hpp"
#include "core/model/document.hpp"
#include "core/model/join_detect.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"
#include "core/solve/ldlt_solve.hpp"

using namespace pw;

namespace {

// Pool index of lattice point (r, c) in makePatchGrid(rows, cols).
uint32_t lat(int cols, int r, int c) { return static_cast<uint32_t>(r * (3 * cols + 1) + c); }

// The (a1, s, b1, alpha) triples of every C1/G1 join, rebuilt here independently of the solver.
struct Triple {
    uint32_t a1, s, b1;
    double alpha;
};
std::vector<Triple> triples(const Document& doc) {
    std::vector<Triple> out;
    for (const Join& j : doc.joins) {
        if (j.continuity == Continuity::C0) continue;
        const Patch& A = doc.patches[j.patchA];
        const Patch& B = doc.patches[j.patchB];
        for (int k = 0; k < 4; ++k) {
            const int kb = j.reversed ? 3 - k : k;
            out.push_back({A.idx[edgeSlot(j.edgeA, k, 1)], A.idx[edgeSlot(j.edgeA, k, 0)], B.idx[edgeSlot(j.edgeB, kb, 1)], j.alpha});
        }
    }
    return out;
}

// Independent residual: max |b1 − (1+α)s + α·a1|.
double tripleResidual(const Document& doc) {
    double worst = 0;
    for (const Triple& t : triples(doc)) {
        const Vec3 r = doc.points[t.b1] - (1 + t.alpha) * doc.points[t.s] + t.alpha * doc.points[t.a1];
        worst = std::max(worst, glm::length(r));
    }
    return worst;
}

double maxMove(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, glm::length(a[i] - b[i]));
    return worst;
}

void expectVecNear(const Vec3& a, const Vec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// Drags `sel` by `delta` (in `steps` increments with one factorisation, like an interactive
// drag), then checks the constraints and that the selection sits exactly where it was put.
void dragAndCheck(Document& doc, const std::vector<uint32_t>& sel, const Vec3& delta, int steps = 3, SolverOptions opt = {}) {
    DragSolver solver(doc, sel, opt);
    std::vector<Vec3> start(sel.size());
    for (size_t i = 0; i < sel.size(); ++i) start[i] = doc.points[sel[i]];
    for (int s = 1; s <= steps; ++s) {
        std::vector<Vec3> target(sel.size());
        for (size_t i = 0; i < sel.size(); ++i) {
            target[i] = start[i] + (static_cast<double>(s) / steps) * delta;
            doc.points[sel[i]] = target[i];
        }
        solver.project(doc.points);
        for (size_t i = 0; i < sel.size(); ++i) ASSERT_EQ(doc.points[sel[i]], target[i]) << "fixed point " << sel[i];
        ASSERT_LE(maxConstraintResidual(doc), 1e-6 * modelSize(doc));
        ASSERT_LE(tripleResidual(doc), 1e-6 * modelSize(doc));
    }
}

// A ring of `around` x `rows` patches around the z axis (u wraps): tangent points on a circle,
// the boundary points between them at the midpoints, so the net is C1 by construction.
Document makeRing(int around, int rows) {
    Document doc;
    doc.name = "ring";
    const int cols = 3 * around;  // lattice columns; column `cols` is column 0 again
    const int lrows = 3 * rows + 1;
    auto idx = [&](int r, int c) { return static_cast<uint32_t>(r * cols + (c % cols)); };
    doc.points.resize(static_cast<size_t>(lrows) * cols);
    auto radiusAt = [](int r) { return 2.0 + 0.2 * std::sin(r * 0.4); };
    for (int r = 0; r < lrows; ++r) {
        // Rows between two patch rows get the mean radius of their neighbours (C1 across v seams).
        const bool seamRow = r % 3 == 0 && r > 0 && r + 1 < lrows;
        const double z = r / 3.0, radius = seamRow ? 0.5 * (radiusAt(r - 1) + radiusAt(r + 1)) : radiusAt(r);
        for (int c = 0; c < cols; ++c) {
            const double th = 2 * std::numbers::pi * c / cols;
            doc.points[idx(r, c)] = Vec3(radius * std::cos(th), radius * std::sin(th), z);
        }
        for (int m = 0; m < around; ++m)  // boundary columns: midpoint of the neighbours
            doc.points[idx(r, 3 * m)] = 0.5 * (doc.points[idx(r, 3 * m - 1 + cols)] + doc.points[idx(r, 3 * m + 1)]);
    }
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < around; ++j) {
            Patch p;
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b) p.idx[a * 4 + b] = idx(3 * i + a, 3 * j + b);
            p.name = "ring_" + std::to_string(i) + "_" + std::to_string(j);
            doc.patches.push_back(p);
        }
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < around; ++j) {
            const auto p = static_cast<uint32_t>(i * around + j);
            doc.joins.push_back(
                Join{p, Edge::U1, static_cast<uint32_t>(i * around + (j + 1) % around), Edge::U0, false, Continuity::C1, 1.0});
            if (i + 1 < rows)
                doc.joins.push_back(Join{p, Edge::V1, static_cast<uint32_t>(p + around), Edge::V0, false, Continuity::C1, 1.0});
        }
    return doc;
}

// Random selections that can be satisfied: a single point, a few scattered points (never all
// three points of one constraint), or a boundary point with its two tangents moved rigidly.
std::vector<uint32_t> randomSelection(const Document& doc, std::mt19937& rng) {
    const auto tri = triples(doc);
    std::uniform_int_distribution<uint32_t> pick(0, static_cast<uint32_t>(doc.points.size() - 1));
    const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
    if (kind == 0) return {pick(rng)};
    if (kind == 3 && !tri.empty()) {
        const Triple& t = tri[std::uniform_int_distribution<size_t>(0, tri.size() - 1)(rng)];
        if (t.alpha == 1.0) return {t.a1, t.s, t.b1};
    }
    for (;;) {
        std::set<uint32_t> s;
        const int n = std::uniform_int_distribution<int>(2, 4)(rng);
        while (static_cast<int>(s.size()) < n) s.insert(pick(rng));
        bool ok = true;
        for (const Triple& t : tri) ok = ok && !(s.count(t.a1) && s.count(t.s) && s.count(t.b1));
        if (ok) return {s.begin(), s.end()};
    }
}

Vec3 randomDelta(std::mt19937& rng, double scale) {
    std::uniform_real_distribution<double> d(-scale, scale);
    return Vec3(d(rng), d(rng), d(rng));
}

}  // namespace

TEST(ModelBuilders, GridLayoutAndExactC1) {
    const Document doc = makePatchGrid(4, 4);
    ASSERT_EQ(doc.patches.size(), 16u);
    ASSERT_EQ(doc.points.size(), 13u * 13u);
    ASSERT_EQ(doc.joins.size(), 24u);  // 2 · 4 · 3 interior edges
    for (const Join& j : doc.joins) {
        EXPECT_EQ(j.continuity, Continuity::C1);
        EXPECT_EQ(j.alpha, 1.0);
        EXPECT_FALSE(j.reversed);
        // The joined edges share their pool entries.
        for (int k = 0; k < 4; ++k)
            EXPECT_EQ(doc.patches[j.patchA].idx[edgeSlot(j.edgeA, k)], doc.patches[j.patchB].idx[edgeSlot(j.edgeB, k)]);
    }
    // Patch i*4+j: i = v row, j = u column; corners at (j, i) .. (j+1, i+1).
    const Patch& p = doc.patches[1 * 4 + 2];
    EXPECT_EQ(doc.points[p.idx[0]].x, 2.0);
    EXPECT_EQ(doc.points[p.idx[0]].y, 1.0);
    EXPECT_EQ(doc.points[p.idx[15]].x, 3.0);
    EXPECT_EQ(doc.points[p.idx[15]].y, 2.0);
    EXPECT_FALSE(p.name.empty());
    EXPECT_LE(maxConstraintResidual(doc), 1e-14);
    EXPECT_LE(tripleResidual(doc), 1e-14);
    // The wave is really there (not flat).
    double zmax = 0;
    for (const Vec3& q : doc.points) zmax = std::max(zmax, std::abs(q.z));
    EXPECT_GT(zmax, 0.2);

    const Document c0 = makePatchGrid(2, 3, Continuity::C0);
    EXPECT_EQ(c0.joins.size(), 2u * 2 + 1u * 3);
    for (const Join& j : c0.joins) EXPECT_EQ(j.continuity, Continuity::C0);
    EXPECT_EQ(makePatchGrid(1, 1).joins.size(), 0u);
}

TEST(DragSolver, ConstraintCountDeduplicatesCornerRows) {
    const Document doc = makePatchGrid(4, 4);
    // 24 joins × 4 rows, minus one duplicate per direction at each of the 3×3 interior corners.
    EXPECT_EQ(DragSolver(doc, {}).constraintCount(), 96u - 18u);
    // A C0 grid shares every boundary point: nothing to constrain.
    EXPECT_EQ(DragSolver(makePatchGrid(4, 4, Continuity::C0), {}).constraintCount(), 0u);
    // Constraints on fixed points only are skipped: fix all three points of one row.
    const uint32_t a1 = lat(4, 1, 2), s = lat(4, 1, 3), b1 = lat(4, 1, 4);
    EXPECT_EQ(DragSolver(doc, {a1, s, b1}).constraintCount(), 77u);
}

TEST(DragSolver, SatisfiedModelDoesNotMove) {
    Document doc = makePatchGrid(4, 4);
    const std::vector<Vec3> before = doc.points;
    projectConstraints(doc, {});
    EXPECT_EQ(doc.points, before);
    DragSolver solver(doc, {lat(4, 4, 4), lat(4, 5, 6)});
    solver.project(doc.points);
    solver.project(doc.points);
    EXPECT_EQ(doc.points, before);
}

class RandomDrags : public ::testing::TestWithParam<int> {};

TEST_P(RandomDrags, KeepConstraintsAndFixedPoints) {
    Document doc = makePatchGrid(4, 4);
    std::mt19937 rng(12345);
    const double size0 = modelSize(doc);
    SolverOptions opt;
    opt.denseComponentLimit = GetParam();
    for (int it = 0; it < 250; ++it) {
        const auto sel = randomSelection(doc, rng);
        dragAndCheck(doc, sel, randomDelta(rng, 0.05 * size0), 3, opt);
        if (HasFatalFailure()) {
            ADD_FAILURE() << "iteration " << it;
            return;
        }
    }
    // The projections are least-change: the model is still a sane surface (joins stay C0/C1).
    for (const JoinContinuity& jc : continuityReport(doc, 8)) {
        EXPECT_LE(jc.c0Gap, 1e-9);
        EXPECT_LE(jc.c1Residual, 1e-6 * modelSize(doc));
    }
}

// Dense factorisation of the small independent groups (default) and sparse everywhere.
INSTANTIATE_TEST_SUITE_P(DragSolver, RandomDrags, ::testing::Values(48, 0));

TEST(DragSolver, TangentDragMirrorsPartner) {
    // Lattice row 1 is not near any v seam: (1,2) and (1,4) are the only tangents of (1,3).
    Document doc = makePatchGrid(4, 4);
    const uint32_t a1 = lat(4, 1, 2), s = lat(4, 1, 3), b1 = lat(4, 1, 4);
    const std::vector<Vec3> before = doc.points;
    const Vec3 delta(0.1, -0.05, 0.2);
    doc.points[a1] += delta;
    projectConstraints(doc, {a1});
    // Weighted least change: Δb1 = −δ·(1/wt) / (1/wt + 4/wb), Δs = −2/wb · λ.
    const double wt = SolverOptions{}.tangentWeight, wb = SolverOptions{}.boundaryWeight;
    const double lambda = -1.0 / (1 / wt + 4 / wb);
    expectVecNear(doc.points[b1] - before[b1], lambda / wt * delta, 1e-12);
    expectVecNear(doc.points[s] - before[s], -2 * lambda / wb * delta, 1e-12);
    EXPECT_LE(maxConstraintResidual(doc), 1e-12);
    for (size_t i = 0; i < doc.points.size(); ++i) {
        if (i != a1 && i != s && i != b1) {
            EXPECT_LE(glm::length(doc.points[i] - before[i]), 1e-12) << i;
        }
    }

    // With a very heavy boundary the partner mirrors exactly: Δb1 = −δ.
    doc = makePatchGrid(4, 4);
    doc.points[a1] += delta;
    SolverOptions heavy;
    heavy.boundaryWeight = 1e9;
    projectConstraints(doc, {a1}, heavy);
    expectVecNear(doc.points[b1] - before[b1], -delta, 1e-7);
    expectVecNear(doc.points[s], before[s], 1e-7);
}

TEST(DragSolver, BoundaryDragCarriesBothTangents) {
    Document doc = makePatchGrid(4, 4);
    // A boundary point in the middle of a seam and one on a v seam (row 6, column 1).
    for (auto [r, c, dr, dc] : {std::array<int, 4>{1, 3, 0, 1}, std::array<int, 4>{6, 1, 1, 0}}) {
        const uint32_t s = lat(4, r, c), a1 = lat(4, r - dr, c - dc), b1 = lat(4, r + dr, c + dc);
        const std::vector<Vec3> before = doc.points;
        const Vec3 delta(-0.07, 0.11, 0.3);
        dragAndCheck(doc, {s}, delta, 1);
        expectVecNear(doc.points[a1] - before[a1], delta, 1e-12);
        expectVecNear(doc.points[b1] - before[b1], delta, 1e-12);
        int moved = 0;
        for (size_t i = 0; i < doc.points.size(); ++i) moved += glm::length(doc.points[i] - before[i]) > 1e-12 ? 1 : 0;
        EXPECT_EQ(moved, 3);
    }
}

TEST(DragSolver, FourPatchCorner) {
    // The interior corner of a 2x2 grid is lattice (3,3); twists at (2,2) (2,4) (4,2) (4,4).
    const Document base = makePatchGrid(2, 2);
    const uint32_t corner = lat(2, 3, 3);
    const Vec3 delta(0.05, 0.08, -0.25);

    // Dragging the corner carries the whole 3x3 block around it rigidly.
    Document doc = base;
    dragAndCheck(doc, {corner}, delta, 2);
    for (int r = 2; r <= 4; ++r)
        for (int c = 2; c <= 4; ++c) expectVecNear(doc.points[lat(2, r, c)] - base.points[lat(2, r, c)], delta, 1e-9);
    EXPECT_LE(maxMove(doc.points, base.points), glm::length(delta) + 1e-9);

    // Dragging a twist point mirrors it across both seams and diagonally.
    doc = base;
    const uint32_t twist = lat(2, 4, 4);
    dragAndCheck(doc, {twist}, delta, 2);
    const Vec3 dDiag = doc.points[lat(2, 2, 2)] - base.points[lat(2, 2, 2)];
    const Vec3 dU = doc.points[lat(2, 4, 2)] - base.points[lat(2, 4, 2)];
    const Vec3 dV = doc.points[lat(2, 2, 4)] - base.points[lat(2, 2, 4)];
    const double d2 = glm::dot(delta, delta);
    EXPECT_GT(glm::dot(dDiag, delta), 0.8 * d2);
    EXPECT_LT(glm::dot(dU, delta), -0.8 * d2);
    EXPECT_LT(glm::dot(dV, delta), -0.8 * d2);
    expectVecNear(dU, dV, 1e-12);  // symmetric problem, symmetric answer
    EXPECT_LE(glm::length(doc.points[corner] - base.points[corner]), 0.05 * glm::length(delta));
    // All four seams around the corner stay smooth.
    for (const JoinContinuity& jc : continuityReport(doc, 16)) {
        EXPECT_LE(jc.c1Residual, 1e-9);
        EXPECT_LE(jc.normalAngleDeg, 1e-5);
    }

    // Dragging the corner and a twist together, several times, stays consistent.
    doc = base;
    std::mt19937 rng(7);
    for (int it = 0; it < 20; ++it) dragAndCheck(doc, {corner, lat(2, 2, 4)}, randomDelta(rng, 0.2));
}

TEST(DragSolver, ChainAndRing) {
    // A chain of five patches.
    Document chain = makePatchGrid(1, 5);
    std::mt19937 rng(99);
    for (int it = 0; it < 60; ++it) dragAndCheck(chain, randomSelection(chain, rng), randomDelta(rng, 0.3), 2);

    // A ring of 6 x 2 patches joined cyclically around the z axis.
    Document ring = makeRing(6, 2);
    EXPECT_EQ(ring.joins.size(), 6u * 2 + 6u);
    EXPECT_LE(maxConstraintResidual(ring), 1e-14);
    EXPECT_LE(tripleResidual(ring), 1e-14);
    // The seam between the last patch and the first is constrained like any other.
    const uint32_t a1 = ring.patches[5].idx[edgeSlot(Edge::U1, 1, 1)];
    const uint32_t s = ring.patches[5].idx[edgeSlot(Edge::U1, 1, 0)];
    const uint32_t b1 = ring.patches[0].idx[edgeSlot(Edge::U0, 1, 1)];
    EXPECT_EQ(s, ring.patches[0].idx[edgeSlot(Edge::U0, 1, 0)]);
    const Vec3 sBefore = ring.points[s], aBefore = ring.points[a1], bBefore = ring.points[b1];
    dragAndCheck(ring, {s}, Vec3(0.3, 0.1, 0.2), 1);
    expectVecNear(ring.points[a1] - aBefore, ring.points[s] - sBefore, 1e-12);
    expectVecNear(ring.points[b1] - bBefore, ring.points[s] - sBefore, 1e-12);
    for (int it = 0; it < 60; ++it) dragAndCheck(ring, randomSelection(ring, rng), randomDelta(rng, 0.3), 2);
}

TEST(DragSolver, G1KeepsItsRatio) {
    Document doc = makePatchGrid(1, 2, Continuity::G1);
    ASSERT_EQ(doc.joins.size(), 1u);
    doc.joins[0].alpha = 2.0;
    EXPECT_GT(maxConstraintResidual(doc), 0.01);  // the C1 grid does not satisfy α = 2
    projectConstraints(doc, {});
    EXPECT_LE(maxConstraintResidual(doc), 1e-12);

    auto checkRatio = [&] {
        for (int k = 0; k < 4; ++k) {
            const Vec3 a1 = doc.points[lat(2, k, 2)], s = doc.points[lat(2, k, 3)], b1 = doc.points[lat(2, k, 4)];
            expectVecNear(b1 - s, 2.0 * (s - a1), 1e-10);
        }
    };
    checkRatio();

    // Tangent drag: Δb1 = −α·δ·(1/wt) / (1/wt + (1+α)²/wb).
    const uint32_t a1 = lat(2, 1, 2), s = lat(2, 1, 3), b1 = lat(2, 1, 4);
    std::vector<Vec3> before = doc.points;
    const Vec3 delta(0.02, 0.1, -0.1);
    dragAndCheck(doc, {a1}, delta, 1);
    checkRatio();
    const double alpha = 2, wt = SolverOptions{}.tangentWeight, wb = SolverOptions{}.boundaryWeight;
    expectVecNear(doc.points[b1] - before[b1], -alpha * delta / wt / (1 / wt + (1 + alpha) * (1 + alpha) / wb), 1e-12);

    // Boundary drag: Δb1 + αΔa1 = (1+α)δ with least change: Δa1 = α·t, Δb1 = t, t = (1+α)δ/(1+α²).
    before = doc.points;
    dragAndCheck(doc, {s}, delta, 1);
    checkRatio();
    expectVecNear(doc.points[a1] - before[a1], alpha * (1 + alpha) / (1 + alpha * alpha) * delta, 1e-12);
    expectVecNear(doc.points[b1] - before[b1], (1 + alpha) / (1 + alpha * alpha) * delta, 1e-12);

    std::mt19937 rng(3);
    for (int it = 0; it < 40; ++it) {
        dragAndCheck(doc, randomSelection(doc, rng), randomDelta(rng, 0.2), 2);
        checkRatio();
    }
}

TEST(DragSolver, UnsharedJoinAddsC0) {
    // Two patches whose common edge is stored twice in the pool: the join ties the copies.
    Document doc = makePatchGrid(1, 2);
    Patch& b = doc.patches[1];
    for (int k = 0; k < 4; ++k) {
        const int slot = edgeSlot(Edge::U0, k);
        doc.points.push_back(doc.points[b.idx[slot]]);
        b.idx[slot] = static_cast<uint32_t>(doc.points.size() - 1);
    }
    EXPECT_EQ(DragSolver(doc, {}).constraintCount(), 8u);
    EXPECT_LE(maxConstraintResidual(doc), 1e-14);
    const uint32_t sA = doc.patches[0].idx[edgeSlot(Edge::U1, 2)], sB = b.idx[edgeSlot(Edge::U0, 2)];
    dragAndCheck(doc, {sA}, Vec3(0.1, 0.2, 0.3), 2);
    EXPECT_LE(glm::length(doc.points[sA] - doc.points[sB]), 1e-12);
    dragAndCheck(doc, {sB}, Vec3(-0.1, 0.0, 0.3), 2);
    EXPECT_LE(glm::length(doc.points[sA] - doc.points[sB]), 1e-12);
    // A mismatch is measured by maxConstraintResidual.
    doc.points[sB].z += 0.5;
    EXPECT_NEAR(maxConstraintResidual(doc), 0.5, 1e-12);
}

TEST(DragSolver, CollapsedEdgeIsSkipped) {
    // Collapse the seam of a 1x2 grid to one pool entry: no C1 rows, the C0 rows are trivial.
    Document doc = makePatchGrid(1, 2);
    for (Patch& p : doc.patches)
        for (int k = 0; k < 4; ++k) {
            int slot = edgeSlot(&p == &doc.patches[0] ? Edge::U1 : Edge::U0, k);
            p.idx[slot] = lat(2, 0, 3);
        }
    EXPECT_EQ(DragSolver(doc, {}).constraintCount(), 0u);
    EXPECT_EQ(maxConstraintResidual(doc), 0.0);
}

TEST(DragSolver, MovableAndLargeGrid) {
    Document doc = makePatchGrid(12, 12);
    const uint32_t s = lat(12, 18, 20), t = lat(12, 19, 22);
    DragSolver a(doc, {s, t});
    DragSolver solver = std::move(a);
    std::mt19937 rng(5);
    for (int it = 0; it < 30; ++it) {
        doc.points[s] += randomDelta(rng, 0.1);
        doc.points[t] += randomDelta(rng, 0.1);
        const Vec3 ps = doc.points[s], pt = doc.points[t];
        solver.project(doc.points);
        ASSERT_EQ(doc.points[s], ps);
        ASSERT_EQ(doc.points[t], pt);
        ASSERT_LE(maxConstraintResidual(doc), 1e-9 * modelSize(doc));
    }
}

class LeastChange : public ::testing::TestWithParam<int> {};

TEST_P(LeastChange, ProjectionIsTheWeightedLeastChange) {
    // Optimality (KKT): the weighted change W·Δ of the free points must lie in the row space of
    // the constraints restricted to the free points. Checked by Gram-Schmidt, independently of the
    // solver's component splitting and regularisation.
    Document doc = makePatchGrid(3, 3);
    SolverOptions opt;
    opt.denseComponentLimit = GetParam();
    std::mt19937 rng(2024);
    const auto tri = triples(doc);
    const size_t n = doc.points.size();
    for (int it = 0; it < 40; ++it) {
        const auto sel = randomSelection(doc, rng);
        std::vector<char> fixed(n, 0), boundary(n, 0);
        for (uint32_t s : sel) fixed[s] = 1;
        for (const Triple& t : tri) boundary[t.s] = 1;

        const std::vector<Vec3> before = doc.points;
        const Vec3 delta = randomDelta(rng, 0.3);
        for (uint32_t s : sel) doc.points[s] += delta;
        projectConstraints(doc, sel, opt);
        ASSERT_LE(maxConstraintResidual(doc), 1e-9 * modelSize(doc));

        // Orthonormal basis of the constraint rows over the free points.
        std::vector<std::vector<double>> basis;
        for (const Triple& t : tri) {
            std::vector<double> row(n, 0.0);
            row[t.b1] += 1.0;
            row[t.s] -= 1.0 + t.alpha;
            row[t.a1] += t.alpha;
            for (size_t i = 0; i < n; ++i)
                if (fixed[i]) row[i] = 0;
            for (int pass = 0; pass < 2; ++pass)
                for (const auto& b : basis) {
                    double dot = 0;
                    for (size_t i = 0; i < n; ++i) dot += row[i] * b[i];
                    for (size_t i = 0; i < n; ++i) row[i] -= dot * b[i];
                }
            double norm = 0;
            for (double v : row) norm += v * v;
            if (norm < 1e-20) continue;  // dependent row
            for (double& v : row) v /= std::sqrt(norm);
            basis.push_back(std::move(row));
        }
        double changeNorm = 0, outside = 0;
        for (int c = 0; c < 3; ++c) {
            std::vector<double> g(n, 0.0);
            for (size_t i = 0; i < n; ++i)
                if (!fixed[i]) g[i] = (boundary[i] ? opt.boundaryWeight : opt.tangentWeight) * (doc.points[i][c] - before[i][c]);
            for (double v : g) changeNorm = std::max(changeNorm, std::abs(v));
            for (const auto& b : basis) {
                double dot = 0;
                for (size_t i = 0; i < n; ++i) dot += g[i] * b[i];
                for (size_t i = 0; i < n; ++i) g[i] -= dot * b[i];
            }
            for (double v : g) outside = std::max(outside, std::abs(v));
        }
        ASSERT_LE(outside, 1e-8 * std::max(changeNorm, 1.0)) << "iteration " << it;
    }
}

INSTANTIATE_TEST_SUITE_P(DragSolver, LeastChange, ::testing::Values(48, 0));

TEST(DragSolver, TeapotWithCollapsedEdges) {
    // The teapot has collapsed edges (lid top, bottom centre) and G1 joins: random drags keep
    // every constraint and every C1/G1 seam smooth, and the normals stay finite.
    Document doc = parseBpt(embedded::teapotBpt, "teapot");
    if (doc.joins.empty()) {
        mergeCoincidentPoints(doc);
        doc.joins = detectJoins(doc);
    }
    ASSERT_GT(doc.joins.size(), 40u);
    projectConstraints(doc, {});
    ASSERT_LE(maxConstraintResidual(doc), 1e-9 * modelSize(doc));
    std::mt19937 rng(11);
    for (int it = 0; it < 100; ++it) {
        const uint32_t p = std::uniform_int_distribution<uint32_t>(0, static_cast<uint32_t>(doc.points.size() - 1))(rng);
        dragAndCheck(doc, {p}, randomDelta(rng, 0.02 * modelSize(doc)), 2);
        if (HasFatalFailure()) return;
    }
    for (const JoinContinuity& jc : continuityReport(doc, 16)) {
        EXPECT_LE(jc.c0Gap, 1e-9);
        EXPECT_TRUE(std::isfinite(jc.normalAngleDeg));
        if (doc.joins[jc.join].continuity != Continuity::C0) {
            EXPECT_LE(jc.normalAngleDeg, 1e-4) << "join " << jc.join;
        }
    }
}

// The drag's multi-column solve (core/solve/ldlt_solve.hpp) gives Eigen's own solve, for the three
// columns of a drag and any other width, on a sparse SPD matrix with fill (a banded Laplacian plus
// random couplings, permuted by AMD).
TEST(Solver, LdltSolveOfSeveralColumnsIsEigens) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int n = 300;
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i) {
        t.emplace_back(i, i, 8.0);
        if (i + 1 < n) t.emplace_back(i, i + 1, -1.0), t.emplace_back(i + 1, i, -1.0);
        const int j = int(rng() % n);
        if (j != i) t.emplace_back(i, j, 0.5), t.emplace_back(j, i, 0.5);
    }
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    const solver_detail::SparseLdlt f(A);
    ASSERT_EQ(f.info(), Eigen::Success);
    for (int k : {3, 1, 2}) {
        Eigen::MatrixXd b(n, k);
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < k; ++c) b(i, c) = u(rng);
        const Eigen::MatrixXd mine = solver_detail::solveLdltColumns(f, b), eigen = f.solve(b);
        EXPECT_LT((mine - eigen).cwiseAbs().maxCoeff(), 1e-12) << k << " columns";
        EXPECT_LT((A * mine - b).cwiseAbs().maxCoeff(), 1e-10) << k << " columns";
    }
}

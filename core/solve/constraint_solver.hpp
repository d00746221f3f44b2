// Projection of edited control points onto the join constraints (DESIGN §1).
//
// Every C1/G1 join gives, for each of its four edge points k, the linear constraint
//   b1k - (1 + alpha)·s_k + alpha·a1k = 0      (s_k = the shared boundary point)
// identical for x, y and z. After an edit the solver finds the least *weighted* change to the free
// points that satisfies all constraints, keeping the dragged points exactly where the user put
// them. Boundary points weigh more than tangent points, so dragging a tangent point mirrors its
// partner across the seam, and dragging a boundary point carries its two tangent neighbours.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace solve {

struct SolverOptions {
    double boundaryWeight = 1e4;  // weight of points on a joined boundary (tangent drags mirror to 0.9996)
    double tangentWeight = 1.0;   // weight of every other point
    // Independent groups of constraints are factorised separately; groups of at most this many
    // constraints use a dense LDLT, larger ones a sparse one (0: sparse everywhere).
    int denseComponentLimit = 48;
    // Local support: only points of patches within this many rings (patches sharing a point) of
    // a patch holding a fixed point move; everything farther stays. A C2 grid's β-constraints
    // couple every row of every patch, so a global least change would reshape the whole model,
    // and solve 16 000 rows per mouse event on a 32×32 grid; three rings hold any C2/G2 edit of a
    // regular grid (a cubic B-spline's support is four patches). When the region cannot hold the
    // joins, project() widens it to the whole model before it reports a conflict. 0: global.
    int localRings = 3;
    // Points that seed the local region like fixed ones without being fixed: what a soft selection
    // moves partly (the joins around them must be held too).
    std::vector<uint32_t> regionPoints;
};

// What one projection reached: the largest remaining constraint residual and, when the constraints
// cannot all hold with the fixed points where they are (an over-constrained set: G2 corners whose
// shape parameters disagree, a join against rows another join pins), the joins whose rows are left
// violated by more than 1e-9 × model size. Nothing is silently broken: callers report these.
struct Projection {
    double residual = 0;
    std::vector<uint32_t> conflictingJoins;  // sorted, unique; kNetSeamJoin for a Bézier net's C1 seam
    bool ok() const { return conflictingJoins.empty(); }
};
inline constexpr uint32_t kNetSeamJoin = 0xffffffffu;

// Factorised once for a set of fixed (dragged) points; each project() call is then a cheap solve.
// Create it when a drag starts; rebuild it when the joins or the fixed set change.
class DragSolver {
public:
    DragSolver(const Document& doc, std::vector<uint32_t> fixedPoints, SolverOptions options = {});
    ~DragSolver();
    DragSolver(DragSolver&&) noexcept;
    DragSolver& operator=(DragSolver&&) noexcept;

    // Moves the free points of `points` (the whole pool, with the fixed points already at their
    // new positions) the least weighted amount so that every constraint holds.
    Projection project(std::vector<Vec3>& points) const;

    size_t constraintCount() const;  // rows of the (local) solve

private:
    struct Impl;
    struct Setup;
    static void build(Impl& im, const Setup& setup, const std::vector<char>& fixed);
    static Projection projectWith(const Impl& im, std::vector<Vec3>& points);
    std::unique_ptr<Impl> impl_;            // the local (or global) solve
    std::unique_ptr<Setup> setup_;          // local solvers: what widening needs
    mutable std::unique_ptr<Impl> global_;  // built when the local region cannot hold the joins
};

// One-shot projection (builds and factorises a DragSolver).
Projection projectConstraints(Document& doc, const std::vector<uint32_t>& fixedPoints, SolverOptions options = {});

// "joins 3 and 7 cannot all hold (over-constrained; the worst condition is off by 0.0021)" for a
// failed projection (at most 8 joins named); "" when it succeeded.
std::string conflictMessage(const Projection& p);

// Largest residual of any join row (C1/G1 tangent rows, C2/G2 curvature rows), and the largest distance between
// points that a join says coincide (0 when the pool shares them). Compare with 1e-6 × modelSize.
double maxConstraintResidual(const Document& doc);
// The same measure for each join (index = join), and for the C1 seams of Bézier nets together.
struct JoinResiduals {
    std::vector<double> perJoin;
    double netSeams = 0;
};
JoinResiduals joinResiduals(const Document& doc);

}  // namespace solve
}  // namespace pw

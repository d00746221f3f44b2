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
#include <vector>

#include "core/document.hpp"

namespace pw {

struct SolverOptions {
    double boundaryWeight = 1e4;  // weight of points on a joined boundary (tangent drags mirror to 0.9996)
    double tangentWeight = 1.0;     // weight of every other point
    // Independent groups of constraints are factorised separately; groups of at most this many
    // constraints use a dense LDLT, larger ones a sparse one (0: sparse everywhere).
    int denseComponentLimit = 48;
};

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
    void project(std::vector<Vec3>& points) const;

    size_t constraintCount() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// One-shot projection (builds and factorises a DragSolver).
void projectConstraints(Document& doc, const std::vector<uint32_t>& fixedPoints, SolverOptions options = {});

// Largest |b1k - (1+alpha)·s_k + alpha·a1k| over all C1/G1 joins, and the largest distance between
// points that a join says coincide (0 when the pool shares them). Compare with 1e-6 × modelSize.
double maxConstraintResidual(const Document& doc);

}  // namespace pw

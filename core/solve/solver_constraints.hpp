// Private to the solver and the continuity report: the linear join constraints of a document as
// sparse rows over pool indices (DESIGN §1). Not part of the public interface.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/model/document.hpp"
#include "core/solve/constraint_solver.hpp"

namespace pw {
inline namespace solve {
namespace solver_detail {

// One scalar constraint Σ coef·p[idx] = 0, applied identically to x, y and z.
struct ConstraintRow {
    std::vector<std::pair<uint32_t, double>> terms;  // sorted by pool index, no zero coefficients
    uint32_t join = 0;                               // the join it comes from (kNetSeamJoin: a net seam)
};

// A row from terms: repeated indices merged, zero coefficients dropped, sorted by index.
ConstraintRow makeRow(std::vector<std::pair<uint32_t, double>> terms, uint32_t join);

// The pool indices along one join, point k of A's edge against the matching point of B's edge.
struct JoinPoints {
    uint32_t a0[4], a1[4], a2[4], b0[4], b1[4], b2[4];  // rows 0 (edge), 1 and 2 inward
};

// False when the join names a patch that does not exist.
bool joinPoints(const Document& doc, const Join& join, JoinPoints& out);
// True when every index of `jp` lies inside a pool of n points.
bool joinPointsInPool(const JoinPoints& jp, size_t n);

// The tangent rows of one C1/G1/C2/G2 join: b1k − (1+α)·a0k + α·a1k = 0 for each edge point k, or
// for a join that leans along its seam the five rows of core/solve/sheared_joins.hpp.
void appendTangentRows(const Join& join, const JoinPoints& jp, uint32_t ji, std::vector<ConstraintRow>& rows);

// Every constraint the joins impose: for each edge point k, a0k − b0k = 0 when the two sides do
// not share the pool entry, for C1/G1/C2/G2 b1k − (1+α)·a0k + α·a1k = 0, and for C2/G2
// b2k − 2·b1k + b0k − α²·(a2k − 2·a1k + a0k) − (β2/2)·(a0k − a1k) = 0. Constraints of a collapsed
// edge (all four edge points one pool entry), and rows whose tangent point is the boundary point
// itself on only one side, are left out: there the control-point condition says nothing useful.
std::vector<ConstraintRow> buildConstraintRows(const Document& doc);

// Points that lie on a joined edge (boundary points), as a flag per pool entry.
std::vector<char> joinedBoundaryPoints(const Document& doc);

}  // namespace solver_detail
}  // namespace solve
}  // namespace pw

// Joins with a Bézier triangle on one side or both (issue 40): the rows that hold them, the fit of
// their shape parameters and their measured seam. Along a triangle's edge the cross-boundary
// derivative towards the opposite corner is quadratic,
//   D(t) = Σ_m B²_m(t)·(f_m − (e_m + e_(m+1))/2),
// with e the edge's four points and f the three points one row in (b111 is the middle one), where a
// patch's is the cubic Σ B³_k(t)·(row1_k − row0_k). A G1 join holds
//   D_B(t) + α(t)·D_A(t) = β(t)·c'(t),   β(t) = s0 (1−t)² + 2 s1 t(1−t) + s2 t²,
// both D pointing into their own side, c' A's edge tangent and α(t) linear from Join::alpha to
// Join::alphaEnd (core/solve/sheared_joins.hpp, with Join::shear as β); its Bernstein coefficients, of the identity's degree, are linear
// rows in the points once α and β are fixed. A C0 join only keeps the edges' points together.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/model/document.hpp"
#include "core/solve/sheared_joins.hpp"
#include "core/solve/solver_constraints.hpp"

namespace pw {
inline namespace solve {

// A combination Σ coef·p[idx] of pool points.
using PointCombination = std::vector<std::pair<uint32_t, double>>;

// The point Σ coef·p[idx].
Vec3 valueOf(const Document& doc, const PointCombination& c);

// One side of a join as polynomials along the seam, t running from A's edge point 0 to point 3.
struct SeamSide {
    std::array<uint32_t, 4> edge{};       // pool indices along the seam
    std::vector<PointCombination> cross;  // Bernstein coefficients of the inward cross derivative (4: patch, 3: triangle)
};

// Side A (`sideB` false) or side B of a join, B's read in A's direction when `reversed`; nullopt
// when the item does not exist or indexes outside the pool.
std::optional<SeamSide> seamSide(const Document& doc, const Join& join, bool sideB);

// The rows of a join with a triangle side: edge points equal where the sides do not share them,
// and for G1 the identity above (its degree: the larger side's, one more for a varying α, 4 with β).
void appendTriangleJoinRows(const Document& doc, const Join& join, uint32_t ji, std::vector<solver_detail::ConstraintRow>& rows);

// α(t) and β(t) measured from the current shape: at each end of the seam the identity involves
// only that end's values (fixed by the sides' boundaries), so α and β there are solved exactly in
// the tangent plane, α running linearly between them (Join::alphaEnd); β's middle coefficient by
// least squares over the inner rows. Exact where the seam is G1 already. nullopt when the seam is
// degenerate (a collapsed edge, or a cross derivative along the edge).
std::optional<ShearFit> fitTriangleSeam(const Document& doc, const Join& join);

// The seam measured at parameter t: both sides' points and the tangent planes' normals, each the
// edge tangent crossed with the side's cross derivative (pointing out of A and into B), so the angle
// between them is the G1 defect whatever way either side is parametrised. `planes` is false where
// a tangent plane is undefined (a collapsed edge or corner).
struct SeamPoint {
    Vec3 a{0.0}, b{0.0};
    Vec3 na{0.0}, nb{0.0};
    bool planes = false;
};
SeamPoint measureTriangleSeam(const Document& doc, const Join& join, double t);

}  // namespace solve
}  // namespace pw

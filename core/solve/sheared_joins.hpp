// G1 joins that lean along their seam (Join::shear): the rows that hold them and the fit that
// measures them (issue 40). Where 3, 5 or 6 patches meet at a corner, the cross tangents of the
// patches around it cannot all be collinear pairs (the rows b1k − (1+α)a0k + α a1k = 0 would make
// the corner's edges point in opposite directions in pairs, which an odd count cannot do); G1
// only asks that B's cross derivative be α·A's plus some multiple β(t) of the edge's tangent:
//   D_B(t) − α·D_A(t) = β(t)·c'(t),   β(t) = s0 (1−t)² + 2 s1 t(1−t) + s2 t²,
// with D and c' the cubic cross derivative and the quadratic edge tangent. Both sides are degree 4;
// their five Bernstein coefficients are five linear rows in the points (α and β fixed).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace solve {

// True when the join leans along its seam (any shear coefficient non-zero) or its α varies
// (Join::alphaEnd): its rows are then the degree-4 identity's
//   D_B(t) − α(t)·D_A(t) = β(t)·c'(t),   α(t) = α0 (1−t) + α1 t.
inline bool hasShear(const Join& j) { return j.shear[0] != 0.0 || j.shear[1] != 0.0 || j.shear[2] != 0.0 || j.alphaEnd != 0.0; }
// α at A's point 3.
inline double endAlpha(const Join& j) { return j.alphaEnd != 0.0 ? j.alphaEnd : j.alpha; }

// Weight of shear coefficient i (0..2) times the edge difference Δ_j = A0(j+1) − A0(j) (j = 0..2)
// in degree-4 row i + j: C(2,i)·C(2,j) / C(4,i+j).
double shearWeight(int i, int j);

// Weight of d_k = B1k − (1+α)·A0k + α·A1k (k = 0..3) in degree-4 row l (0..4): degree elevation.
double elevationWeight(int l, int k);

// Weight of α0 (end 0) or α1 (end 1) times A's cross difference A0k − A1k in degree-4 row l.
double alphaWeight(int l, int k, int end);

// The Bernstein coefficients, along the join, of the term a fitted join lets go: its rows hold the
// identity's five coefficients only in proportion to these. (0, 0, 1, 0, 0) for a join as a fill
// made it; a part [t0, t1] of it (Join::fittedSpan) has B⁴₂ restricted there (blossoms).
std::array<double, 5> fittedWeights(const Join& join);

// The combinations of the identity's five coefficients that a join's rows hold: the five
// themselves, or for a fitted join those orthogonal to what it lets go — the middle coefficient
// and, for a part a split cut (fittedSpan), that part of the term too (fittedWeights), which the
// part's free middle cannot absorb once either side moves. Orthonormal, so the rows keep the
// coefficients' scale.
std::vector<std::array<double, 5>> heldCoefficients(const Join& join);

// The same join with A's parameter along the edge running the other way (its patch flipped): α's
// ends swap, β(t) becomes −β(1 − t), and a fitted part's span is mirrored.
Join reversedAlongEdge(const Join& join);

// A leaning join restricted to the part [from, to] of its edge (A's parameter), exactly: α(t) is
// linear and β(t) quadratic there too (β over the shorter edge's differences, so divided by its
// length). What a split gives each half of a fitted join, whose rows the shape meets only in part
// and which a fit from the shape would therefore change.
Join restrictedJoin(const Join& join, double from, double to);

// The join's α and shear measured from its rows by least squares (the rows of the identity above
// it holds, x, y and z: up to fifteen equations; four unknowns, five when α varies). Exact after any operation that keeps the
// surface (a split, a move of both sides): β restricted to part of the edge is still quadratic.
// nullopt when the join's patches do not exist or the fit is singular (a collapsed edge).
struct ShearFit {
    double alpha = 1.0;
    double alphaEnd = 0.0;  // fitted only for a join whose α varies
    std::array<double, 3> shear{};
};
std::optional<ShearFit> fitShear(const Document& doc, const Join& join);

}  // namespace solve
}  // namespace pw

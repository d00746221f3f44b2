// Evaluation of one 4x4 window: position, partial derivatives and unit normal for every basis,
// normals that stay finite at degenerate edges, bit-identical shared boundaries, and the exact
// de Casteljau split of a Bézier patch (DESIGN §2).
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/base/math_types.hpp"
#include "core/model/basis.hpp"

namespace pw {
inline namespace eval {

struct SurfacePoint {
    Vec3 p{0.0};
    Vec3 du{0.0};  // ∂p/∂u
    Vec3 dv{0.0};  // ∂p/∂v
    Vec3 n{0.0};   // unit normal, normalize(du × dv), with a fallback where that cross product vanishes
};

// Position and derivatives at (u, v) through the basis (matrix form for splines, Bernstein for
// Bézier), then the normal.
SurfacePoint evaluateNet(const Net16& net, Basis basis, double tension, double u, double v);

// Position, first and second derivatives and normal: what curvature needs (continuity report,
// curvature combs). Normal as evaluateNet's.
struct SurfaceJet {
    Vec3 p{0.0}, du{0.0}, dv{0.0}, duu{0.0}, duv{0.0}, dvv{0.0}, n{0.0};
};
SurfaceJet evaluateJet(const Net16& net, Basis basis, double tension, double u, double v);

// The normal at (u, v) given the derivatives there. Where du × dv vanishes (a collapsed edge such
// as the teapot's lid top) it uses the limit from inside the patch (the mixed derivative), and if
// that vanishes too, the normal a small step towards the patch centre.
Vec3 normalAt(const Net16& net, Basis basis, double tension, double u, double v, const Vec3& du, const Vec3& dv);

// Reference evaluators used to check the fast one.
Vec3 evaluateBezierBernsteinSum(const Net16& net, double u, double v);         // Σ B_i(v) B_j(u) P_ij
Vec3 evaluateMatrixForm(const Net16& net, const Mat4& m, double u, double v);  // V·M·G·Mᵀ·Uᵀ
Vec3 evaluateBezierDeCasteljau(const Net16& net, double u, double v);

// Exact de Casteljau split of a Bézier patch at u (left: u in [0,u], right: [u,1]) or at v.
std::pair<Net16, Net16> splitBezierU(const Net16& net, double u);
std::pair<Net16, Net16> splitBezierV(const Net16& net, double v);

// A point on a cubic Bézier curve at parameter k/n, evaluated in the canonical direction of the
// curve's four pool indices so that every patch sharing the curve gets bit-identical results.
Vec3 evaluateSharedBezierEdge(const std::array<Vec3, 4>& pts, const std::array<uint32_t, 4>& poolIdx, int k, int n);

// Precomputed basis weights for an (nu+1) x (nv+1) grid of a given basis.
struct GridWeights {
    Basis basis = Basis::Bezier;
    double tension = 0.5;
    int nu = 0, nv = 0;
    std::vector<BasisWeights> u, v;
};
GridWeights makeGridWeights(Basis basis, double tension, int nu, int nv);

// Evaluates the window on the grid u = c/nu, v = r/nv; out[r*(nu+1)+c]. For Bézier windows the
// boundary rows and columns come from evaluateSharedBezierEdge (watertight seams).
void evaluateGrid(const Net16& net, const std::array<uint32_t, 16>& poolIdx, const GridWeights& weights, std::vector<SurfacePoint>& out);

}  // namespace eval
}  // namespace pw

// Cubic Bézier triangles (10 control points, TrianglePatch in document.hpp): evaluation in
// barycentric coordinates, derivatives along two independent directions, unit normals that stay
// finite where an edge collapses, and boundary points from that edge's 4 points alone in the
// canonical direction of its pool indices (watertight shared edges, DESIGN §2).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/base/math_types.hpp"

namespace pw {
inline namespace model {
struct Document;
}  // namespace model
}  // namespace pw

namespace pw {
inline namespace eval {

// Ten control points in the canonical order of TrianglePatch::idx (b300, b210, b201, b120, b111,
// b102, b030, b021, b012, b003).
using Net10 = std::array<Vec3, 10>;

// Slot (0..9) of b_ijk, i + j + k = 3.
int triSlot(int i, int j, int k);

// Slot of the k-th point (k = 0..3) along triangle edge `edge` (0: u = 0, from the v corner to the
// w corner; 1: v = 0, from w to u; 2: w = 0, from u to v), like the triangle domain's outer levels.
int triEdgeSlot(int edge, int k);

// A point of the triangle at barycentric (u, v, w = 1 - u - v).
struct TriPoint {
    Vec3 p{0.0};
    Vec3 du{0.0};  // ∂p/∂u with v fixed (w = 1 - u - v), i.e. towards the u = 1 corner
    Vec3 dv{0.0};  // ∂p/∂v with u fixed
    Vec3 n{0.0};   // unit normal: normalize(du × dv), with a fallback where that vanishes
};

// Position, derivatives and normal; w is computed as 1 - u - v.
TriPoint evaluateTriangle(const Net10& net, double u, double v);

// Same with w given separately (so that grid points can pass exact (n-i-j)/n).
TriPoint evaluateTriangle(const Net10& net, double u, double v, double w);

// The normal given the derivatives at (u, v, w). Where du × dv vanishes (a collapsed edge or a
// corner whose two edge tangents are parallel) it takes the normal a small step towards the
// centroid, so every normal is finite and unit length; a net collapsed to a line gives (0, 0, 1).
Vec3 triangleNormalAt(const Net10& net, double u, double v, double w, const Vec3& du, const Vec3& dv);

// Reference: the explicit sum Σ 3!/(i!j!k!) u^i v^j w^k b_ijk.
Vec3 evaluateTriangleBernsteinSum(const Net10& net, double u, double v, double w);

// Control points of one triangle from the pool.
Net10 gatherTriangleNet(const Document& doc, const std::array<uint32_t, 10>& idx);

// Pool indices of edge `edge` (triEdgeSlot order).
std::array<uint32_t, 4> triEdgePool(const std::array<uint32_t, 10>& idx, int edge);

// The uniform triangular grid at level n: points (i, j) with u = i/n, v = j/n, w = (n-i-j)/n,
// stored row by row in j (row j holds i = 0..n-j). (n+1)(n+2)/2 points, n² triangles.
inline size_t triGridIndex(int i, int j, int n) {
    return static_cast<size_t>(j) * (n + 1) - static_cast<size_t>(j) * (j - 1) / 2 + static_cast<size_t>(i);
}
inline size_t triGridSize(int n) { return static_cast<size_t>(n + 1) * (n + 2) / 2; }

// Edge `edge` point k (k = 0..n, triEdgeSlot direction) as grid coordinates (i, j).
std::array<int, 2> triGridEdgePoint(int edge, int k, int n);

// Evaluates the grid (triGridIndex order). Boundary positions come from each edge's 4 points
// alone (evaluateSharedBezierEdge), so neighbours sharing the edge get bit-identical positions.
void evaluateTriangleGrid(const Net10& net, const std::array<uint32_t, 10>& poolIdx, int n, std::vector<TriPoint>& out);

// The same surface as a bicubic patch with a collapsed edge (what CAD formats without triangles
// take): the cubic composed with (s, t) -> (u, v, w) = (1 - s, s (1 - t), s t), which is bilinear,
// so the result is exactly bicubic. Row-major like Patch::idx (row i = t, column j = s); column 0
// (s = 0) is the u = 1 corner b300 four times. The rows run so that the patch's normal
// (∂/∂s × ∂/∂t) agrees with the triangle's.
Net16 triangleAsCollapsedQuad(const Net10& net);

// The inverse, for a quad read back from a CAD file: the triangle whose collapsed quad is `quad`
// within `tol` (every control point), or nullopt when it is not one (a collapsed quad of another
// shape, or an ordinary patch).
std::optional<Net10> collapsedQuadAsTriangle(const Net16& quad, double tol);

}  // namespace eval
}  // namespace pw

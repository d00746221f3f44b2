// Joins with a Bézier triangle on a side (issue 40): a triangle's edge joined C0 or G1 to a patch's
// edge or to another triangle's, held live by the solver like any join (the rows are in
// core/solve/triangle_seams.hpp). joinEdges, setJoinContinuity, remeasureJoin and unjoin
// (core/ops/join_ops.hpp) hand such joins here. Invalid requests throw EditError.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/model/document.hpp"

namespace pw {
inline namespace ops {

// Joins side (a, ea) to side (b, eb), at least one of them a triangle's edge (Edge::T0..T2; the
// index is then a triangle's). The end points pair the nearer way; edges that meet (within 1e-6 of
// their length) merge at their midpoints, else b's edge points move onto a's (Match). G1 fits α
// and β(t) to the shape by least squares (exact where the seam is G1 already) and projects the
// points onto the rows (a's side of the seam kept when matching); b lying back over a (α ≤ 0) is
// refused. Only C0 and G1 exist for triangles: their cross derivative is quadratic, so
// C1 between a triangle and a patch's cubic one has no meaning. A patch side must be Bézier and
// polynomial. Returns the join's index.
size_t joinTriangleEdges(Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb, Continuity continuity);

// Join j (with a triangle side) held as C0 or G1 from now on; α and β measured again. EditError,
// the join unchanged, when that cannot hold with the other joins.
void setTriangleJoinContinuity(Document& doc, size_t j, Continuity continuity);

// α and β of G1 join j (with a triangle side) fitted again from the shape (after a split of its
// patch side moved it onto a half whose rows are shorter).
void remeasureTriangleJoin(Document& doc, size_t j);

}  // namespace ops
}  // namespace pw

// Joining patch edges: plan and make a join (Rhino's Join and MatchSrf), change a join's
// continuity in place, and unjoin. Invalid requests throw EditError; the document is then unchanged
// (EditSession::apply works on a copy).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/model/document.hpp"
#include "core/model/topology.hpp"

namespace pw {
inline namespace ops {

// How a join of edge ea of patch a to edge eb of patch b goes (Rhino's Join and MatchSrf, with
// the orientation chosen so the patches end up on opposite sides of the seam, never folded):
// - the end points pair the nearer way (`reversed`);
// - when b is free (no joins, no point shared beyond that edge) and its normal would disagree with
//   a's across the seam, b's u direction is reversed first (`flipB`; a u edge then changes name);
// - when b extends back over a (its rows lie on a's side of the seam), free b is turned over its
//   own edge (`reflectB`, mirrored in the plane with normal `reflectNormal`); a b that is not free
//   is refused;
// - when the edges do not meet (`match`), a stays and b's boundary row moves onto a's edge, its
//   tangent row with it (C0) or onto a's continuation (C1, G1); else the edges merge at midpoints.
struct JoinPlan {
    Edge edgeB = Edge::U0;  // b's edge after the flip
    bool reversed = false;
    bool flipB = false;
    bool reflectB = false;
    Vec3 reflectNormal{0.0};
    bool match = false;
};
JoinPlan planJoin(const Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb);

// Joins edge ea of patch a to edge eb of patch b as planJoin says, records the join with
// `continuity` (G1: alpha from the current tangent lengths) and projects the constraints (a's
// rows at the seam fixed when matching). When the two edges are already joined to each other, the
// join's continuity is changed instead (setJoinContinuity). A C1/G1 join that closes a corner of 3,
// 5 or 6 patches whose seams are all C1/G1 makes it a G1 corner (core/ops/corner_ops; five and six
// split their patches 2×2 first), and `note` then says so. Returns the join's index.
size_t joinEdges(Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb, Continuity continuity, std::string* note = nullptr);

// Join j held with `continuity` from now on: the shape parameters are measured again from the
// current shape (α from the tangent rows' lengths for G1/G2, β2 by least squares for G2; 1 and 0
// for C1/C2) and the points projected onto the new constraints, A's side of the seam kept where it
// is. EditError when the joins cannot all hold then, naming them. A change to C1/G1 that closes a
// corner of 3, 5 or 6 such seams makes it a G1 corner, as joinEdges does (`note` says so).
void setJoinContinuity(Document& doc, size_t j, Continuity continuity, std::string* note = nullptr);

// The shape parameters of join j measured again from its rows, its continuity kept (C1 becomes G1
// and C2 becomes G2 when α is no longer 1): for a join whose rows an exact operation rescaled (a
// split's half, whose tangent rows are shorter, by t for a polynomial patch and by a ratio of
// weights for a rational one).
void remeasureJoin(Document& doc, size_t j);

// Removes join j; patch B of the join gets its own copies of the edge points, so the patches can
// be moved apart.
void unjoin(Document& doc, size_t j);

}  // namespace ops
}  // namespace pw

// Patch operations of the editor, pure (no Vulkan): add, duplicate, delete, flip, extrude from a
// boundary edge, split at u or v, join and unjoin two boundary edges. Every operation keeps the
// pool shared where patches meet and the join list consistent (indices renumbered, stale joins
// dropped). Invalid requests throw EditError with a message for the user; the document is then
// unchanged.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/base/errors.hpp"
#include "core/model/document.hpp"
#include "core/model/topology.hpp"

namespace pw {

// A flat 1x1 Bézier patch of side `size` centred at `center`, in the ground plane (z = const for
// z-up documents, y = const otherwise). Returns the new patch index.
uint32_t addFlatPatch(Document& doc, const Vec3& center, double size, bool zUp = true);

// A copy of patch p with its own new points, moved by `offset`. Returns the new patch index.
uint32_t duplicatePatch(Document& doc, uint32_t p, const Vec3& offset);

// Removes patch p and its joins, renumbers the other joins and drops points nobody uses.
void deletePatch(Document& doc, uint32_t p);

// Reverses the u direction (mirrors the columns), so the normal flips; joins are rewritten.
void flipPatch(Document& doc, uint32_t p);

// A new Bézier patch continuing patch p across edge e with C1 continuity (the cross-boundary
// tangent is repeated outward), sharing the edge's pool points; records the C1 join. Returns the
// new patch index.
uint32_t extrudeEdge(Document& doc, uint32_t p, Edge e);

// Exact de Casteljau split of Bézier patch p at parameter t (along u when `alongU`, else v). The
// first half keeps index p, the second is appended; the new shared curve gets new pool points and a
// join (C1 at t = 0.5, else G1 with alpha = (1-t)/t). Joins on the edges that were cut are dropped
// (their neighbours now meet two patches); joins on the far edge move to the second half. Those
// kept joins get their ratio rescaled (the halves' tangent rows are shorter), so C1 becomes G1.
std::pair<uint32_t, uint32_t> splitPatch(Document& doc, uint32_t p, bool alongU, double t);

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
// rows at the seam fixed when matching). Returns the new join index.
size_t joinEdges(Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb, Continuity continuity);

// Removes join j; patch B of the join gets its own copies of the edge points, so the patches can
// be moved apart.
void unjoin(Document& doc, size_t j);

// Removes pool points that no patch, surface or triangle uses and renumbers the rest.
void compactPool(Document& doc);

// Cubic Bézier curves (isoline domain). A new arch of width `size` at `center` in the ground plane.
uint32_t addCurve(Document& doc, const Vec3& center, double size, bool zUp = true);
// A curve on boundary `e` of Bézier patch p that shares the edge's pool points, so it follows the
// patch when its points move (and the patch keeps them if the curve is deleted).
uint32_t curveFromEdge(Document& doc, uint32_t p, Edge e);
// Removes curve c; points no longer used by anything are dropped from the pool.
void deleteCurve(Document& doc, uint32_t c);

// Cubic Bézier triangles. A new flat triangle of side `size` centred at `center` in the ground plane
// (its normal up), its 10 points on the uniform lattice.
uint32_t addTriangle(Document& doc, const Vec3& center, double size, bool zUp = true);
// A copy of triangle t with fresh points moved by `offset`; returns its index.
uint32_t duplicateTriangle(Document& doc, uint32_t t, const Vec3& offset);
// Removes triangle t; points no longer used by anything are dropped from the pool.
void deleteTriangle(Document& doc, uint32_t t);

// The edge of a patch nearest the parameter point (u, v).
Edge nearestEdge(double u, double v);

}  // namespace pw

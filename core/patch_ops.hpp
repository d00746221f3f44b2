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

#include "core/document.hpp"

namespace pw {

class EditError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

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

// Joins edge ea of patch a to edge eb of patch b: the edge points are merged into a's pool entries
// (placed at the midpoints; direction chosen by the nearer end points), the join recorded with
// `continuity` (G1: alpha from the current tangent lengths) and the constraints projected.
// Returns the new join index.
size_t joinEdges(Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb, Continuity continuity);

// Removes join j; patch B of the join gets its own copies of the edge points, so the patches can
// be moved apart.
void unjoin(Document& doc, size_t j);

// Index of a join that uses edge e of patch p, or -1.
int findJoin(const Document& doc, uint32_t p, Edge e);

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

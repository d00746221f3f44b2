// Patch operations of the editor, pure (no Vulkan): add, duplicate, delete, flip, extrude from a
// boundary edge (splits: core/ops/split_ops.hpp; joins: core/ops/join_ops.hpp). Every operation keeps the
// pool shared where patches meet and the join list consistent (indices renumbered, stale joins
// dropped). Invalid requests throw EditError with a message for the user; the document is then
// unchanged.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/base/errors.hpp"
#include "core/model/document.hpp"
#include "core/model/topology.hpp"

namespace pw {
inline namespace ops {

// A flat 1x1 Bézier patch of side `size` centred at `center`, in the ground plane (z = const for
// z-up documents, y = const otherwise). Returns the new patch index.
uint32_t addFlatPatch(Document& doc, const Vec3& center, double size, bool zUp = true);

// A copy of patch p with its own new points, moved by `offset`. Returns the new patch index.
uint32_t duplicatePatch(Document& doc, uint32_t p, const Vec3& offset);

// Removes patch p and its joins, renumbers the other joins and drops points nobody uses.
void deletePatch(Document& doc, uint32_t p);

// Reverses the u direction (mirrors the columns), so the normal flips; joins are rewritten.
void flipPatch(Document& doc, uint32_t p);
// flipPatch for several patches at once, in one pass over the joins (each patch flipped once).
void flipPatches(Document& doc, const std::vector<uint32_t>& patches);

// A new Bézier patch continuing patch p across edge e with C1 continuity (the cross-boundary
// tangent is repeated outward), sharing the edge's pool points; records the C1 join. Returns the
// new patch index.
uint32_t extrudeEdge(Document& doc, uint32_t p, Edge e);

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

// Helpers of the operations in core/ops: EditError unless patch p exists and is Bézier (`what`
// names the operation); EditError "patch p is rational; <needs>" when any of its points has a
// weight other than 1; a new pool point; the edge across the patch from e; slot s of a patch
// with its u direction reversed.
void checkBezier(const Document& doc, uint32_t p, const char* what);
void checkPolynomial(const Document& doc, uint32_t p, const std::string& needs);
uint32_t addPoint(Document& doc, const Vec3& v, double weight = 1.0);
Edge oppositeEdge(Edge e);
int flippedSlot(int s);

}  // namespace ops
}  // namespace pw

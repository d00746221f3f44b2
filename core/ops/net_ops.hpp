// Operations on net surfaces (one rows x cols control net under one basis), pure (no Vulkan):
// create flat nets, tubes and tori; insert and delete rows and columns; close a direction; switch
// the basis; convert a net to Bézier patches with the joins it implies (exact basis change) and a
// regular C2 grid of Bézier patches back to a B-spline net. Invalid requests throw EditError
// (core/base/errors.hpp) with a message for the user; the document is then unchanged.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/base/errors.hpp"
#include "core/model/document.hpp"
#include "core/model/topology.hpp"

namespace pw {
inline namespace ops {

enum class NetShape { Flat, Tube, Torus };

// A new rows x cols net (each ≥ 4) of `size` centred at `center`: flat in the ground plane, a tube
// (columns closed around the up axis) or a torus (both directions closed). Returns its index.
uint32_t addNetSurface(Document& doc, uint32_t rows, uint32_t cols, NetShape shape, Basis basis, const Vec3& center, double size,
                       bool zUp = true);

// Removes net s and the points nobody else uses.
void deleteNetSurface(Document& doc, uint32_t s);

// A new row of points before row `at` (0..rows): midway between its neighbours, or continuing the
// last spacing at an open end. Columns likewise.
void insertNetRow(Document& doc, uint32_t s, uint32_t at);
void insertNetColumn(Document& doc, uint32_t s, uint32_t at);
// Removes a row or column (a net keeps at least 4 of each) and the points nobody uses.
void deleteNetRow(Document& doc, uint32_t s, uint32_t row);
void deleteNetColumn(Document& doc, uint32_t s, uint32_t col);

// Opens or closes the columns (u) or rows (v) of a net: a closed direction wraps around.
void setNetClosed(Document& doc, uint32_t s, bool alongU, bool closed);
// Switches the basis of a net (Catmull-Rom uses `tension`).
void setNetBasis(Document& doc, uint32_t s, Basis basis, double tension);

// Why a net does not tile into whole windows (for example a Bézier net whose side is not 3k + 1),
// or nullopt when every point is used.
std::optional<std::string> netLayoutProblem(const Surface& s);

// The Bézier control points of each window of net `s` (exact basis change: the same surface),
// rows x cols of the Bézier grid that the windows share (3 per window, +1 on open sides), in
// pool-independent form: row-major positions.
struct BezierGrid {
    uint32_t rows = 0, cols = 0;
    bool closedU = false, closedV = false;
    std::vector<Vec3> points;
};
BezierGrid netToBezierGrid(const Document& doc, const Surface& s);

// Replaces net `s` by independent Bézier patches that share their boundary points, with the
// joins the basis implies (C1 for B-spline and Catmull-Rom, and for Bézier nets that keep C1;
// C0 otherwise). Returns the new patch indices, row by row.
std::vector<uint32_t> convertNetToPatches(Document& doc, uint32_t s);

// Replaces the Bézier patches `patches` (every patch when empty) by one uniform B-spline net when
// they form a regular grid (neighbours share whole edges, same orientation; a direction may wrap)
// that is C2 across every seam within `tolerance` × model size. Returns the new surface index.
// keepPatches: leave the patches (and the points only they use) for the caller to remove.
uint32_t convertPatchesToNet(Document& doc, std::vector<uint32_t> patches, double tolerance = 1e-9, bool keepPatches = false);

// The same grid of Bézier patches as one Bézier net that keeps C1 (Surface::keepC1) on their own
// points, when every seam is C1 within `tolerance` × model size (each seam point the midpoint of
// its neighbours across it: a Catmull-Rom net written to STEP comes back so). Returns the new
// surface index; EditError otherwise. keepC1 false: any grid, a net whose seams stay as they are
// (a trimmed CAD face fitted with uneven knots).
uint32_t convertPatchesToBezierNet(Document& doc, std::vector<uint32_t> patches, double tolerance = 1e-9, bool keepPatches = false,
                                   bool keepC1 = true);

}  // namespace ops
}  // namespace pw

// G1 corners where 3, 5 or 6 patches meet (issue 40, item 1). One bicubic patch per face cannot be
// G1 there with the plain rows (cross tangents collinear in pairs around an odd or six-fold corner
// is impossible), so each seam through the corner leans along its edge near it (Join::shear, core/
// solve/sheared_joins.hpp): β = s·(1−t)² from the corner, measured so that the corner's edges, laid
// into one tangent plane, satisfy every seam's condition there. Three patches need nothing more;
// five and six of fixed patches need the freedom of a 2×2 split of each corner patch (the cut runs
// on through the joins it crosses, so no join is dropped); a fill's, free inside, do not. The joins stay linear rows: the live solver holds
// the corner exactly while any point of it or its neighbours is dragged, and the patches stay plain bicubic Bézier patches (exact in STEP).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace ops {

// The patches around one point, in order, and the joins between consecutive ones (joins[i] is
// between patches[i] and patches[i + 1], cyclically).
struct CornerCycle {
    std::vector<uint32_t> patches;
    std::vector<size_t> joins;
    Vec3 at{0.0};
};

// The closed fan of patches around the corner of patch p at (cu, cv) (each 0 or 1), found through
// the joins on the edges through that point; nullopt when an edge through it has no join (the fan
// is open) or the walk meets a collapsed edge.
std::optional<CornerCycle> cornerCycle(const Document& doc, uint32_t p, int cu, int cv);

// Makes the seams of the closed fan around that corner G1 — every seam with `allSeams`, else the
// C1/G1 ones (C0 seams stay C0): for 3, 5 or 6 patches with leaning seams (5 and 6 split 2×2 first,
// unless a seam leans there already), for 4 with plain G1 joins. Returns
// what it did for the status line ("corner of 3 patches at (0.58, 0.58, 0.58) held G1 …").
// EditError, naming the cause, when the fan is open, has a G2 seam, a rational or spline patch, a
// seam a construction makes, does not turn one way around the corner, or cannot hold (conflict,
// fold). Without `split`, five or six patches are held as they are (a fill's patches, free
// inside, can be: core/ops/fill_hole); there, where the leans measured from the corner's edges do
// not close round it and every seam continues one of ratio 1 (or none), the corner is held with
// every ratio 1 and its edges there laid evenly round it (an affine image of a regular n-gon's spokes).
std::string makeG1Corner(Document& doc, uint32_t p, int cu, int cv, bool allSeams = true, bool split = true);

// For a join just made or changed to C1/G1: at either end of its edge, a closed fan of 3, 5 or 6
// patches with a C1/G1 seam that does not lean there yet has its C1/G1 seams made leaning G1 as
// above (plain rows would turn two of the corner's edges opposite, collapsing the patch between).
// Returns the status text ("" when there was none).
std::string closeCornersOf(Document& doc, size_t j);

// α at each end of join j (A's point 0, point 3) where it continues a C1/G1 seam straight through
// a regular corner (4 patches meet there, or will once a hole is filled): the two seams cross the
// same two tangent legs there, so their ratios must agree exactly (the rows round a regular corner
// are singular unless the ratios multiply to 1). nullopt at an end with no such seam.
std::array<std::optional<double>, 2> alphaAtEnds(const Document& doc, size_t j);

}  // namespace ops
}  // namespace pw

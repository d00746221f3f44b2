// Splitting patches without dropping a join (issue 40, item 5): an exact de Casteljau split of a
// Bézier patch, carried across every joined edge the cut line crosses into the neighbour at the
// matching parameter, ring after ring (Blender's loop cut, Rhino's InsertKnot on a polysurface).
// Each join the cut crosses becomes two; the other joins follow their half with their ratio
// rescaled. Invalid requests throw EditError; the document is then unchanged.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace ops {

// One patch the cut goes through: split along u (the cut is the line u = t) or along v.
struct RingCut {
    uint32_t patch = 0;
    bool alongU = true;
    double t = 0.5;
};

// The patches a split of patch p at t must cut so that no join is dropped: p, and across each
// joined edge the cut line crosses, the neighbour at the matching parameter, until the ring
// closes or ends at open edges. EditError when the ring reaches a patch that is not Bézier, or
// comes back to a patch at another parameter or direction.
std::vector<RingCut> splitRingOf(const Document& doc, uint32_t p, bool alongU, double t);

// Splits every patch of the ring through p. Each cut patch keeps its index for its first half
// (parameters 0..t) and appends its second half; the halves meet in a new join (C1 at t = 0.5,
// else G1 with α = (1 − t)/t); a join the cut crosses becomes one join per half; a join on a cut
// patch's far edge moves to the second half (its ratio rescaled, so C1 becomes G1). Returns the
// cuts made, in ring order, with the index of each second half.
std::vector<std::pair<RingCut, uint32_t>> splitRing(Document& doc, uint32_t p, bool alongU, double t);

// splitRing, returning the two halves of p.
std::pair<uint32_t, uint32_t> splitPatch(Document& doc, uint32_t p, bool alongU, double t);

}  // namespace ops
}  // namespace pw

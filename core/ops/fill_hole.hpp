// Filling an n-sided hole (issue 40, item 2; Rhino's Patch and MultiSidedPatch, Alias's
// Multi-Edge Blend, Plasticity's Patch — but held live): 3 to 6 sides, each one patch edge, two
// edges end to end, or a curve of one cubic segment, closed into a loop. A curve is split at its
// middle and the fill shares its points (no join: the fill's edge is the curve; DESIGN §14). Each side is split at its middle (a side of
// one edge: its patch is split there, the cut running on through its ring so no join is dropped), and one bicubic patch per hole corner
// fills it, the n of them meeting at a centre: G1 to every surrounding patch, and G1 to each other through the corner construction of
// core/ops/corner_ops (leaning seams; the fill's patches, free inside, are not split there). Everything stays joins the live solver
// holds: drag the surroundings and the fill follows, within the solver's residual. A hole whose
// sides' two ends ask different tangent ratios is filled with fitted joins (core/ops/
// fitted_sides): held within 0.1°, as no bicubic fill can be exact there; where that is refused
// (a seam past 0.1°, a fold), the fill falls back to joins of one ratio each where the surroundings
// can bend to meet them (the status line says so), else it is refused naming the sides.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace ops {

struct HoleSide {
    std::vector<std::pair<uint32_t, Edge>> edges;  // one edge, or two that meet end to end
    int32_t curve = -1;                            // else a document curve of one polynomial segment, not closed
};

// Fills the hole; returns the status line ("filled a 3-sided hole with 3 patches (18..20) …").
// EditError, with the document unchanged by the caller's EditSession, when a side is not an open
// edge of a Bézier patch or a curve of one segment, the sides do not close a loop, or the fill
// cannot hold.
std::string fillHole(Document& doc, const std::vector<HoleSide>& sides);

// Fills a 3-sided hole of single edges with one cubic Bézier triangle sharing their points (the
// corner patch Rhino's and Alias's fillets leave as a degenerate quad), G1 to all three through
// the triangle joins of core/ops/triangle_joins.hpp; its middle point b111, the surroundings' free
// points beside the edges and each join's α and lean β(t) are what the seams are held with. A side
// may be a curve of one cubic segment instead (polynomial, not closed): the triangle's edge is then
// the curve's own points, with nothing to join (three curves make a triangle through them, as
// Rhino's EdgeSrf does with three curves). Returns the status line. EditError as fillHole, and when
// a side has two edges.
std::string fillHoleWithTriangle(Document& doc, const std::vector<HoleSide>& sides);

}  // namespace ops
}  // namespace pw

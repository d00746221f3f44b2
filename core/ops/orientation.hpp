// Consistent outward orientation of a whole model. For a closed (or nearly closed) surface the flux
// of the position through it, ∮ (p - c)·n dA, is three times the enclosed volume whatever c is:
// positive when the normals point out, negative when every patch is turned inside out.
#pragma once

#include "core/model/document.hpp"

namespace pw {
inline namespace ops {

// ∮ (p - c)·n dA over every window (c = bounding-box centre), by the midpoint rule on an
// n x n grid per window.
double positionFlux(const Document& doc, int n = 8);

// Share of the patches' boundary curves (collapsed ones not counted) that are in no join.
double openBoundaryShare(const Document& doc);

// Flips every patch (flipPatch, joins rewritten) when the model is mostly closed (at most 25 % of
// its boundary curves open; "outward" means nothing for an open sheet) and the flux is negative.
// Returns true if it did. Meant for imports that carry no orientation (.bpt); surfaces are left
// as they are.
bool orientOutward(Document& doc);

}  // namespace ops
}  // namespace pw

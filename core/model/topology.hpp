// How the document's pieces connect, as queries the layers above share (the solver, picking and the
// operations): the join on a patch edge, and the C1 seams that a Bézier net keeps by itself.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/model/document.hpp"

namespace pw {

// Index of a join that uses edge e of patch p, or -1.
int findJoin(const Document& doc, uint32_t p, Edge e);

// The C1 conditions of Bézier nets that keep C1, as triples (before, seam, after) of pool indices
// with seam = (before + after) / 2 (rows of the constraint solver).
std::vector<std::array<uint32_t, 3>> netC1Triples(const Document& doc);

}  // namespace pw

// Finds joins between patches that share a boundary curve in the pool: C0 where the four edge
// indices coincide (same or reversed order); C1 or G1 (with the ratio alpha) where the cross-
// boundary control rows are also collinear with a constant ratio along the edge.
#pragma once

#include <vector>

#include "document.hpp"

namespace pw {

struct JoinDetectOptions {
    double relativeTolerance = 1e-6;  // × model size: collinearity and ratio tolerance
    double c1RatioTolerance = 1e-6;   // |alpha - 1| below this is C1
};

std::vector<Join> detectJoins(const Document& doc, JoinDetectOptions options = {});

// Pool entries with bit-identical coordinates merged into one; patch and surface indices rewritten.
void mergeCoincidentPoints(Document& doc);

}  // namespace pw

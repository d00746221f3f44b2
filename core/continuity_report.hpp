// Measured continuity along each join: how far the two sides are from C0, C1 and a shared normal.
#pragma once

#include <vector>

#include "core/document.hpp"

namespace pw {

struct JoinContinuity {
    size_t join = 0;
    double c0Gap = 0;            // largest distance between the two sides' surface points on the seam
    double c1Residual = 0;       // largest |B1k - B0k - alpha·(A0k - A1k)| over the edge's points
    double normalAngleDeg = 0;   // largest angle between the two sides' normals along the seam
};

// Samples each seam at `samples`+1 points.
std::vector<JoinContinuity> continuityReport(const Document& doc, int samples = 32);

}  // namespace pw

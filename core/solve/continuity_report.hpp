// Measured continuity along each join, the way Rhino's EdgeContinuity measures it: the gap
// between the two sides, the angle between their normals and the deviation of their curvature
// across the seam (largest along the edge), plus the control-point residuals the solver holds.
#pragma once

#include <cstdint>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace solve {

struct JoinContinuity {
    size_t join = 0;
    double c0Gap = 0;           // largest distance between the two sides' surface points on the seam
    double c1Residual = 0;      // largest tangent-row residual (|B1k - B0k - alpha·(A0k - A1k)|, or a leaning seam's rows)
    double c2Residual = 0;      // C2/G2: largest residual of the β-constraint rows (else 0)
    double normalAngleDeg = 0;  // largest angle between the two sides' normals along the seam
    // Largest |κA − κB| / max(|κA|, |κB|, κ0) · 100 along the seam, κ the normal curvature in the
    // direction across the seam (in the tangent plane, perpendicular to the edge) on each side and
    // κ0 = 1e-3 / model size (bends flatter than a thousand model sizes count as flat).
    double curvatureDeviationPct = 0;
    double maxCurvature = 0;  // largest |κ| across the seam on either side (1 / model units)
};

// What a join fails of the tolerances its continuity asks for: position for every join, the
// normal angle for C1/G1/C2/G2, the curvature deviation for C2/G2.
enum ToleranceFailure : uint8_t { kWithinTolerance = 0, kPositionOut = 1, kAngleOut = 2, kCurvatureOut = 4 };
uint8_t toleranceFailures(const JoinContinuity& c, Continuity continuity, const ContinuityTolerances& tol);

// Samples each seam at `samples`+1 points; `only` (when not empty) limits the report to those joins.
std::vector<JoinContinuity> continuityReport(const Document& doc, int samples = 32, const std::vector<size_t>& only = {});

}  // namespace solve
}  // namespace pw

// Least-squares fits of sampled curves by C2 cubic splines, written out as chains of cubic Bézier
// segments (3n + 1 points, the document's curve form): intersection and projected curves (issue
// 64) and their p-curves in a surface's domain. C2, so the curves made are as smooth as
// `curve-through`'s.
#pragma once

#include <vector>

#include "core/base/math_types.hpp"

namespace pw {
inline namespace trim {

struct CurveFit {
    std::vector<Vec3> bezier;  // 3n + 1 points; closed fits end on their first point
    double deviation = 0.0;    // the largest distance from a sample to the fit at its parameter
};

// Fits `samples` (in order; for a closed curve the first is not repeated at the end) with
// `segments` cubic segments, parameterised by chord length. An open fit passes through the first
// and last samples exactly.
CurveFit fitCubicChain(const std::vector<Vec3>& samples, bool closed, size_t segments);
// The fewest segments (from `minSegments`, at most `maxSegments`) whose fit stays within `tol`;
// the last tried when none does.
CurveFit fitCubicChainWithin(const std::vector<Vec3>& samples, bool closed, double tol, size_t minSegments = 2, size_t maxSegments = 96);

}  // namespace trim
}  // namespace pw

// Scale-relative tolerances of the evaluators (quad patches and Bézier triangles): a control net's
// size, and whether a cross product of tangents is too small to give a normal's direction.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <glm/common.hpp>

#include "core/base/math_types.hpp"

namespace pw {
inline namespace base {

// Diagonal of the control points' bounding box (never 0).
template <size_t N>
double netScale(const std::array<Vec3, N>& net) {
    Vec3 lo = net[0], hi = net[0];
    for (const Vec3& p : net) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return std::max(glm::length(hi - lo), 1e-300);
}

// True where a cross product n of two tangents is too small to give a direction (`scale2`: the
// net's scale squared).
inline bool degenerateCross(const Vec3& n, double scale2) { return !(glm::length(n) > 1e-12 * scale2); }

}  // namespace base
}  // namespace pw

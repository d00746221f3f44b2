// The quarter turns between a document's up axis and a file's: glTF and OBJ are +Y up, STEP and IGES
// +Z up. Each only permutes and negates coordinates, so it is exact and turning back restores the
// same numbers.
#pragma once

#include <array>

#include "core/base/math_types.hpp"

namespace pw {
inline namespace base {

// A Z-up point in a +Y-up file: (x, y, z) -> (x, z, -y) (+Z to +Y, the front -Y to +Z).
inline std::array<float, 3> zUpToYUp(const std::array<float, 3>& p) { return {p[0], p[2], -p[1]}; }

// A Y-up point in a +Z-up file: (x, y, z) -> (x, -z, y), the inverse of zUpToYUp.
inline Vec3 yUpToZUp(const Vec3& p) { return {p.x, -p.z, p.y}; }

}  // namespace base
}  // namespace pw

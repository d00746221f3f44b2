// Partial upload of moved control points during a drag: which pool entries changed since the last
// upload, and their positions written into a mapped vertex buffer laid out like the renderer's pool
// (host-visible, four floats a point: x y z and the weight, which a drag leaves alone). Header-only,
// no Vulkan.
#pragma once

#include <cstdint>
#include <vector>

#include "core/base/math_types.hpp"

namespace pw {
inline namespace base {

// Indices i where after[i] != before[i] (sizes must match); `before` is then updated to `after`.
inline void takeChangedPoints(std::vector<Vec3>& before, const std::vector<Vec3>& after, std::vector<uint32_t>& changed) {
    changed.clear();
    const size_t n = std::min(before.size(), after.size());
    for (size_t i = 0; i < n; ++i)
        if (before[i] != after[i]) {
            changed.push_back(uint32_t(i));
            before[i] = after[i];
        }
}

// dst[4i..4i+2] = points[i] for each changed i (dst[4i+3], the weight, stays).
inline void writePoolPositions(const std::vector<Vec3>& points, const std::vector<uint32_t>& changed, float* dst) {
    for (uint32_t i : changed) {
        dst[4 * size_t(i) + 0] = float(points[i].x);
        dst[4 * size_t(i) + 1] = float(points[i].y);
        dst[4 * size_t(i) + 2] = float(points[i].z);
    }
}

}  // namespace base
}  // namespace pw

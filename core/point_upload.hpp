// Partial upload of moved control points during a drag: which pool entries changed since the last
// upload, and their float3 values written into a mapped vertex buffer (host-visible, tightly packed
// vec3 floats like the renderer's pool buffer). Header-only, no Vulkan.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math_types.hpp"

namespace pw {

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

// dst[3i..3i+2] = points[i] for each changed i.
inline void writeFloat3(const std::vector<Vec3>& points, const std::vector<uint32_t>& changed, float* dst) {
    for (uint32_t i : changed) {
        dst[3 * size_t(i) + 0] = float(points[i].x);
        dst[3 * size_t(i) + 1] = float(points[i].y);
        dst[3 * size_t(i) + 2] = float(points[i].z);
    }
}

}  // namespace pw

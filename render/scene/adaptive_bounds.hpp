// CPU bound of the segments each window gets this frame under adaptive tessellation, from the
// control shader's own per-edge formula (core/gpu/patch_math.h's adaptiveEdgeLevel), so that draws can be
// batched by the levels actually produced rather than by the worst case (64 -> one window per draw).
#pragma once

#include <cstdint>
#include <vector>

#include "core/model/camera_math.hpp"
#include "core/model/document.hpp"
#include "render/scene/surface_scene.hpp"

namespace pw::render {
inline namespace scene {

// A window's segments along u (its two edges v = 0 and v = 1, and so its first inner level) and along
// v (edges u = 0 and u = 1, the second inner level), where each is certainly one number; 0 where not.
struct DirectionLevels {
    uint8_t u = 0, v = 0;
    bool known() const { return u != 0 && v != 0; }
    bool operator==(const DirectionLevels&) const = default;
};

// Per window: an upper bound of its outer and inner segments (1..64), +1 for float differences.
// With `uniform`: per window, the segments along u and along v where the control shader's float
// arithmetic cannot round either direction's two edges otherwise (no override).
std::vector<uint8_t> adaptiveLevelBounds(const SurfaceScene& s, const TessSettings& tess, const ViewMatrices& vm, float viewportW,
                                         float viewportH, float maxLevel, std::vector<DirectionLevels>* uniform = nullptr);

}  // namespace scene
}  // namespace pw::render

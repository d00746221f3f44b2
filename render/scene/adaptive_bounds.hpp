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

// Per window: an upper bound of its outer and inner segments (1..64), +1 for float differences.
// With `uniform`: per window, the segments of all six levels when they are certainly one number (the
// control shader's float arithmetic cannot round any edge otherwise; no override), else 0.
std::vector<uint8_t> adaptiveLevelBounds(const SurfaceScene& s, const TessSettings& tess, const ViewMatrices& vm, float viewportW,
                                         float viewportH, float maxLevel, std::vector<uint8_t>* uniform = nullptr);

}  // namespace scene
}  // namespace pw::render

// Off-screen culling decided on the CPU before the control shader runs (DESIGN §3): the box of the
// scene's points against the frustum (nothing to cull: the frame takes the fixed-level control
// shader), and per window when the frustum cuts the scene: windows wholly inside drawn without the
// per-patch test, windows wholly outside not drawn at all, only those near a plane left to the test
// (core/gpu/patch_math.h frustumPlane, the planes the control shader uses; the same result).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "render/scene/surface_scene.hpp"

namespace pw::render {
inline namespace scene {

// Every point inside the frustum of viewProj, with room for the control shader's float rounding:
// the box of the points, its corner nearest each plane's outside. True for no points.
bool insideFrustum(const std::vector<glm::vec3>& points, const glm::mat4& viewProj);

// The windows of s as the frustum of viewProj sees them, for the two draws of a frame: `tested`
// marks (1) the windows the per-patch test need not draw, `inside` those the fixed-level draw need
// not (all but the wholly inside ones; every window when `fixedAllowed` is false: levels or culling
// other than uniform and off-screen need the full control shader). Windows already drawn by merged
// blocks (`merged`, may be null) are in neither draw.
struct WindowCulling {
    std::vector<uint8_t> skipTested, skipInside;
    uint32_t outside = 0, inside = 0;  // windows wholly outside (not drawn) and wholly inside
};
WindowCulling classifyWindows(const SurfaceScene& s, const glm::mat4& viewProj, bool fixedAllowed, const std::vector<uint8_t>* merged);

}  // namespace scene
}  // namespace pw::render

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

// The box of a scene's points, computed once a frame for both tests below.
struct PointsBox {
    glm::vec3 lo{0.0f}, hi{0.0f};
    bool empty = true;
    float reach() const;  // how far from the origin its coordinates go (the scale of the plane tests' rounding)
};
PointsBox pointsBox(const std::vector<glm::vec3>& points);

// Every point of the box inside the frustum of viewProj, with room for the control shader's float
// rounding: the box's corner nearest each plane's outside. True for an empty box.
bool insideFrustum(const PointsBox& box, const glm::mat4& viewProj);

// The windows of s (whose points' box is `box`) as the frustum of viewProj sees them, for the two
// draws of a frame: `skipTested` marks (1) the windows the per-patch test need not draw,
// `skipInside` those the fixed-level draw need not (all but the wholly inside ones; every window
// when `fixedAllowed` is false: levels or culling other than uniform and off-screen need the full
// control shader), `skipCulled` those one draw of every window need not (the culled ones). Windows
// already drawn by merged blocks (`merged`, may be null) are in no draw.
struct WindowCulling {
    std::vector<uint8_t> skipTested, skipInside, skipCulled;
    uint32_t outside = 0, inside = 0;  // windows wholly outside (not drawn) and wholly inside
};
WindowCulling classifyWindows(const SurfaceScene& s, const PointsBox& box, const glm::mat4& viewProj, bool fixedAllowed,
                              const std::vector<uint8_t>* merged);

}  // namespace scene
}  // namespace pw::render

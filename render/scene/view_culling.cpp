#include "render/scene/view_culling.hpp"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/gpu/patch_math.h"

namespace pw::render {
inline namespace scene {

PointsBox pointsBox(const std::vector<glm::vec3>& points) {
    PointsBox b;
    if (points.empty()) return b;
    b.lo = b.hi = points[0];
    b.empty = false;
    for (const glm::vec3& p : points) {
        b.lo = glm::min(b.lo, p);
        b.hi = glm::max(b.hi, p);
    }
    return b;
}

float PointsBox::reach() const { return glm::length(hi - lo) + glm::length(hi + lo); }

bool insideFrustum(const PointsBox& box, const glm::mat4& viewProj) {
    if (box.empty) return true;
    const float extent = box.reach();
    for (int k = 0; k < 6; ++k) {
        const glm::vec4 plane = gpu::frustumPlane(viewProj, k);
        const glm::vec3 nearest(plane.x >= 0 ? box.lo.x : box.hi.x, plane.y >= 0 ? box.lo.y : box.hi.y, plane.z >= 0 ? box.lo.z : box.hi.z);
        if (glm::dot(plane, glm::vec4(nearest, 1.0f)) < 1e-5f * glm::length(glm::vec3(plane)) * extent) return false;
    }
    return true;
}

WindowCulling classifyWindows(const SurfaceScene& s, const PointsBox& box, const glm::mat4& viewProj, bool fixedAllowed,
                              const std::vector<uint8_t>* merged) {
    WindowCulling c;
    c.skipTested.assign(s.windowCount, 1);
    c.skipInside.assign(s.windowCount, 1);
    c.skipCulled.assign(s.windowCount, 1);
    // Near a plane, within what float rounding of the plane test may move (relative to the scene's
    // coordinates and the plane's offset), the control shader decides.
    const float reach = box.reach();
    glm::vec4 planes[6];
    float pad[6];
    for (int k = 0; k < 6; ++k) {
        planes[k] = gpu::frustumPlane(viewProj, k);
        pad[k] = 1e-5f * (glm::length(glm::vec3(planes[k])) * reach + std::abs(planes[k].w));
    }
    for (uint32_t w = 0; w < s.windowCount; ++w) {
        if (merged && (*merged)[w]) continue;
        const uint32_t* idx = &s.cpuIndices[size_t(w) * 16];
        bool out = false, in = true;
        for (int k = 0; k < 6 && !out; ++k) {
            bool allOut = true;
            for (int i = 0; i < 16; ++i) {
                const float d = glm::dot(planes[k], glm::vec4(s.cpuPoints[idx[i]], 1.0f));
                allOut = allOut && d < -pad[k];
                in = in && d > pad[k];
            }
            out = allOut;
        }
        if (out) {
            ++c.outside;  // every control point outside one plane: the control shader would cull it
        } else if (in && fixedAllowed) {
            ++c.inside;
            c.skipInside[w] = c.skipCulled[w] = 0;
        } else {
            c.skipTested[w] = c.skipCulled[w] = 0;
        }
    }
    return c;
}

}  // namespace scene
}  // namespace pw::render

// CPU mirrors of the shader interface in shaders/common.glsl (std140 uniform block, std430
// storage buffers, push constants). Keep both in step.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace pw::render {

struct FrameUniforms {
    glm::mat4 viewProj;
    glm::mat4 view;
    glm::vec4 eye;
    glm::vec4 lightDir;   // w: normal overlay length
    glm::vec4 viewport;   // xy pixels
    glm::vec4 outer;      // uniform outer levels
    glm::vec4 inner;      // xy inner, z max level, w target pixels per segment
    glm::vec4 dist;       // x d0, y d1, z curvature scale, w zebra stripes
    glm::uvec4 modes;     // x spacing, y adaptive, z cull bits (1 back, 2 offscreen), w shading
    glm::uvec4 sel;       // x hovered point, y selected point
    // View rays: the direction from the eye through NDC (x, y) is rayZ + x rayX + y rayY (the
    // fragment shader's view vector, so no world position travels as a varying).
    glm::vec4 rayX, rayY, rayZ;
    glm::vec4 isoline;  // isoline domain (curves, isocurves): x lines, y segments
};
static_assert(sizeof(FrameUniforms) == 2 * 64 + 12 * 16);

struct PatchData {
    glm::vec4 outer{0.0f};
    glm::vec4 inner{0.0f};  // xy inner levels, z = 1: override active
};

struct DrawPush {
    glm::mat4 basis{1.0f};  // row-major basis matrix M (rows t^3, t^2, t, 1)
    uint32_t patchBase = 0;
    uint32_t basisKind = 0;  // 0 Bézier, 1 B-spline, 2 Catmull-Rom
    uint32_t drawMode = 0;   // 0 shaded, 1 flat colour, 3 grid points
    uint32_t isoDirection = 0;  // isocurve overlay: 0 lines along u, 1 along v
    glm::vec4 color{1.0f};
};
static_assert(sizeof(DrawPush) == 96);

constexpr uint32_t kNoPoint = 0xffffffffu;

}  // namespace pw::render

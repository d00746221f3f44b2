// Merged blocks (issue 43): lavapipe's tessellation costs about 6 µs a patch whatever its level, so
// thousands of small windows cost more than their triangles. Windows of a net that all get the same
// levels this frame, nu along u and nv along v, are drawn Bu x Bv at a time (4 x 4, 2 x 2, 2 x 1 or
// 1 x 2) as one patch at levels Bu nu and Bv nv (shaders/merged.tesc, surface.tese -DMERGED): the
// tessellator still makes every vertex, and the evaluation shader places each at exactly the
// parameters the window's own patch would get (core/gpu/tess_place.h), so the surface and the seams
// with unmerged neighbours stay the same (only the diagonals the tessellator picks inside a block may
// differ). Powers of two merge on any device (i / (B n) is i' / n); other levels only where the
// tessellator's placement is known (lavapipe's 16.16 fixed point). Only where the result cannot differ:
// spline nets (normals continuous across their windows' seams, where a vertex inside a block is
// evaluated on one of the two windows), shading by position and normal only (not UV, patch id,
// curvature or level), equal or pow2 spacing, no overrides, no displacement, no window the control
// shader would cull, no wireframe or normals overlay (they show each patch's own tessellation).
#pragma once

#include <vulkan/vulkan.h>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <utility>
#include <vector>

#include "core/model/camera_math.hpp"
#include "core/model/document.hpp"
#include "render/scene/adaptive_bounds.hpp"
#include "render/scene/surface_scene.hpp"

namespace pw::render {
inline namespace scene {

// The largest level of a merged patch (Bu nu, Bv nv).
constexpr uint32_t kMaxMergedLevel = 16;

struct MergedBlocks {
    std::vector<glm::uvec4> blocks;                     // first window, windows per net row, Bu + 256 Bv, nu + 256 nv; in window order
    std::vector<std::pair<uint32_t, uint32_t>> perRun;  // per basis run of the scene: [first, count) of its blocks
    std::vector<uint8_t> merged;                        // per window: 1 when a block draws it
    uint32_t windows = 0;                               // windows the blocks draw
};

// The blocks of this frame. `uniform`: per window the levels along u and v its edges certainly round
// to (adaptiveLevelBounds), 0 where not; `cullView`: the view that culls (offscreen, far);
// `deviceMax`: the device's largest tessellation level (Bu nu and Bv nv exceed neither it nor kMaxMergedLevel);
// `anyLevel`: the device places vertices as core/gpu/tess_place.h, so levels other than powers of two merge too.
MergedBlocks planMergedBlocks(const SurfaceScene& s, const std::vector<DirectionLevels>& uniform, const TessSettings& tess,
                              const ViewMatrices& cullView, float deviceMax, bool anyLevel);

// Draws the blocks (the merged pipeline bound), per basis run, as many a draw as keep their evaluation
// vertices within `vertexBudget` (0: no limit); the number of draws.
uint32_t recordMergedBlocks(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, const MergedBlocks& m, gpu::DrawPush push,
                            uint32_t vertexBudget);

// Per window the levels uniform settings (no adaptivity) give along u and v, when each direction's agree; 0 otherwise.
std::vector<DirectionLevels> settingsWindowLevels(const SurfaceScene& s, const TessSettings& tess);

}  // namespace scene
}  // namespace pw::render

// GPU copy of a document for the tessellated surface: the pool as a vertex buffer (position and weight), 16 pool
// indices per window as the index buffer, per-patch level overrides, and runs of windows sharing
// a basis (one push-constant matrix per run); the Bézier triangles' 10 pool indices each in a second
// index buffer (drawn by triangle_draws.*). Records the batched surface draws.
#pragma once

#include <vector>

#include "core/gpu/gpu_interface.h"
#include "core/model/document.hpp"
#include "core/model/height_map.hpp"
#include "core/tess/tess_levels.hpp"
#include "render/vk/buffers.hpp"

namespace pw::render {
inline namespace scene {

struct BasisRun {
    uint32_t first = 0, count = 0;  // windows [first, first + count)
    uint32_t basisKind = 0;
    glm::mat4 matrix{1.0f};
};

// The windows of one net: rows x cols of them, row after row, from `first`.
struct NetWindows {
    uint32_t first = 0, rows = 0, cols = 0;
};

struct SurfaceScene {
    Buffer pool;       // 4 floats per pool point: xyz, weight (HostWritten: dragged points are written in place); also storage
    Buffer indices;    // 16 uint32 per window; also storage (merged blocks read their windows' points)
    Buffer patchData;  // gpu::PatchData per window
    uint32_t pointCount = 0;
    uint32_t windowCount = 0;
    float overrideMax = 0.0f;  // largest override level (0 = none)
    std::vector<BasisRun> runs;
    // CPU copies for per-frame level bounds (adaptive batching).
    std::vector<glm::vec3> cpuPoints;
    std::vector<uint32_t> cpuIndices;  // 16 per window
    std::vector<float> overrideLevel;  // per window: largest override level, 0 = none
    std::vector<NetWindows> nets;      // the nets' windows, for merged blocks (render/scene/merged_blocks.hpp)
    // Bézier triangles: 10 uint32 pool indices each; their gpu::PatchData follows the windows' in
    // patchData (triangle t is entry windowCount + t).
    Buffer triIndices;
    uint32_t triangleCount = 0;
    // Bézier curves: 4 uint32 pool indices each (isoline domain, render/scene/triangle_draws.hpp).
    Buffer curveIndices;
    uint32_t curveCount = 0;
    // The control points drawn: when some pool points belong to no item (hidden items, orphans), the
    // pool indices of those that do; otherwise empty and every point is drawn.
    Buffer shownPoints;
    uint32_t shownPointCount = 0;
    // Trims (issue 64): every tested window's v-monotone segments in its own (u, v), sorted by their
    // lowest v, three vec4 each: the box (umin, vmin, umax, vmax), then b0 b1 and b2 b3 (binding 7;
    // PatchData::trim points into it), and how many windows are trimmed at all.
    std::vector<glm::vec4> trimData;
    Buffer trimSegments;
    uint32_t trimmedWindows = 0;
};

// Per window, then per Bézier triangle: its levels under the shared-edge rule
// (core/tess/edge_levels.hpp) and its displacement, as the control shaders read them; sets the
// scene's overrideLevel and overrideMax. `inst`: expandPatches(doc).
std::vector<gpu::PatchData> windowPatchData(const Document& doc, const std::vector<PatchInstance>& inst, const HeightMap* map,
                                            const std::vector<HeightMap>* mips, SurfaceScene& s);

// `map`: the height map whose detail per edge goes into the patch data (displacement-adaptive levels).
// `mips`: the map's heightMipChain when the caller holds it (else made for the map's detail).
SurfaceScene uploadSurfaceScene(Device& dev, const Document& doc, const HeightMap* map = nullptr,
                                const std::vector<HeightMap>* mips = nullptr);

// Binds pool + index buffers and issues the draws, at most `perDraw` windows per vkCmdDrawIndexed,
// or, with `levels` (per-window segment bounds) and a non-zero `vertexBudget`, as many windows as
// keep windows x (max level + 2)^2 <= vertexBudget. Returns the number of draws. `push` supplies
// drawMode/colour; basis fields are filled per run.
// One window alone (the curvature graph across a join); 0 draws for a window the scene lacks.
// The basis run that holds window w; null for a window the scene lacks.
const BasisRun* windowRun(const SurfaceScene& s, uint32_t w);

uint32_t recordWindowDraw(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, uint32_t window, gpu::DrawPush push);

// With `skip`, the windows marked 1 are left out (merged blocks draw them).
uint32_t recordSurfaceDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, uint32_t perDraw, gpu::DrawPush push,
                            const std::vector<uint8_t>* levels = nullptr, uint32_t vertexBudget = kCpuDrawVertexBudget,
                            const std::vector<uint8_t>* skip = nullptr);

glm::mat4 basisPushMatrix(Basis basis, double tension);

}  // namespace scene
}  // namespace pw::render

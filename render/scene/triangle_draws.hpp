// Draws of the document's patches that are not 4x4 windows. Cubic Bézier triangles (patch lists of 10 control points from the pool,
// SurfaceScene::triIndices), batched like the windows: at most `perDraw` triangles per
// vkCmdDrawIndexed (a triangle at level L has (L+1)(L+2)/2 evaluation vertices, fewer than a
// window, so the windows' batch size keeps lavapipe within its budget, DESIGN §4).
#pragma once

#include <vulkan/vulkan.h>

#include "core/gpu/gpu_interface.h"
#include "render/scene/surface_scene.hpp"

namespace pw::render {
inline namespace scene {

// Binds the pool and the triangle index buffer and issues the draws; patchBase is
// windowCount + first triangle (their gpu::PatchData follows the windows'). Returns the number of draws.
uint32_t recordTriangleDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, uint32_t perDraw, gpu::DrawPush push);

// Binds the pool and the curve index buffer and draws every Bézier curve (patch lists of 4 control
// points through the isoline domain): a curve has at most 65 evaluation vertices, so a draw holds
// vertexBudget / 65 curves (lavapipe: 63; 0 = no budget, one draw). Returns the number of draws.
uint32_t recordCurveDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, gpu::DrawPush push, uint32_t vertexBudget);

}  // namespace scene
}  // namespace pw::render

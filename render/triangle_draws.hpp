// Draws of the document's cubic Bézier triangles (patch lists of 10 control points from the pool,
// SurfaceScene::triIndices), batched like the windows: at most `perDraw` triangles per
// vkCmdDrawIndexed (a triangle at level L has (L+1)(L+2)/2 evaluation vertices, fewer than a
// window, so the windows' batch size keeps lavapipe within its budget, DESIGN §4).
#pragma once

#include <vulkan/vulkan.h>

#include "gpu_types.hpp"
#include "surface_scene.hpp"

namespace pw::render {

// Binds the pool and the triangle index buffer and issues the draws; patchBase is
// windowCount + first triangle (their PatchData follows the windows'). Returns the number of draws.
uint32_t recordTriangleDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, uint32_t perDraw,
                             DrawPush push);

}  // namespace pw::render

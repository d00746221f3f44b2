#include "render/scene/triangle_draws.hpp"

#include <algorithm>

namespace pw::render {
inline namespace scene {

namespace {

// `count` patches of `points` pool indices each from `indexBuffer`, at most `perDraw` per
// vkCmdDrawIndexed; patch i's gpu::PatchData is entry patchBase0 + i. Returns the number of draws.
uint32_t recordPatchListDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, VkBuffer indexBuffer, uint32_t count,
                              uint32_t points, uint32_t perDraw, uint32_t patchBase0, gpu::DrawPush push) {
    if (count == 0) return 0;
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, s.pool.buffer.ptr(), &zero);
    vkCmdBindIndexBuffer(cmd, indexBuffer, 0, VK_INDEX_TYPE_UINT32);
    perDraw = std::max(perDraw, 1u);
    push.basisKind = gpu::kBasisBezier;
    uint32_t draws = 0;
    for (uint32_t first = 0; first < count; first += perDraw) {
        push.patchBase = patchBase0 + first;
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(gpu::DrawPush), &push);
        vkCmdDrawIndexed(cmd, points * std::min(perDraw, count - first), 1, points * first, 0, 0);
        ++draws;
    }
    return draws;
}

}  // namespace

uint32_t recordTriangleDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, uint32_t perDraw, gpu::DrawPush push) {
    return recordPatchListDraws(cmd, layout, s, s.triIndices.buffer, s.triangleCount, 10, perDraw, s.windowCount, push);
}

uint32_t recordCurveDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, gpu::DrawPush push, uint32_t vertexBudget) {
    const uint32_t perDraw = vertexBudget == 0 ? UINT32_MAX : vertexBudget / 65;
    return recordPatchListDraws(cmd, layout, s, s.curveIndices.buffer, s.curveCount, 4, perDraw, 0, push);
}

}  // namespace scene
}  // namespace pw::render

#include "triangle_draws.hpp"

#include <algorithm>

namespace pw::render {

uint32_t recordTriangleDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, uint32_t perDraw,
                             DrawPush push) {
    if (s.triangleCount == 0) return 0;
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &s.pool.buffer, &zero);
    vkCmdBindIndexBuffer(cmd, s.triIndices.buffer, 0, VK_INDEX_TYPE_UINT32);
    perDraw = std::max(perDraw, 1u);
    push.basisKind = 0;  // Bézier
    uint32_t draws = 0;
    for (uint32_t first = 0; first < s.triangleCount; first += perDraw) {
        const uint32_t n = std::min(perDraw, s.triangleCount - first);
        push.patchBase = s.windowCount + first;
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(DrawPush), &push);
        vkCmdDrawIndexed(cmd, 10 * n, 1, 10 * first, 0, 0);
        ++draws;
    }
    return draws;
}

uint32_t recordCurveDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, DrawPush push,
                          uint32_t vertexBudget) {
    if (s.curveCount == 0) return 0;
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &s.pool.buffer, &zero);
    vkCmdBindIndexBuffer(cmd, s.curveIndices.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(DrawPush), &push);
    const uint32_t perDraw = vertexBudget == 0 ? s.curveCount : std::max(1u, vertexBudget / 65);
    uint32_t draws = 0;
    for (uint32_t first = 0; first < s.curveCount; first += perDraw) {
        vkCmdDrawIndexed(cmd, 4 * std::min(perDraw, s.curveCount - first), 1, 4 * first, 0, 0);
        ++draws;
    }
    return draws;
}

}  // namespace pw::render

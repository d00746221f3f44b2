#include "render/vk/stats.hpp"

#include "render/vk/vk_check.hpp"

#include <cstdlib>
#include <nlohmann/json.hpp>

namespace pw::render {
inline namespace vk {

namespace {
constexpr VkQueryPipelineStatisticFlags kStatFlags =
    VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT | VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT |
    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT | VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT |
    VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_CONTROL_SHADER_PATCHES_BIT |
    VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT;
}

nlohmann::json statsJson(const FrameStats& s) {
    // Grouped as the stats read: pipeline counts, patches and draws, times.
    return {{"triangles", s.triangles()},
            {"clipping_invocations", s.clippingInvocations},
            {"clipping_primitives", s.clippingPrimitives},
            {"tess_eval_invocations", s.tesInvocations},
            {"tess_control_patches", s.tcsPatches},
            {"input_primitives", s.inputPrimitives},
            {"vertex_shader_invocations", s.vsInvocations},
            {"pipeline_statistics", s.pipelineStatsValid},
            {"patches", s.patches},
            {"patches_culled", s.patchesCulled},
            {"cull_test_skipped", s.cullTestSkipped},
            {"merged_windows", s.mergedWindows},
            {"merged_blocks", s.mergedBlocks},
            {"draws", s.draws},
            {"displaced_edges", s.displacedEdges},
            {"displacement_level", s.displacementLevel},
            {"gpu_ms", s.gpuMs},
            {"wall_ms", s.wallMs},
            {"submit_wait_ms", s.submitMs}};
}

std::string statsToJson(const FrameStats& s, int indent) { return statsJson(s).dump(indent); }

FrameQueries::FrameQueries(Device& dev) : dev_(dev) {
    if (dev.caps().timestamps) {
        VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        ci.queryType = VK_QUERY_TYPE_TIMESTAMP;
        ci.queryCount = 2;
        VK_CHECK(vkCreateQueryPool(dev.device(), &ci, nullptr, ts_.replace(dev.device())));
    }
    if (dev.caps().pipelineStatistics) {
        VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        ci.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
        ci.queryCount = 1;
        ci.pipelineStatistics = kStatFlags;
        VK_CHECK(vkCreateQueryPool(dev.device(), &ci, nullptr, stats_.replace(dev.device())));
    }
}

FrameQueries::~FrameQueries() = default;

void FrameQueries::reset(VkCommandBuffer cmd) {
    if (ts_) vkCmdResetQueryPool(cmd, ts_, 0, 2);
    if (stats_) vkCmdResetQueryPool(cmd, stats_, 0, 1);
}
void FrameQueries::timestampBegin(VkCommandBuffer cmd) {
    if (ts_) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, ts_, 0);
}
void FrameQueries::timestampEnd(VkCommandBuffer cmd) {
    if (ts_) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, ts_, 1);
}
void FrameQueries::statsBegin(VkCommandBuffer cmd) {
    if (stats_) vkCmdBeginQuery(cmd, stats_, 0, 0);
}
void FrameQueries::statsEnd(VkCommandBuffer cmd) {
    if (stats_) vkCmdEndQuery(cmd, stats_, 0);
}

void FrameQueries::read(FrameStats& out) {
    if (ts_) {
        uint64_t t[2] = {0, 0};
        if (vkGetQueryPoolResults(dev_.device(), ts_, 0, 2, sizeof(t), t, sizeof(uint64_t),
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS)
            out.gpuMs = double(t[1] - t[0]) * dev_.caps().timestampPeriodNs / 1e6;
    }
    if (stats_) {
        // Results come in the order of the flag bits.
        uint64_t r[6] = {0, 0, 0, 0, 0, 0};
        if (vkGetQueryPoolResults(dev_.device(), stats_, 0, 1, sizeof(r), r, sizeof(r),
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS) {
            out.pipelineStatsValid = true;
            out.inputPrimitives = r[0];
            out.vsInvocations = r[1];
            out.clippingInvocations = r[2];
            out.clippingPrimitives = r[3];
            out.tcsPatches = r[4];
            out.tesInvocations = r[5];
        }
    }
}

OwnedQueryPool makeTransformFeedbackQuery(Device& dev, uint32_t count) {
    VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qci.queryType = VK_QUERY_TYPE_TRANSFORM_FEEDBACK_STREAM_EXT;
    qci.queryCount = count;
    OwnedQueryPool query;
    VK_CHECK(vkCreateQueryPool(dev.device(), &qci, nullptr, query.replace(dev.device())));
    return query;
}

std::array<uint64_t, 2> readTransformFeedbackQuery(Device& dev, VkQueryPool pool, uint32_t index) {
    std::array<uint64_t, 2> prims{0, 0};
    VK_CHECK(vkGetQueryPoolResults(dev.device(), pool, index, 1, sizeof prims, prims.data(), sizeof prims,
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    return prims;
}

}  // namespace vk
}  // namespace pw::render

// DomainView::capture: the domain pattern the fixed tessellator made, read back as primitives
// through VK_EXT_transform_feedback (the CAPTURE variants of domain.tese, rasterisation discarded),
// for vector figures (render/figures/figure_vector.hpp: every triangle the GPU made becomes one
// path) and for capture files (core/io/tess_capture_file.hpp).
#include <algorithm>
#include <cstring>
#include <string>

#include "core/base/errors.hpp"
#include "core/gpu/domain_interface.h"
#include "render/domain/domain_view.hpp"
#include "render/scene/shader_variants.hpp"
#include "render/vk/buffers.hpp"
#include "render/vk/pipeline_builder.hpp"
#include "render/vk/stats.hpp"
#include "shaders/spirv.hpp"

namespace pw::render {
inline namespace domain {

namespace {

constexpr VkDeviceSize kStride = 2 * sizeof(float);

}  // namespace

VkPipeline DomainView::capturePipeline(DomainKind kind, Spacing spacing) {
    const size_t d = size_t(kind), s = size_t(spacingVariant(spacing));
    if (!capturePipes_[d][s]) {
        OwnedShaderModule vert(dev_.device(), makeModule(dev_, spirv::domain_vert()));
        OwnedShaderModule tesc(dev_.device(), makeModule(dev_, spirv::domain_tesc()));
        OwnedShaderModule tese(dev_.device(), makeModule(dev_, spirv::domain_tese(d, s, spirv::domain_tese_output_capture)));
        PipelineDesc pd;
        pd.tess = true;
        pd.patchControlPoints = 1;
        pd.vertexLayout = -1;
        pd.depthTest = pd.depthWrite = false;
        pd.rasterizerDiscard = true;
        pd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert},
                     {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tesc},
                     {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, tese}};
        capturePipes_[d][s] = OwnedPipeline(dev_.device(), buildPipeline(dev_, layout_, VK_NULL_HANDLE, pd, VK_FORMAT_UNDEFINED,
                                                                         VK_FORMAT_UNDEFINED, VK_SAMPLE_COUNT_1_BIT));
    }
    return capturePipes_[d][s].get();
}

TessPattern DomainView::capture(const DomainPane& pane) {
    if (!dev_.caps().transformFeedback)
        throw InputError("vulkan", "device '" + dev_.name() +
                                       "' has no transform feedback (VK_EXT_transform_feedback), which vector figures read "
                                       "the tessellator's primitives through");
    TessPattern out;
    out.kind = pane.kind;
    out.spacing = pane.spacing;
    out.levels = pane.levels;
    const VkDeviceSize vertsPerPrimitive = VkDeviceSize(out.vertsPerPrimitive());
    const VkPipeline pipe = capturePipeline(pane.kind, pane.spacing);
    gpu::DomainPush push{};
    setDomainLevels(push, pane);
    push.transform = {1.0f, 1.0f, 0.0f, 0.0f};
    const DomainCounts want = expectedDomainCounts(pane.kind, pane.levels, pane.spacing, float(dev_.caps().maxTessLevel));
    if (want.culled) return out;

    const OwnedQueryPool query = makeTransformFeedbackQuery(dev_);
    const Device::TransformFeedbackFns& xfb = dev_.transformFeedback();
    // Room for the rules' count (and then some); when the query says more were made, once more at
    // the exact size.
    VkDeviceSize capacity = std::max<VkDeviceSize>(VkDeviceSize(want.primitives) * 2 + 64, 64) * vertsPerPrimitive * kStride;
    for (int attempt = 0;; ++attempt) {
        Buffer buf = createBuffer(dev_, capacity, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT, MemoryUse::Readback);
        dev_.submitAndWait([&](VkCommandBuffer cmd) {
            vkCmdResetQueryPool(cmd, query, 0, 1);
            vkCmdBeginQuery(cmd, query, 0, 0);                     // outside rendering, like the statistics queries
            VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};  // no attachments: nothing is drawn
            ri.renderArea = {{0, 0}, {1, 1}};
            ri.layerCount = 1;
            vkCmdBeginRendering(cmd, &ri);
            const VkViewport vp{0, 0, 1, 1, 0, 1};
            vkCmdSetViewport(cmd, 0, 1, &vp);
            vkCmdSetScissor(cmd, 0, 1, &ri.renderArea);
            const VkDeviceSize zero = 0;
            xfb.bind(cmd, 0, 1, buf.buffer.ptr(), &zero, &capacity);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipe);
            vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof push, &push);
            xfb.begin(cmd, 0, 0, nullptr, nullptr);
            vkCmdDraw(cmd, 1, 1, 0, 0);
            xfb.end(cmd, 0, 0, nullptr, nullptr);
            vkCmdEndRendering(cmd);
            vkCmdEndQuery(cmd, query, 0);
            VkMemoryBarrier hb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            hb.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT;
            hb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &hb, 0, nullptr, 0,
                                 nullptr);
        });
        const std::array<uint64_t, 2> prims = readTransformFeedbackQuery(dev_, query);  // written, needed
        if (prims[1] > prims[0]) {
            if (attempt > 0)
                throw OutputError("(capture)",
                                  "the GPU made " + std::to_string(prims[1]) + " primitives but wrote only " + std::to_string(prims[0]));
            capacity = VkDeviceSize(prims[1]) * vertsPerPrimitive * kStride;
            continue;
        }
        out.uv.resize(size_t(prims[0]) * vertsPerPrimitive);
        std::memcpy(out.uv.data(), buf.mapped, out.uv.size() * kStride);
        return out;
    }
}

}  // namespace domain
}  // namespace pw::render

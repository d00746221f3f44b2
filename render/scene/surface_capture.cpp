// Renderer::captureSurface: the surface pass of a frame with rasterisation discarded and every
// vertex the evaluation shaders emit written to a buffer (VK_EXT_transform_feedback; the CAPTURE
// variants of surface.tese and tri_surface.tese), then welded on the CPU (core/mesh/mesh_weld.hpp).
// Same frame uniforms, control shaders, batching and culling as render(): the triangles are the
// ones the screen shows.
#include <algorithm>
#include <cstring>
#include <string>
#include <utility>

#include "core/base/errors.hpp"
#include "core/mesh/mesh_weld.hpp"
#include "render/scene/renderer.hpp"
#include "render/scene/renderer_impl.hpp"
#include "render/scene/triangle_draws.hpp"
#include "render/vk/pipeline_builder.hpp"
#include "render/vk/stats.hpp"
#include "shaders/spirv.hpp"

namespace pw::render {
inline namespace scene {

namespace {

constexpr VkDeviceSize kStride = sizeof(SoupVertex);  // 36 bytes: position, normal, uv, item

// An upper bound of the bytes a capture writes when no edge has more than `segments` segments:
// 2 s^2 triangles a quad domain, s^2 a triangle domain.
VkDeviceSize captureBound(const SurfaceScene& s, int segments) {
    const VkDeviceSize sq = VkDeviceSize(segments) * VkDeviceSize(segments);
    return (2 * sq * s.windowCount + sq * s.triangleCount) * 3 * kStride;
}

}  // namespace

CapturedSurface Renderer::captureSurface(const RenderOptions& optIn) {
    if (!dev_.caps().transformFeedback)
        throw InputError("vulkan", "device '" + dev_.name() +
                                       "' has no transform feedback (VK_EXT_transform_feedback), which exporting the "
                                       "surface as displayed reads the tessellator's triangles through");
    Impl& m = *impl_;
    RenderOptions opt = optIn;
    opt.display.shading = ShadingMode::Lit;  // no curvature work in the evaluation shader
    opt.mergeWindows = MergeWindows::Never;  // every window its own patch: the capture pipelines read 16 points a patch
    if (opt.lodCamera) {                     // a debug camera's levels and culling are its frozen camera's: capture as that one sees it
        opt.camera = *opt.lodCamera;
        opt.lodCamera.reset();
    }
    const VkRect2D area = paneRect(opt, target_.extent());
    const FramePlan plan = prepareFrame(opt, area);
    const size_t slot = overlayIndex(plan.variant, plan.levels);
    const int disp = m.displaced ? 1 : 0;
    auto& captureWindows = m.captureWindows[size_t(disp)];
    auto& captureTriangles = m.captureTriangles[size_t(disp)];

    // Pipelines on first use: vertex, the frame's control shader, the capture evaluation shader
    // (plain, or displaced by the height map); the triangles' only for a document that has some.
    if (!captureWindows[slot] || (m.scene.triangleCount && !captureTriangles[slot])) {
        const size_t levels = size_t(plan.levels), spacing = size_t(plan.variant), capture = spirv::surface_tese_varyings_capture;
        OwnedShaderModule vert(dev_.device(), makeModule(dev_, spirv::surface_vert()));
        OwnedShaderModule tesc(dev_.device(), makeModule(dev_, spirv::surface_tesc(levels)));
        OwnedShaderModule tese(dev_.device(), makeModule(dev_, spirv::surface_tese(spacing, capture, size_t(disp))));
        OwnedShaderModule ttesc(dev_.device(), makeModule(dev_, spirv::tri_surface_tesc(levels)));
        OwnedShaderModule ttese(dev_.device(), makeModule(dev_, spirv::tri_surface_tese(spacing, capture, size_t(disp))));
        PipelineDesc pd;
        pd.tess = true;
        pd.rasterizerDiscard = true;
        pd.depthTest = pd.depthWrite = false;
        pd.patchControlPoints = 16;
        pd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert},
                     {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tesc},
                     {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, tese}};
        // Rendering without attachments: nothing is drawn, so the capture never touches the target
        // (the editor's swapchain image belongs to its frame).
        const VkFormat none = VK_FORMAT_UNDEFINED;
        if (!captureWindows[slot])
            captureWindows[slot] =
                OwnedPipeline(dev_.device(), buildPipeline(dev_, pipes_.layout, pipes_.cache, pd, none, none, VK_SAMPLE_COUNT_1_BIT));
        pd.patchControlPoints = 10;
        pd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert},
                     {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, ttesc},
                     {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, ttese}};
        if (m.scene.triangleCount)
            captureTriangles[slot] =
                OwnedPipeline(dev_.device(), buildPipeline(dev_, pipes_.layout, pipes_.cache, pd, none, none, VK_SAMPLE_COUNT_1_BIT));
    }

    // The first try holds the bound from the largest segment count these settings can give (capped:
    // adaptive levels bound it by 64); when the query says more were needed, once more at that size.
    int segments = maxSegments(opt.tess, m.scene.overrideMax, plan.maxLevel);
    if (!plan.levelBounds.empty()) segments = *std::max_element(plan.levelBounds.begin(), plan.levelBounds.end());
    VkDeviceSize capacity =
        std::clamp<VkDeviceSize>(captureBound(m.scene, std::max(segments, 1) + 1), 3 * kStride, VkDeviceSize(256) << 20);
    Buffer counter = createBuffer(dev_, 16, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_COUNTER_BUFFER_BIT_EXT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  MemoryUse::Readback);
    const OwnedQueryPool query = makeTransformFeedbackQuery(dev_);
    const Device::TransformFeedbackFns& xfb = dev_.transformFeedback();

    for (int attempt = 0;; ++attempt) {
        Buffer out = createBuffer(dev_, capacity, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT, MemoryUse::Readback);
        VkCommandBuffer cmd = m.cmd;
        VK_CHECK(vkResetCommandBuffer(cmd, 0));
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
        vkCmdResetQueryPool(cmd, query, 0, 1);
        vkCmdFillBuffer(cmd, m.counters.buffer, 0, 16, 0);
        vkCmdFillBuffer(cmd, counter.buffer, 0, 16, 0);
        VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        mb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        mb.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_READ_BIT_EXT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1, &mb, 0, nullptr,
                             0, nullptr);
        vkCmdBeginQuery(cmd, query, 0, 0);  // outside rendering, like the statistics query
        VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
        ri.renderArea = area;
        ri.layerCount = 1;
        vkCmdBeginRendering(cmd, &ri);
        const VkViewport viewport{
            float(area.offset.x), float(area.offset.y), float(area.extent.width), float(area.extent.height), 0.0f, 1.0f};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &area);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes_.layout, 0, 1, &m.set, 0, nullptr);
        const VkDeviceSize zero = 0;
        xfb.bind(cmd, 0, 1, out.buffer.ptr(), &zero, &capacity);
        gpu::DrawPush push;  // the surface pass's: culled patches are counted
        // Windows, then the Bézier triangles resuming where the windows stopped (the counter).
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, captureWindows[slot]);
        xfb.begin(cmd, 0, 0, nullptr, nullptr);
        recordSurfaceDraws(cmd, pipes_.layout, m.scene, plan.perDraw, push, plan.bounds(), plan.budget);
        xfb.end(cmd, 0, 1, counter.buffer.ptr(), &zero);
        if (m.scene.triangleCount) {
            vkCmdEndRendering(cmd);  // no barriers inside dynamic rendering
            VkMemoryBarrier cb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            cb.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT;
            cb.dstAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_READ_BIT_EXT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT, VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1, &cb, 0,
                                 nullptr, 0, nullptr);
            vkCmdBeginRendering(cmd, &ri);
            vkCmdSetViewport(cmd, 0, 1, &viewport);
            vkCmdSetScissor(cmd, 0, 1, &area);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes_.layout, 0, 1, &m.set, 0, nullptr);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, captureTriangles[slot]);
            xfb.begin(cmd, 0, 1, counter.buffer.ptr(), &zero);
            recordTriangleDraws(cmd, pipes_.layout, m.scene, plan.perDraw, push);
            xfb.end(cmd, 0, 1, counter.buffer.ptr(), &zero);
        }
        vkCmdEndRendering(cmd);
        vkCmdEndQuery(cmd, query, 0);
        VkMemoryBarrier hb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        hb.srcAccessMask =
            VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT | VK_ACCESS_SHADER_WRITE_BIT;
        hb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT | VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT,
                             VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &hb, 0, nullptr, 0, nullptr);
        VK_CHECK(vkEndCommandBuffer(cmd));
        submitAndWait(dev_, cmd, m.fence);

        const std::array<uint64_t, 2> prims = readTransformFeedbackQuery(dev_, query);  // written, needed
        if (prims[1] > prims[0]) {
            if (attempt > 0)
                throw OutputError("(capture)",
                                  "the GPU made " + std::to_string(prims[1]) + " triangles but wrote only " + std::to_string(prims[0]));
            capacity = VkDeviceSize(prims[1]) * 3 * kStride;
            continue;
        }
        const uint32_t bytes = *static_cast<const uint32_t*>(counter.mapped);
        const uint64_t vertices = std::min<uint64_t>(bytes / kStride, prims[0] * 3);
        std::vector<SoupVertex> soup(vertices);
        std::memcpy(soup.data(), out.mapped, vertices * kStride);
        // The evaluation shaders declare `ccw`, which Vulkan reads in its upper-left domain origin:
        // seen from the normal (du x dv) side the triangles come out clockwise, so turn them.
        for (size_t t = 0; t + 2 < soup.size(); t += 3) std::swap(soup[t + 1], soup[t + 2]);
        CapturedSurface result;
        result.gpuTriangles = prims[0];
        if (dev_.caps().storesAndAtomics) {
            result.patchesCulled = static_cast<const uint32_t*>(m.counters.mapped)[0];
            result.culledCounted = true;
        }
        WeldStats ws;
        // Seams are bit-identical; poles and collapsed edges agree to float rounding of the model's size.
        // Poles are welded within the tolerance, other edges only where bit-identical (mesh_weld.hpp);
        // the poles of the points as drawn now (a drag updates the pool, not the scene's windows).
        const std::vector<Vec3> points(m.scene.cpuPoints.begin(), m.scene.cpuPoints.end());
        const std::vector<uint8_t> collapsed =
            m.windows.size() == m.scene.windowCount ? collapsedWindowEdges(m.windows, points) : std::vector<uint8_t>{};
        result.mesh = weldTriangleSoup(soup, m.scene.windowCount, m.scene.triangleCount, 1e-6 * std::max(modelSize_, 1e-9), &ws,
                                       collapsed.empty() ? nullptr : &collapsed);
        result.degenerate = ws.degenerateTriangles;
        return result;
    }
}

}  // namespace scene
}  // namespace pw::render

// Renderer::captureSurface: the surface pass of a frame with rasterisation discarded and every
// vertex the evaluation shaders emit written to a buffer (VK_EXT_transform_feedback; the CAPTURE
// variants of surface.tese and tri_surface.tese), then welded on the CPU (core/mesh/mesh_weld.hpp),
// piece by piece while the device makes the next piece.
// Same frame uniforms, control shaders, batching and culling as render(): the triangles are the
// ones the screen shows.
#include <algorithm>
#include <cstdlib>
#include <exception>
#include <limits>
#include <optional>
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
// The capture's pieces (welded while the device makes the next): at most 8, of 4 windows or more
// (the teapot at 64 as displayed: 0.33 s in one piece, 0.26 s in 4 or 8).
constexpr uint32_t kMaxPieces = 8, kWindowsPerPiece = 4;

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
    // A smaller first try, so that tests can take the second try's path.
    if (const char* first = std::getenv("PATCHWORK_CAPTURE_FIRST_BYTES"))
        capacity = std::clamp<VkDeviceSize>(std::strtoull(first, nullptr, 10), 3 * kStride, capacity);
    // The windows in pieces, each its own submission: the CPU welds one piece while the device
    // makes the next (on lavapipe the tessellator runs on the queue's thread). Each piece resumes
    // the transform feedback where the one before stopped and leaves its end in its own counter,
    // so the pieces lie one after the other in `out`, in window order; the Bézier triangles come last.
    const uint32_t windows = m.scene.windowCount;
    const uint32_t pieces = std::clamp<uint32_t>(windows / kWindowsPerPiece, 1, kMaxPieces);
    std::vector<std::vector<uint8_t>> skips(pieces > 1 ? pieces : 0);
    for (uint32_t k = 0; k < skips.size(); ++k) {
        skips[k].assign(windows, 1);
        std::fill(skips[k].begin() + windows * k / pieces, skips[k].begin() + windows * (k + 1) / pieces, uint8_t(0));
    }
    Buffer counter =
        createBuffer(dev_, 4 * VkDeviceSize(pieces),
                     VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_COUNTER_BUFFER_BIT_EXT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
    const OwnedQueryPool query = makeTransformFeedbackQuery(dev_, pieces);
    std::vector<OwnedCommandBuffer> cmds;
    std::vector<OwnedFence> fences(pieces);
    for (uint32_t k = 0; k < pieces; ++k) {
        cmds.emplace_back(dev_.device(), dev_.commandPool());
        VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(dev_.device(), &fci, nullptr, fences[k].replace(dev_.device())));
    }
    // Seams are bit-identical; poles and collapsed edges agree to float rounding of the model's size.
    // Poles are welded within the tolerance, other edges only where bit-identical (mesh_weld.hpp);
    // the poles of the points as drawn now (a drag updates the pool, not the scene's windows).
    const std::vector<Vec3> points(m.scene.cpuPoints.begin(), m.scene.cpuPoints.end());
    const std::vector<uint8_t> collapsed = m.windows.size() == windows ? collapsedWindowEdges(m.windows, points) : std::vector<uint8_t>{};
    const double tolerance = 1e-6 * std::max(modelSize_, 1e-9);

    for (int attempt = 0;; ++attempt) {
        Buffer out = createBuffer(dev_, capacity, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT, MemoryUse::Readback);
        // Pieces already submitted may still be running when something throws (a submission, the
        // weld): let the device finish before anything they use is released.
        struct IdleOnThrow {
            VkQueue queue;
            int exceptions = std::uncaught_exceptions();
            ~IdleOnThrow() {
                if (std::uncaught_exceptions() > exceptions) vkQueueWaitIdle(queue);
            }
        } idleOnThrow{dev_.queue()};
        for (uint32_t k = 0; k < pieces; ++k) {
            VkCommandBuffer cmd = cmds[k];
            VK_CHECK(vkResetFences(dev_.device(), 1, fences[k].ptr()));  // signalled by the try before
            VK_CHECK(vkResetCommandBuffer(cmd, 0));
            VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
            VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
            recordCapturePiece(cmd, k, pieces, skips.empty() ? nullptr : &skips[k], out.buffer, capacity, counter.buffer, query,
                               captureWindows[slot], captureTriangles[slot], plan, area);
            VK_CHECK(vkEndCommandBuffer(cmd));
            VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
            si.commandBufferCount = 1;
            si.pCommandBuffers = cmds[k].ptr();
            VK_CHECK(vkQueueSubmit(dev_.queue(), 1, &si, fences[k]));
        }

        // Each piece as it completes: its triangles, welded while the device makes the next. Its
        // counter says where it stopped (whole triangles); the queries, which say whether the
        // buffer was too small, are read once the last piece is done (lavapipe waits for the whole
        // queue to read one).
        std::optional<SoupWelder> welder;
        uint64_t begin = 0;
        bool full = false;  // a counter past the buffer: what follows is not welded (the queries will ask for more)
        for (uint32_t k = 0; k < pieces; ++k) {
            VK_CHECK(vkWaitForFences(dev_.device(), 1, fences[k].ptr(), VK_TRUE, UINT64_MAX));
            const uint64_t end = static_cast<const uint32_t*>(counter.mapped)[k];
            full = full || end > capacity;
            if (full) continue;
            const uint64_t vertices = (end - std::min<uint64_t>(begin, end)) / (3 * kStride) * 3;
            if (!welder)
                welder.emplace(windows, m.scene.triangleCount, tolerance, collapsed.empty() ? nullptr : &collapsed,
                               size_t(vertices) * pieces);
            // The evaluation shaders declare `ccw`, which Vulkan reads in its upper-left domain
            // origin: seen from the normal (du x dv) side the triangles come out clockwise, so turn them.
            welder->add(reinterpret_cast<const SoupVertex*>(static_cast<const char*>(out.mapped) + begin), size_t(vertices),
                        SoupWinding::Turned);
            begin = std::max<uint64_t>(begin, end);
        }
        uint64_t written = 0, needed = 0;
        for (uint32_t k = 0; k < pieces; ++k) {
            const std::array<uint64_t, 2> prims = readTransformFeedbackQuery(dev_, query, k);  // written, needed
            written += prims[0];
            needed += prims[1];
        }
        if (needed > written) {  // the buffer was too small: once more at the size needed
            if (attempt > 0)
                throw OutputError("(capture)",
                                  "the GPU made " + std::to_string(needed) + " triangles but wrote only " + std::to_string(written));
            capacity = VkDeviceSize(needed) * 3 * kStride;
            if (capacity > std::numeric_limits<uint32_t>::max())  // the counters are 32-bit byte offsets
                throw OutputError("(capture)", "the surface as displayed has " + std::to_string(needed) +
                                                   " triangles, more than one capture holds (4 GiB); lower the document's levels");
            continue;
        }
        CapturedSurface result;
        result.gpuTriangles = written;
        if (dev_.caps().storesAndAtomics) {
            result.patchesCulled = static_cast<const uint32_t*>(m.counters.mapped)[0];
            result.culledCounted = true;
        }
        WeldStats ws;
        result.mesh = welder->finish(&ws);
        result.degenerate = ws.degenerateTriangles;
        return result;
    }
}

// Piece k of `pieces` of the capture (its windows: those `skip` leaves; all when null), into `out`
// from where the piece before stopped (its counter), its end into counter k, counted by query k.
// The first piece clears the queries and counters; the last also captures the Bézier triangles.
void Renderer::recordCapturePiece(VkCommandBuffer cmd, uint32_t k, uint32_t pieces, const std::vector<uint8_t>* skip, VkBuffer out,
                                  VkDeviceSize capacity, VkBuffer counter, VkQueryPool query, VkPipeline windowsPipe,
                                  VkPipeline trianglesPipe, const FramePlan& plan, const VkRect2D& area) {
    Impl& m = *impl_;
    const Device::TransformFeedbackFns& xfb = dev_.transformFeedback();
    const VkDeviceSize zero = 0, before = 4 * VkDeviceSize(k ? k - 1 : 0), mine = 4 * VkDeviceSize(k);
    VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    if (k == 0) {
        vkCmdResetQueryPool(cmd, query, 0, pieces);
        vkCmdFillBuffer(cmd, m.counters.buffer, 0, 16, 0);
        vkCmdFillBuffer(cmd, counter, 0, VK_WHOLE_SIZE, 0);
        mb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        mb.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_READ_BIT_EXT |
                           VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT |
                                 VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT,
                             0, 1, &mb, 0, nullptr, 0, nullptr);
    } else {  // the piece before's end counter and culled count, written in an earlier submission
        mb.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT | VK_ACCESS_SHADER_WRITE_BIT;
        mb.dstAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_READ_BIT_EXT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT | VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT,
                             VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT, 0, 1, &mb, 0, nullptr,
                             0, nullptr);
    }
    vkCmdBeginQuery(cmd, query, k, 0);  // outside rendering, like the statistics query
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = area;
    ri.layerCount = 1;
    const VkViewport viewport{float(area.offset.x), float(area.offset.y), float(area.extent.width), float(area.extent.height), 0.0f, 1.0f};
    const auto beginRendering = [&] {
        vkCmdBeginRendering(cmd, &ri);
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &area);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes_.layout, 0, 1, &m.set, 0, nullptr);
    };
    beginRendering();
    xfb.bind(cmd, 0, 1, &out, &zero, &capacity);
    gpu::DrawPush push;  // the surface pass's: culled patches are counted
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, windowsPipe);
    if (k == 0)
        xfb.begin(cmd, 0, 0, nullptr, nullptr);
    else
        xfb.begin(cmd, 0, 1, &counter, &before);
    recordSurfaceDraws(cmd, pipes_.layout, m.scene, plan.perDraw, push, plan.bounds(), plan.budget, skip);
    xfb.end(cmd, 0, 1, &counter, &mine);
    if (k + 1 == pieces && m.scene.triangleCount) {  // resuming where the windows stopped
        vkCmdEndRendering(cmd);                      // no barriers inside dynamic rendering
        VkMemoryBarrier cb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        cb.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT;
        cb.dstAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_READ_BIT_EXT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT, VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1, &cb, 0, nullptr,
                             0, nullptr);
        beginRendering();
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, trianglesPipe);
        xfb.begin(cmd, 0, 1, &counter, &mine);
        recordTriangleDraws(cmd, pipes_.layout, m.scene, plan.perDraw, push);
        xfb.end(cmd, 0, 1, &counter, &mine);
    }
    vkCmdEndRendering(cmd);
    vkCmdEndQuery(cmd, query, k);
    VkMemoryBarrier hb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    hb.srcAccessMask =
        VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT | VK_ACCESS_SHADER_WRITE_BIT;
    hb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT | VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT,
                         VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &hb, 0, nullptr, 0, nullptr);
}

}  // namespace scene
}  // namespace pw::render

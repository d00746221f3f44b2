// The renderer's private state and per-frame setup, shared by its two files: renderer.cpp (frames)
// and surface_capture.cpp (the tessellator's triangles read back through transform feedback).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "core/model/camera_math.hpp"
#include "render/scene/height_texture.hpp"
#include "render/scene/merged_blocks.hpp"
#include "render/scene/overlays.hpp"
#include "render/scene/pipelines.hpp"
#include "render/scene/plain_mesh.hpp"
#include "render/scene/renderer.hpp"
#include "render/scene/surface_scene.hpp"
#include "render/vk/buffers.hpp"
#include "render/vk/stats.hpp"
#include "render/vk/vk_check.hpp"
#include "render/vk/vk_owned.hpp"

namespace pw::render {
inline namespace scene {

struct Renderer::Impl {
    SurfaceScene scene;
    std::vector<PatchInstance> windows;  // the scene's windows, for the capture's collapsed edges
    OverlayScene overlays;
    PlainMesh mesh;
    Buffer frameUbo, counters;
    Buffer ground;  // ground grid vertices (position + rgba) for groundStep / groundZUp
    uint32_t groundVertexCount = 0;
    Buffer frustum;  // the debug camera's frustum lines of the last frame that drew them (rewritten each such frame)
    uint32_t frustumVertexCount = 0;
    double groundStep = 0.0;
    bool groundZUp = true;
    OwnedDescriptorPool descPool;
    VkDescriptorSet set = VK_NULL_HANDLE;  // freed with descPool
    std::unique_ptr<FrameQueries> queries;
    OwnedCommandBuffer cmd;
    OwnedFence fence;
    // Transform-feedback pipelines (windows, then Bézier triangles; by overlayIndex), made on first capture.
    // [0] plain, [1] displaced.
    std::array<std::array<OwnedPipeline, kSpacingVariants * kLevelsVariants>, 2> captureWindows, captureTriangles;
    // Displacement (DESIGN §11): the map, its texture (binding 3; 1 x 1 zero without one) and the
    // frame uniforms' displace and planar vectors, all from the last setDocument.
    std::shared_ptr<const HeightMap> map;
    HeightTexture height;
    std::vector<HeightMap> mips;  // the map's mip levels (core/model/height_map.hpp heightMipChain), made once per map
    bool displaced = false;
    glm::vec4 displace{0.0f}, planar{0.0f};
    glm::vec4 heightLod{0.0f};  // the frame's heightLod when band limiting is on (core/gpu/gpu_interface.h)
    std::vector<Join> joins;    // the document's, for the curvature graph across a join (windows = patch indices)
    Buffer blocks;              // this frame's merged blocks (render/scene/merged_blocks.hpp), HostWritten
    Buffer placeholder;         // bound where the scene has no buffer yet (no windows)
    // Bindings 4..7: the pool and window indices as storage, the blocks, the trim segments.
    std::array<const Buffer*, 4> mergedBuffers() const {
        const auto or_ = [&](const Buffer& b) { return b.buffer ? &b : &placeholder; };
        return {or_(scene.pool), or_(scene.indices), or_(blocks), or_(scene.trimSegments)};
    }
};

// Submits `cmd` to the device's queue and waits for it on `fence` (reset first).
inline void submitAndWait(Device& dev, VkCommandBuffer cmd, VkFence fence) {
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    VK_CHECK(vkResetFences(dev.device(), 1, &fence));
    VK_CHECK(vkQueueSubmit(dev.queue(), 1, &si, fence));
    VK_CHECK(vkWaitForFences(dev.device(), 1, &fence, VK_TRUE, UINT64_MAX));
}

// What a frame's draws need besides the frame uniforms (written by Renderer::prepareFrame).
struct Renderer::FramePlan {
    ViewMatrices vm;
    int variant = 0;  // spacing variant
    LevelsVariant levels = LevelsVariant::Fixed;
    bool cullTestSkipped = false;  // FrameStats::cullTestSkipped
    // Windows culled on the CPU (render/scene/view_culling.hpp): when not empty, the windows go in
    // two draws, the fixed-level control shader for those wholly inside (skipInside 0) and the full
    // one for those near a plane (skipTested 0); windows wholly outside are in neither.
    std::vector<uint8_t> skipTested, skipInside;
    std::vector<uint8_t> skipCulled;  // the overlays' one draw in window order: the culled windows (and merged) left out
    uint32_t windowsCulled = 0, windowsInside = 0;
    float maxLevel = 64.0f;
    uint32_t budget = 0, perDraw = 1;   // evaluation vertices per draw (0: no limit), windows per draw
    std::vector<uint8_t> levelBounds;   // adaptive: batch by this frame's levels, not by the worst case
    std::optional<ViewMatrices> lodVm;  // a debug camera's (RenderOptions::lodCamera), whose frustum is drawn
    MergedBlocks merged;                // windows drawn several to a patch (render/scene/merged_blocks.hpp)
    double frustumDepth = 0.0;
    const std::vector<uint8_t>* bounds() const { return levelBounds.empty() ? nullptr : &levelBounds; }
};

}  // namespace scene
}  // namespace pw::render

#include "render/scene/renderer.hpp"
#include "render/scene/renderer_impl.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/base/point_upload.hpp"
#include "core/eval/displacement.hpp"
#include "core/gpu/gpu_interface.h"
#include "core/model/camera_math.hpp"
#include "core/tess/tess_levels.hpp"
#include "render/scene/adaptive_bounds.hpp"
#include "render/scene/frame_passes.hpp"
#include "render/scene/merged_blocks.hpp"
#include "render/scene/overlays.hpp"
#include "render/scene/plain_mesh.hpp"
#include "render/scene/shader_variants.hpp"
#include "render/scene/surface_scene.hpp"
#include "render/scene/triangle_draws.hpp"
#include "render/scene/view_culling.hpp"
#include "render/vk/buffers.hpp"
#include "render/vk/vk_owned.hpp"

namespace pw::render {
inline namespace scene {

RenderOptions optionsFromDocument(const Document& doc) {
    RenderOptions o;
    o.tess = doc.tess;
    o.display = doc.display;
    o.camera = doc.camera;
    o.displacementScale = doc.displacement.scale;
    o.displacementBias = doc.displacement.bias;
    return o;
}

VkRect2D paneRect(const RenderOptions& opt, VkExtent2D extent) {
    const auto& r = opt.pane;
    const int x0 = std::clamp(r[0], 0, int(extent.width)), y0 = std::clamp(r[1], 0, int(extent.height));
    const int x1 = std::clamp(r[0] + std::max(r[2], 0), x0, int(extent.width));
    const int y1 = std::clamp(r[1] + std::max(r[3], 0), y0, int(extent.height));
    if (x1 - x0 < 1 || y1 - y0 < 1) return {{0, 0}, extent};
    return {{x0, y0}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}};
}

namespace {

void writeDescriptors(Device& dev, VkDescriptorSet set, const Buffer& ubo, const Buffer& patches, const Buffer& counters,
                      const HeightTexture& height, const std::array<const Buffer*, 4>& merged) {
    // 0 frame uniforms, 1 patch data, 2 counters, 4..6 the merged blocks' pool, window indices and
    // blocks, 7 the trim segments.
    const Buffer* storage[8] = {&ubo, &patches, &counters, nullptr, merged[0], merged[1], merged[2], merged[3]};
    VkDescriptorBufferInfo infos[8];
    VkWriteDescriptorSet w[8];
    for (uint32_t i = 0; i < 8; ++i) {
        w[i] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w[i].dstSet = set;
        w[i].dstBinding = i;
        w[i].descriptorCount = 1;
        if (i == 3) continue;
        infos[i] = {storage[i]->buffer, 0, VK_WHOLE_SIZE};
        w[i].descriptorType = i == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w[i].pBufferInfo = &infos[i];
    }
    const VkDescriptorImageInfo image{height.sampler, height.image.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    w[3].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w[3].pImageInfo = &image;
    vkUpdateDescriptorSets(dev.device(), 8, w, 0, nullptr);
}

}  // namespace

Renderer::Renderer(Device& dev, RenderTarget& target) : dev_(dev), target_(target), impl_(std::make_unique<Impl>()) {
    pipes_ = createPipelines(dev, target.colorFormat(), target.depthFormat(), target.samples());
    Impl& m = *impl_;
    m.frameUbo = createBuffer(dev, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::HostWritten);
    m.counters = createBuffer(dev, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
    std::memset(m.counters.mapped, 0, 16);
    m.scene.patchData = uploadStatic(dev, std::vector<gpu::PatchData>(1), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

    m.height = uploadHeightTexture(dev, nullptr, {});
    m.placeholder = uploadStatic(dev, std::vector<uint32_t>(4, 0u), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    VkDescriptorPoolSize sizes[3] = {
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 6}, {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
    VkDescriptorPoolCreateInfo dp{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dp.maxSets = 1;
    dp.poolSizeCount = 3;
    dp.pPoolSizes = sizes;
    VK_CHECK(vkCreateDescriptorPool(dev.device(), &dp, nullptr, m.descPool.replace(dev.device())));
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = m.descPool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &pipes_.setLayout;
    VK_CHECK(vkAllocateDescriptorSets(dev.device(), &ai, &m.set));
    writeDescriptors(dev, m.set, m.frameUbo, m.scene.patchData, m.counters, m.height, m.mergedBuffers());

    m.queries = std::make_unique<FrameQueries>(dev);
    m.cmd = OwnedCommandBuffer(dev.device(), dev.commandPool());
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(dev.device(), &fci, nullptr, m.fence.replace(dev.device())));
}

Renderer::~Renderer() {
    vkDeviceWaitIdle(dev_.device());
    impl_.reset();  // buffers, queries, pool, fence: each frees itself; then the pipelines
}

void Renderer::setDocument(const Document& doc, std::shared_ptr<const HeightMap> map) {
    vkDeviceWaitIdle(dev_.device());
    Impl& m = *impl_;
    const DisplacementSettings& ds = doc.displacement;
    if (!ds.active() || (map && map->empty())) map.reset();
    if (map != m.map) {
        m.mips = map ? heightMipChain(*map, 32) : std::vector<HeightMap>{};  // the texture's levels and the edges' detail
        m.height = uploadHeightTexture(dev_, map.get(), m.mips);
        m.map = map;
    }
    m.displaced = bool(m.map);
    m.scene = uploadSurfaceScene(dev_, doc, m.map.get(), &m.mips);
    m.windows = expandPatches(doc);
    m.overlays = uploadOverlayScene(dev_, doc);
    m.joins = doc.joins;
    const std::array<double, 4> rect = planarRect(doc);
    m.displace = {0.0f, 0.0f, ds.mapping == DisplacementMapping::Planar ? 1.0f : 0.0f, doc.camera.zUp ? 1.0f : 0.0f};
    m.planar = {float(rect[0]), float(rect[1]), float(1.0 / rect[2]), float(1.0 / rect[3])};
    m.heightLod = {float(mapTexelsPerUnit(doc, m.windows, m.map.get())),
                   float(std::min<uint32_t>(m.height.levels - 1, uint32_t(gpu::kHeightDetailLevels))), 0.0f, 0.0f};
    if (m.displaced) ensureDisplacedPipelines(dev_, pipes_);
    // Merged blocks: at most one per 2 windows, written each frame that merges.
    m.blocks =
        createBuffer(dev_, sizeof(glm::uvec4) * (m.scene.windowCount / 2 + 1), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostWritten);
    writeDescriptors(dev_, m.set, m.frameUbo, m.scene.patchData, m.counters, m.height, m.mergedBuffers());
    modelSize_ = pw::modelSize(doc);
}

void Renderer::setPlainMesh(const TriangleMesh& mesh) {
    vkDeviceWaitIdle(dev_.device());
    impl_->mesh = uploadPlainMesh(dev_, mesh);
}

void Renderer::updatePoints(const std::vector<Vec3>& points, const std::vector<uint32_t>& changed) {
    SurfaceScene& s = impl_->scene;
    std::vector<uint32_t> valid;
    valid.reserve(changed.size());
    for (uint32_t i : changed)
        if (i < s.pointCount && i < points.size()) valid.push_back(i);
    writePoolPositions(points, valid, static_cast<float*>(s.pool.mapped));  // the weights stay: a drag moves points only
    for (uint32_t i : valid)
        if (i < s.cpuPoints.size()) s.cpuPoints[i] = glm::vec3(points[i]);
}

bool Renderer::mergingWanted(const RenderOptions& opt) const {
    const Impl& m = *impl_;
    const bool device = opt.mergeWindows == MergeWindows::Always ||
                        (opt.mergeWindows == MergeWindows::Auto && dev_.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU);
    const DisplaySettings& ds = opt.display;
    const TessSettings& ts = opt.tess;
    // A vertex on a seam inside a block is evaluated on one of its two windows, so only what is
    // continuous there may be drawn: position and normal (lean varyings), not UV, patch id or curvature.
    return device && !m.scene.nets.empty() && !m.displaced && !opt.plainMesh && !opt.rawTessellator && !opt.lodCamera &&
           !ds.showWireframe && !ds.showNormals && varyingsVariant(ds.shading) == VaryingsVariant::Lean && m.scene.trimmedWindows == 0 &&
           !(ts.adaptive == AdaptiveMode::Distance && ts.distanceFrom != DistanceFrom::Edges);
}

void Renderer::updateLevels(const Document& doc) {
    Impl& m = *impl_;
    const std::vector<PatchInstance> inst = expandPatches(doc);
    if (inst.size() != m.scene.windowCount || doc.triangles.size() != m.scene.triangleCount || doc.points.size() != m.scene.pointCount ||
        m.scene.trimmedWindows > 0)  // trims: their segments are uploaded with the scene
        return setDocument(doc, m.map);
    const std::vector<gpu::PatchData> pd = windowPatchData(doc, inst, m.map.get(), &m.mips, m.scene);
    const VkDeviceSize bytes = sizeof(gpu::PatchData) * pd.size();
    if (m.scene.patchData.mapped && bytes > 0) {  // the previous frame has completed (render waits for it)
        std::memcpy(m.scene.patchData.mapped, pd.data(), bytes);
        const VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, m.scene.patchData.memory.get(), 0, VK_WHOLE_SIZE};
        VK_CHECK(vkFlushMappedMemoryRanges(dev_.device(), 1, &range));
        return;
    }
    vkDeviceWaitIdle(dev_.device());
    m.scene.patchData = uploadStatic(dev_, pd, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    writeDescriptors(dev_, m.set, m.frameUbo, m.scene.patchData, m.counters, m.height, m.mergedBuffers());
}

Renderer::FramePlan Renderer::prepareFrame(const RenderOptions& opt, VkRect2D area) {
    Impl& m = *impl_;
    const VkExtent2D ext = area.extent;
    const TessSettings& ts = opt.tess;
    const DisplaySettings& ds = opt.display;
    FramePlan plan;
    const ViewMatrices vm = viewMatrices(opt.camera, double(ext.width) / double(ext.height));
    gpu::FrameUniforms fu{};
    fu.viewProj = vm.viewProj;
    fu.view = vm.view;
    fu.eye = glm::vec4(vm.eye, 1.0f);
    const ViewMatrices lod = opt.lodCamera ? viewMatrices(*opt.lodCamera, double(ext.width) / double(ext.height)) : vm;
    fu.lodViewProj = lod.viewProj;
    fu.lodEye = glm::vec4(lod.eye, opt.lodCamera ? 1.0f : 0.0f);
    const glm::vec3 light(ds.lightDir[0], ds.lightDir[1], ds.lightDir[2]);
    const float lightLen = glm::length(light);
    const glm::vec3 lightUnit = lightLen > 1e-12f && std::isfinite(lightLen) ? light / lightLen : glm::vec3(0.0f, 0.0f, 1.0f);
    fu.lightDir = glm::vec4(lightUnit, ds.normalLength);
    // View rays: inverse(viewProj) * (x, y, 1, 1) is linear in the NDC x and y, and so is its
    // direction from the eye, h.xyz - eye * h.w. Orthographic rays are all the view direction.
    if (opt.camera.orthographic) {
        fu.rayX = fu.rayY = glm::vec4(0.0f);
        fu.rayZ = glm::vec4(vm.forward, 0.0f);
    } else {
        const glm::mat4 inv = glm::inverse(vm.viewProj);
        auto ray = [&](const glm::vec4& h) { return glm::vec4(glm::vec3(h) - vm.eye * h.w, 0.0f); };
        fu.rayX = ray(inv[0]);
        fu.rayY = ray(inv[1]);
        fu.rayZ = ray(inv[2] + inv[3]);
    }
    fu.viewport = {float(ext.width), float(ext.height), float(area.offset.x), float(area.offset.y)};
    fu.outer = {ts.outer[0], ts.outer[1], ts.outer[2], ts.outer[3]};
    const float maxLevel = std::clamp(std::min(ts.maxLevel, float(dev_.caps().maxTessLevel)), 1.0f, 64.0f);
    fu.inner = {ts.inner[0], ts.inner[1], maxLevel, ts.targetPixels};
    fu.dist = {ts.distanceNear, ts.distanceFar, float(4.0 / std::max(modelSize_, 1e-9)), 12.0f};
    fu.dist.z = float(std::max(modelSize_, 1e-9) / 4.0);
    fu.distModes = {uint32_t(ts.distanceCurve), uint32_t(ts.distanceFrom), 0u, 0u};
    fu.lodDist = {ts.distanceExponents[0], ts.distanceExponents[1], 0.0f, 0.0f};
    fu.modes = {uint32_t(ts.spacing), uint32_t(ts.adaptive),
                (ts.cullBackfaces ? gpu::kCullBackFaces : 0u) | (ts.cullOffscreen ? gpu::kCullOffscreen : 0u) |
                    (ts.cullFar ? gpu::kCullFar : 0u) | (ts.heightDetail ? 0u : gpu::kKeepHeightLevels),
                uint32_t(ds.shading)};
    fu.sel = {opt.hoveredPoint >= 0 ? uint32_t(opt.hoveredPoint) : gpu::kNoPoint,
              opt.selectedPoint >= 0 ? uint32_t(opt.selectedPoint) : gpu::kNoPoint, m.scene.pointCount, 0u};
    fu.isoline = {ts.isolineLevels[0], ts.isolineLevels[1], 0.0f, 0.0f};
    // Without a map nothing is displaced: no scale or bias, so the culling margin is 0 (as on the CPU).
    fu.displace = m.displaced ? glm::vec4(opt.displacementScale, opt.displacementBias, m.displace.z, m.displace.w)
                              : glm::vec4(0.0f, 0.0f, m.displace.z, m.displace.w);
    fu.planar = m.planar;
    // Band-limited displacement with adaptive levels that follow the map's detail (DESIGN §11).
    const bool bandLimit = m.displaced && ts.adaptive != AdaptiveMode::None && ts.heightDetail;
    fu.heightLod = bandLimit ? m.heightLod : glm::vec4(0.0f);
    fu.comb = {float(combToothLength(ds, modelSize_)), float(std::clamp(ds.combDensity, 2, 21)), 5.0f, 0.0f};
    std::memcpy(m.frameUbo.mapped, &fu, sizeof(fu));
    plan.vm = vm;
    if (opt.lodCamera) {  // the frustum out to the far distance in distance mode, else just past the farthest control point
        plan.lodVm = lod;
        double reach = opt.lodCamera->distance;
        for (const glm::vec3& p : m.scene.cpuPoints) reach = std::max(reach, double(glm::dot(p - lod.eye, lod.forward)));
        plan.frustumDepth = opt.lodFrustumDepth > 0.0               ? opt.lodFrustumDepth
                            : ts.adaptive == AdaptiveMode::Distance ? double(ts.distanceFar)
                                                                    : 1.05 * reach;
    }
    plan.variant = spacingVariant(ts.spacing);
    plan.levels = levelsVariant(ts);
    // Uniform levels whose only culling is off-screen, with every control point inside the deciding
    // camera's frustum: no patch can be culled, so the control shader without the per-patch test
    // draws the same frame (the framed model, the usual view; on an H200 the test cost grid128 ~5 %).
    const bool fixedAllowed = ts.adaptive == AdaptiveMode::None && !ts.cullBackfaces;
    const bool cpuCulling =
        plan.levels == LevelsVariant::Full && ts.cullOffscreen && !m.displaced && !opt.lodCamera && !opt.plainMesh && !opt.rawTessellator;
    const PointsBox box = cpuCulling ? pointsBox(m.scene.cpuPoints) : PointsBox{};
    const bool wholeInside = cpuCulling && insideFrustum(box, lod.viewProj);
    if (wholeInside && fixedAllowed) {
        plan.levels = LevelsVariant::Fixed;
        plan.cullTestSkipped = true;
    }
    plan.maxLevel = maxLevel;
    plan.budget = dev_.drawVertexBudget();
    plan.perDraw = patchesPerDraw(maxSegments(ts, m.scene.overrideMax, maxLevel), plan.budget);
    // (Displaced windows batch by the worst case: the map's detail may raise any edge to the maximum.)
    const bool merge = mergingWanted(opt);
    std::vector<DirectionLevels> uniform;
    if (ts.adaptive != AdaptiveMode::None && !m.displaced)
        plan.levelBounds = adaptiveLevelBounds(m.scene, ts, lod, float(ext.width), float(ext.height), maxLevel, merge ? &uniform : nullptr);
    else if (merge)
        uniform = settingsWindowLevels(m.scene, ts);
    if (merge) {
        plan.merged = planMergedBlocks(m.scene, uniform, ts, lod, float(dev_.caps().maxTessLevel), dev_.caps().fixedPointTessellator);
        if (!plan.merged.blocks.empty())
            std::memcpy(m.blocks.mapped, plan.merged.blocks.data(), sizeof(glm::uvec4) * plan.merged.blocks.size());
    }
    // The frustum cuts the scene: windows wholly outside are not drawn, wholly inside ones skip the
    // per-patch test (uniform levels), only the rest run it (render/scene/view_culling.hpp).
    if (cpuCulling && !wholeInside && m.scene.windowCount > 0) {
        WindowCulling c = classifyWindows(m.scene, box, lod.viewProj, fixedAllowed, plan.merged.windows ? &plan.merged.merged : nullptr);
        if (c.outside > 0 || c.inside > 0) {
            plan.windowsCulled = c.outside;
            plan.windowsInside = c.inside;
            plan.skipTested = std::move(c.skipTested);
            plan.skipInside = std::move(c.skipInside);
            plan.skipCulled = std::move(c.skipCulled);
        }
    }
    return plan;
}

FrameStats Renderer::render(const RenderOptions& opt) {
    Impl& m = *impl_;
    FrameStats stats;
    const auto t0 = std::chrono::steady_clock::now();
    const VkRect2D area = paneRect(opt, target_.extent());
    const VkExtent2D ext = area.extent;  // the pane's size: aspect, pixel sizes
    const DisplaySettings& ds = opt.display;

    // Step 1: frame uniforms, shader variants, batching.
    const FramePlan plan = prepareFrame(opt, area);

    // Step 2: record.
    VkCommandBuffer cmd = m.cmd;
    VK_CHECK(vkResetCommandBuffer(cmd, 0));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    m.queries->reset(cmd);
    vkCmdFillBuffer(cmd, m.counters.buffer, 0, 16, 0);
    VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    mb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    mb.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT, 0, 1, &mb, 0, nullptr, 0,
                         nullptr);
    m.queries->timestampBegin(cmd);
    m.queries->statsBegin(cmd);
    const std::array<float, 4> background{ds.background[0], ds.background[1], ds.background[2], 1.0f};
    VkViewport viewport{float(area.offset.x), float(area.offset.y), float(ext.width), float(ext.height), 0.0f, 1.0f};
    const VkRect2D scissor = area;
    if (opt.keepTarget) {  // a later pane: the others stay, this rectangle starts from the background
        target_.resumeRendering(cmd);
        VkClearAttachment clears[2] = {{VK_IMAGE_ASPECT_COLOR_BIT, 0, {}}, {VK_IMAGE_ASPECT_DEPTH_BIT, 0, {}}};
        clears[0].clearValue.color = {{background[0], background[1], background[2], background[3]}};
        clears[1].clearValue.depthStencil = {1.0f, 0};
        const VkClearRect rect{area, 0, 1};
        vkCmdClearAttachments(cmd, 2, clears, 1, &rect);
    } else {
        target_.beginRendering(cmd, background);
    }
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes_.layout, 0, 1, &m.set, 0, nullptr);

    // Step 3: the surface (statistics cover this pass only), then the overlays (FramePasses).
    FramePasses::Frame frame{
        cmd, dev_, opt, plan, m, pipes_, pipes_.tess[m.displaced ? 1 : 0], varyingsVariant(ds.shading, m.scene.trimmedWindows > 0), stats};
    FramePasses::surface(frame);
    // Step 4: overlays, after the statistics query ends (outside rendering, see stats.hpp).
    bool anyOverlay = false;
    for (const FramePasses::Pass& pass : FramePasses::overlays()) anyOverlay = anyOverlay || pass.wanted(frame);
    if (anyOverlay) {
        target_.pauseRendering(cmd);
        m.queries->statsEnd(cmd);
        target_.resumeRendering(cmd);
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes_.layout, 0, 1, &m.set, 0, nullptr);
    }
    for (const FramePasses::Pass& pass : FramePasses::overlays())
        if (pass.wanted(frame)) pass.record(frame);
    target_.endRendering(cmd);
    if (!anyOverlay) m.queries->statsEnd(cmd);
    m.queries->timestampEnd(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));

    // Step 5: submit and wait.
    const auto t1 = std::chrono::steady_clock::now();
    submitAndWait(dev_, cmd, m.fence);
    const auto t2 = std::chrono::steady_clock::now();
    stats.wallMs = std::chrono::duration<double, std::milli>(t2 - t0).count();
    stats.submitMs = std::chrono::duration<double, std::milli>(t2 - t1).count();

    // Step 6: results.
    m.queries->read(stats);
    if (dev_.caps().storesAndAtomics) {
        const auto* c = static_cast<const uint32_t*>(m.counters.mapped);
        stats.patchesCulled = c[0] + plan.windowsCulled;
        stats.displacedEdges = c[1];
        stats.displacementLevel = c[2];
    }
    return stats;
}

void Renderer::warmUp() {
    // A one-patch scene: the pipelines do not depend on the document, and drawing a big one a dozen
    // times made opening a 16 384-window net take 26 s on lavapipe (issue 67).
    Document one;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) one.points.push_back(Vec3(j - 1.5, i - 1.5, 0.25 * ((i + j) % 2)));
    Patch patch;
    for (uint32_t s = 0; s < 16; ++s) patch.idx[s] = s;
    one.patches.push_back(patch);
    setDocument(one);
    RenderOptions o;
    o.tess.outer = {2, 2, 2, 2};
    o.tess.inner = {2, 2};
    o.display.showGrid = o.display.showWireframe = o.display.showNormals = o.display.showBoundaries = o.display.showIsocurves = true;
    for (Spacing s : {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven})
        for (bool culling : {false, true})                                          // both levels variants
            for (ShadingMode shading : {ShadingMode::Lit, ShadingMode::PatchId}) {  // both varying sets
                o.tess.spacing = s;
                o.tess.cullBackfaces = o.tess.cullOffscreen = culling;
                o.display.shading = shading;
                render(o);
            }
    // Merged blocks (lean, no overlays, drawn for nets): made.
    (void)static_cast<VkPipeline>(pipes_.merged);
    if (impl_->mesh.indexCount) {
        o.plainMesh = true;
        for (ShadingMode shading : {ShadingMode::Lit, ShadingMode::PatchId}) {
            o.display.shading = shading;
            render(o);
        }
    }
}

}  // namespace scene
}  // namespace pw::render

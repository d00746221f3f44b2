#include "render/scene/frame_passes.hpp"

#include <algorithm>
#include <cmath>

#include "render/scene/merged_blocks.hpp"
#include "render/scene/overlays.hpp"
#include "render/scene/plain_mesh.hpp"
#include "render/scene/surface_scene.hpp"
#include "render/scene/triangle_draws.hpp"

namespace pw::render {
inline namespace scene {

namespace {

using Frame = FramePasses::Frame;

constexpr VkDeviceSize kZero = 0;

size_t surfaceSlot(const Frame& f) { return surfaceIndex(f.plan.variant, f.plan.levels, f.varyings); }
size_t overlaySlot(const Frame& f) { return overlayIndex(f.plan.variant, f.plan.levels); }

// The windows through `full` (the plan's control shader), but for windows culled on the CPU
// (render/scene/view_culling.hpp): those outside not at all, and with `fixed` (given when some
// windows are wholly inside) those through it first, then the rest through `full`. (The shaded surface only: each of its pixels
// belongs to one triangle, so the order of the two draws cannot show; a wire's shared edges are
// drawn by both windows and keep the one order.) `merged`: windows merged blocks draw instead (may be null).
void recordWindows(Frame& f, VkPipeline full, VkPipeline fixed, gpu::DrawPush push, const std::vector<uint8_t>* merged) {
    const auto& m = f.m;
    if (f.plan.skipTested.empty()) {
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, full);
        f.stats.draws += recordSurfaceDraws(f.cmd, f.pipes.layout, m.scene, f.plan.perDraw, push, f.plan.bounds(), f.plan.budget, merged);
        return;
    }
    if (fixed == VK_NULL_HANDLE) {
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, full);
        f.stats.draws +=
            recordSurfaceDraws(f.cmd, f.pipes.layout, m.scene, f.plan.perDraw, push, f.plan.bounds(), f.plan.budget, &f.plan.skipCulled);
        return;
    }
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, fixed);
    f.stats.draws +=
        recordSurfaceDraws(f.cmd, f.pipes.layout, m.scene, f.plan.perDraw, push, f.plan.bounds(), f.plan.budget, &f.plan.skipInside);
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, full);
    f.stats.draws +=
        recordSurfaceDraws(f.cmd, f.pipes.layout, m.scene, f.plan.perDraw, push, f.plan.bounds(), f.plan.budget, &f.plan.skipTested);
}

// Windows (and the Bézier triangles after them) through the family's pipelines at `slot`.
void recordPatches(Frame& f, const std::array<LazyPipeline, kSpacingVariants * kLevelsVariants>& windows,
                   const std::array<LazyPipeline, kSpacingVariants * kLevelsVariants>& triangles, gpu::DrawPush push) {
    const auto& m = f.m;
    recordWindows(f, windows[overlaySlot(f)], VK_NULL_HANDLE, push, nullptr);
    if (m.scene.triangleCount && triangles[overlaySlot(f)]) {
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, triangles[overlaySlot(f)]);
        f.stats.draws += recordTriangleDraws(f.cmd, f.pipes.layout, m.scene, f.plan.perDraw, push);
    }
}

// Windows per draw for the isoline domain: a window draws lines x (segments + 1) <= 64 x 65
// evaluation vertices.
uint32_t windowsPerIsolineDraw(const Frame& f) {
    const uint32_t lines = uint32_t(std::ceil(std::clamp(f.opt.tess.isolineLevels[0], 1.0f, 64.0f)));
    return f.plan.budget == 0 ? UINT32_MAX : std::max(1u, f.plan.budget / (65u * lines));
}

bool groundWanted(const Frame& f) { return f.opt.groundGridStep > 0.0 && std::isfinite(f.opt.groundGridStep); }

// The editor's ground grid: behind the surface where the surface is nearer (depth test, no write).
void groundPass(Frame& f) {
    auto& m = f.m;
    if (!m.ground.buffer || m.groundStep != f.opt.groundGridStep || m.groundZUp != f.opt.camera.zUp) {
        const std::vector<float> v = groundGridVertices(f.opt.groundGridStep, f.opt.camera.zUp);
        m.ground =
            uploadStatic(f.dev, v, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);  // no frame reads the old one: render() waits for its own submission
        m.groundVertexCount = uint32_t(v.size() / 7);
        m.groundStep = f.opt.groundGridStep;
        m.groundZUp = f.opt.camera.zUp;
    }
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.groundLines);
    vkCmdPushConstants(f.cmd, f.pipes.layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(f.push), &f.push);
    vkCmdBindVertexBuffers(f.cmd, 0, 1, m.ground.buffer.ptr(), &kZero);
    vkCmdDraw(f.cmd, m.groundVertexCount, 1, 0, 0);
    ++f.stats.draws;
}

bool wireframeWanted(const Frame& f) { return f.opt.display.showWireframe && !f.opt.plainMesh; }

void wireframePass(Frame& f) {
    gpu::DrawPush wp;
    wp.drawMode = gpu::kDrawFlatColour;
    wp.color = {f.opt.wireColor[0], f.opt.wireColor[1], f.opt.wireColor[2], f.opt.wireColor[3]};
    recordPatches(f, f.fam.wire, f.fam.triWire, wp);
}

bool normalsWanted(const Frame& f) { return f.opt.display.showNormals && !f.opt.plainMesh && f.fam.normals[overlaySlot(f)]; }

void normalsPass(Frame& f) {
    gpu::DrawPush np;
    np.drawMode = gpu::kDrawFlatColour;  // an overlay: the control shader counts culled patches once, in the surface pass
    np.color = {0.2f, 0.9f, 1.0f, 1.0f};
    recordPatches(f, f.fam.normals, f.fam.triNormals, np);
}

bool isocurvesWanted(const Frame& f) { return f.opt.display.showIsocurves && !f.opt.plainMesh && f.m.scene.windowCount; }

// The isoline domain: isoparametric curves of every window, along u then along v.
void isocurvesPass(Frame& f) {
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.isocurves[size_t(f.plan.variant)]);
    gpu::DrawPush ip;
    ip.color = {0.35f, 0.95f, 0.45f, 1.0f};
    for (uint32_t dir : {0u, 1u}) {
        ip.isoDirection = dir;
        f.stats.draws += recordSurfaceDraws(f.cmd, f.pipes.layout, f.m.scene, windowsPerIsolineDraw(f), ip, nullptr, f.plan.budget);
    }
}

bool curvesWanted(const Frame& f) { return f.m.scene.curveCount > 0; }

// The document's Bézier curves (isoline domain). Curves count as overlays: the statistics are the
// surface's triangles.
void curvesPass(Frame& f) {
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.curves[size_t(f.plan.variant)]);
    gpu::DrawPush cp;
    cp.color = {0.95f, 0.35f, 0.25f, 1.0f};
    f.stats.draws += recordCurveDraws(f.cmd, f.pipes.layout, f.m.scene, cp, f.plan.budget);
}

bool combsWanted(const Frame& f) { return f.opt.display.showCombs && !f.opt.plainMesh; }

// Curvature combs: teeth, then the envelope through their tips, on every curve, on the isocurve
// overlay's lines, and on the isocurves crossing the selected join on either side.
void combsPass(Frame& f) {
    const auto& m = f.m;
    const bool iso = f.opt.display.showIsocurves;
    gpu::DrawPush kp;
    const Join* graph = f.opt.combJoin >= 0 && size_t(f.opt.combJoin) < m.joins.size() ? &m.joins[size_t(f.opt.combJoin)] : nullptr;
    for (uint32_t mode : {gpu::kDrawCombTeeth, gpu::kDrawCombEnvelope}) {
        kp.drawMode = mode;
        kp.color = mode == gpu::kDrawCombTeeth ? glm::vec4(0.95f, 0.5f, 0.85f, 1.0f) : glm::vec4(1.0f, 0.8f, 0.95f, 1.0f);
        if (m.scene.curveCount) {
            vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.combs);
            f.stats.draws += recordCurveDraws(f.cmd, f.pipes.layout, m.scene, kp, f.plan.budget);
        }
        if ((iso || graph) && m.scene.windowCount) vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.isoCombs);
        if (iso && m.scene.windowCount)
            for (uint32_t dir : {0u, 1u}) {
                kp.isoDirection = dir;
                f.stats.draws += recordSurfaceDraws(f.cmd, f.pipes.layout, m.scene, windowsPerIsolineDraw(f), kp, nullptr, f.plan.budget);
            }
        if (graph) {  // the isocurves across the seam: along u for a u0/u1 edge, along v for v0/v1
            const auto across = [](Edge e) { return e == Edge::U0 || e == Edge::U1 ? 0u : 1u; };
            kp.isoDirection = across(graph->edgeA) | 2u;
            f.stats.draws += recordWindowDraw(f.cmd, f.pipes.layout, m.scene, graph->patchA, kp);
            kp.isoDirection = across(graph->edgeB) | 2u;
            f.stats.draws += recordWindowDraw(f.cmd, f.pipes.layout, m.scene, graph->patchB, kp);
        }
    }
}

bool boundariesWanted(const Frame& f) { return f.opt.display.showBoundaries && f.m.overlays.boundaryVertexCount; }

// Patch boundaries coloured by continuity (render/scene/overlays).
void boundariesPass(Frame& f) {
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.colorLines);
    vkCmdPushConstants(f.cmd, f.pipes.layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(f.push), &f.push);
    vkCmdBindVertexBuffers(f.cmd, 0, 1, f.m.overlays.boundaryVerts.buffer.ptr(), &kZero);
    vkCmdDraw(f.cmd, f.m.overlays.boundaryVertexCount, 1, 0, 0);
    ++f.stats.draws;
}

bool frustumWanted(const Frame& f) { return f.plan.lodVm.has_value(); }

// A debug camera's frustum (the camera that decided the levels and culling), rewritten each frame:
// no frame reads the old buffer, render() waits for its own submission.
void frustumPass(Frame& f) {
    auto& m = f.m;
    const std::vector<float> v = frustumLineVertices(*f.plan.lodVm, f.plan.frustumDepth);
    m.frustum = uploadStatic(f.dev, v, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    m.frustumVertexCount = uint32_t(v.size() / 7);
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.colorLines);
    vkCmdPushConstants(f.cmd, f.pipes.layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(f.push), &f.push);
    vkCmdBindVertexBuffers(f.cmd, 0, 1, m.frustum.buffer.ptr(), &kZero);
    vkCmdDraw(f.cmd, m.frustumVertexCount, 1, 0, 0);
    ++f.stats.draws;
}

bool controlNetWanted(const Frame& f) { return f.opt.display.showGrid && f.m.scene.pointCount; }

// The control net: its lines, then the points of the shown items.
void controlNetPass(Frame& f) {
    const auto& m = f.m;
    gpu::DrawPush gp;
    gp.color = {0.95f, 0.75f, 0.2f, 1.0f};
    vkCmdBindVertexBuffers(f.cmd, 0, 1, m.scene.pool.buffer.ptr(), &kZero);
    if (m.overlays.gridIndexCount) {
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.gridLines);
        vkCmdPushConstants(f.cmd, f.pipes.layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(gp), &gp);
        vkCmdBindIndexBuffer(f.cmd, m.overlays.gridIndices.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(f.cmd, m.overlays.gridIndexCount, 1, 0, 0, 0);
    }
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.gridPoints);
    gp.drawMode = gpu::kDrawGridPoints;
    gp.color = {0.1f, 0.1f, 0.1f, 1.0f};
    vkCmdPushConstants(f.cmd, f.pipes.layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(gp), &gp);
    if (m.scene.shownPointCount) {  // only the points of shown items (gl_VertexIndex is still the pool index)
        vkCmdBindIndexBuffer(f.cmd, m.scene.shownPoints.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(f.cmd, m.scene.shownPointCount, 1, 0, 0, 0);
    } else {
        vkCmdDraw(f.cmd, m.scene.pointCount, 1, 0, 0);
    }
    f.stats.draws += 2;
}

constexpr FramePasses::Pass kOverlays[] = {
    {"ground grid", groundWanted, groundPass},
    {"wireframe", wireframeWanted, wireframePass},
    {"normals", normalsWanted, normalsPass},
    {"isocurves", isocurvesWanted, isocurvesPass},
    {"curves", curvesWanted, curvesPass},
    {"curvature combs", combsWanted, combsPass},
    {"boundaries", boundariesWanted, boundariesPass},
    {"control net", controlNetWanted, controlNetPass},
    {"debug camera frustum", frustumWanted, frustumPass},
};

}  // namespace

void FramePasses::surface(Frame& f) {
    auto& m = f.m;
    if (f.opt.plainMesh) {
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.mesh[size_t(f.varyings)]);
        f.push.drawMode = gpu::kDrawPlainMesh;
        vkCmdPushConstants(f.cmd, f.pipes.layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(f.push), &f.push);
        recordPlainMesh(f.cmd, m.mesh);
        f.stats.draws = m.mesh.indexCount ? 1 : 0;
        return;
    }
    if (f.opt.rawTessellator) {
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.raw);
        f.stats.draws = recordSurfaceDraws(f.cmd, f.pipes.layout, m.scene, f.plan.perDraw, f.push, nullptr, f.plan.budget);
        f.stats.patches = m.scene.windowCount;
        return;
    }
    const MergedBlocks& merged = f.plan.merged;
    f.stats.cullTestSkipped = f.plan.cullTestSkipped;
    const VkPipeline fixed = f.plan.windowsInside > 0
                                 ? VkPipeline(f.fam.surface[surfaceIndex(f.plan.variant, LevelsVariant::Fixed, f.varyings)])
                                 : VK_NULL_HANDLE;
    f.stats.draws = 0;
    recordWindows(f, f.fam.surface[surfaceSlot(f)], fixed, f.push, merged.windows ? &merged.merged : nullptr);
    f.stats.patches = m.scene.windowCount;
    if (merged.windows) {  // windows at one level, several to a patch
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipes.merged);
        f.stats.draws += recordMergedBlocks(f.cmd, f.pipes.layout, m.scene, merged, f.push, f.plan.budget);
        f.stats.mergedWindows = merged.windows;
        f.stats.mergedBlocks = uint32_t(merged.blocks.size());
    }
    if (m.scene.triangleCount) {  // Bézier triangles after the windows, inside the same statistics
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.fam.triSurface[surfaceSlot(f)]);
        f.stats.draws += recordTriangleDraws(f.cmd, f.pipes.layout, m.scene, f.plan.perDraw, f.push);
        f.stats.patches += m.scene.triangleCount;
    }
}

std::span<const FramePasses::Pass> FramePasses::overlays() { return kOverlays; }

}  // namespace scene
}  // namespace pw::render

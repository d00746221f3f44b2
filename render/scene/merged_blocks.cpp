#include "render/scene/merged_blocks.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

#include "core/gpu/patch_math.h"
#include "core/tess/tess_levels.hpp"

namespace pw::render {
inline namespace scene {

namespace {

bool powerOfTwo(uint32_t n) { return n != 0 && (n & (n - 1)) == 0; }

// What the control shader's culling would do to window w (no displacement: no margin), judged a
// little in its favour: a window near a plane counts as culled and stays unmerged, so the control
// shader decides it.
bool mayBeCulled(const SurfaceScene& s, uint32_t w, const TessSettings& tess, const ViewMatrices& vm) {
    const uint32_t* idx = &s.cpuIndices[size_t(w) * 16];
    if (tess.cullOffscreen)
        for (int k = 0; k < 6; ++k) {
            const glm::vec4 plane = gpu::frustumPlane(vm.viewProj, k);
            const float pad = 1e-4f * glm::length(glm::vec3(plane));
            bool outside = true;
            for (int i = 0; i < 16 && outside; ++i) outside = glm::dot(plane, glm::vec4(s.cpuPoints[idx[i]], 1.0f)) < pad;
            if (outside) return true;
        }
    if (tess.cullFar && tess.adaptive == AdaptiveMode::Distance) {
        glm::vec3 c(0.0f);
        for (int i = 0; i < 16; ++i) c += s.cpuPoints[idx[i]];
        if (glm::distance(vm.eye, c / 16.0f) >= tess.distanceFar * (1.0f - 1e-4f)) return true;
    }
    return false;
}

}  // namespace

std::vector<DirectionLevels> settingsWindowLevels(const SurfaceScene& s, const TessSettings& tess) {
    // As the fixed-levels control shader: the settings rounded, with no max-level clamp (that is adaptive's).
    const auto agreed = [&](float inner, float a, float b) {
        const int n = roundedSegments(inner, tess.spacing);
        return uint8_t(roundedSegments(a, tess.spacing) == n && roundedSegments(b, tess.spacing) == n ? n : 0);
    };
    // inner[0] subdivides along u, as the edges v0 and v1 (outer 1 and 3) do.
    DirectionLevels d{agreed(tess.inner[0], tess.outer[1], tess.outer[3]), agreed(tess.inner[1], tess.outer[0], tess.outer[2])};
    if (!d.known()) d = {};
    std::vector<DirectionLevels> out(s.windowCount, d);
    for (uint32_t w = 0; w < s.windowCount; ++w)
        if (s.overrideLevel[w] != 0.0f) out[w] = {};  // the shared-edge rule may raise its edges
    return out;
}

MergedBlocks planMergedBlocks(const SurfaceScene& s, const std::vector<DirectionLevels>& uniform, const TessSettings& tess,
                              const ViewMatrices& cullView, float deviceMax, bool anyLevel) {
    MergedBlocks out;
    out.merged.assign(s.windowCount, 0);
    out.perRun.assign(s.runs.size(), {0u, 0u});
    if (tess.spacing != Spacing::Equal && tess.spacing != Spacing::Pow2) return out;  // fractional: no uniform grid
    if (tess.cullBackfaces) return out;                                               // the normal-cone test is the control shader's alone
    if (uniform.size() != s.windowCount) return out;
    // Patches up to level 16: past that the per-patch cost is small beside the triangles', and
    // lavapipe's draw module slows down on very large patches.
    const uint32_t maxLevel = uint32_t(std::min(deviceMax, float(kMaxMergedLevel)));
    // Per window, the levels it may be merged at (0: not at all).
    std::vector<DirectionLevels> level(s.windowCount);
    const auto mergeable = [&](uint8_t n) { return anyLevel || powerOfTwo(n); };
    // Spline nets only: their windows meet with continuous normals (C2 B-splines, C1 Catmull-Rom),
    // so a seam vertex evaluated on either window shades alike; Bézier nets may have creases.
    for (const NetWindows& net : s.nets) {
        const BasisRun* run = windowRun(s, net.first);  // a net's windows share one basis
        if (!run || run->basisKind == gpu::kBasisBezier) continue;
        for (uint32_t w = net.first; w < net.first + net.rows * net.cols; ++w) {
            const DirectionLevels d = uniform[w];
            // A quad with one inner level 1 and the other above gets that level rounded up to 2 (the
            // Vulkan spec's special case): such a window alone has vertices a block would not.
            if (d.known() && mergeable(d.u) && mergeable(d.v) && (d.u == 1) == (d.v == 1) && !mayBeCulled(s, w, tess, cullView))
                level[w] = d;
        }
    }
    const auto tryBlock = [&](const NetWindows& net, uint32_t r0, uint32_t c0, uint32_t bu, uint32_t bv) {
        if (r0 + bv > net.rows || c0 + bu > net.cols) return false;
        const uint32_t first = net.first + r0 * net.cols + c0;
        const DirectionLevels n = level[first];
        if (!n.known() || bu * n.u > maxLevel || bv * n.v > maxLevel) return false;
        // The same special case for the block: a strip of level-1 windows would gain vertices inside.
        if ((bu * n.u == 1) != (bv * n.v == 1)) return false;
        for (uint32_t r = 0; r < bv; ++r)
            for (uint32_t c = 0; c < bu; ++c)
                if (!(level[first + r * net.cols + c] == n)) return false;
        out.blocks.push_back({first, net.cols, bu + 256u * bv, n.u + 256u * n.v});
        for (uint32_t r = 0; r < bv; ++r)
            for (uint32_t c = 0; c < bu; ++c) out.merged[first + r * net.cols + c] = 1;
        out.windows += bu * bv;
        return true;
    };
    // Tiles of 4 x 4 windows; where a tile is not one level, its 2 x 2 quarters, and where a quarter
    // is not, its rows or columns of two.
    for (const NetWindows& net : s.nets)
        for (uint32_t r0 = 0; r0 < net.rows; r0 += 4)
            for (uint32_t c0 = 0; c0 < net.cols; c0 += 4) {
                if (tryBlock(net, r0, c0, 4, 4)) continue;
                for (uint32_t r = r0; r < r0 + 4; r += 2)
                    for (uint32_t c = c0; c < c0 + 4; c += 2) {
                        if (tryBlock(net, r, c, 2, 2)) continue;
                        const bool rows = tryBlock(net, r, c, 2, 1) & tryBlock(net, r + 1, c, 2, 1);
                        if (!rows && !out.merged[net.first + r * net.cols + c] && !out.merged[net.first + (r + 1) * net.cols + c])
                            for (uint32_t k = 0; k < 2; ++k) tryBlock(net, r, c + k, 1, 2);
                    }
            }
    // Blocks in window order (nets in order, tiles row by row within a net do not keep it).
    std::sort(out.blocks.begin(), out.blocks.end(), [](const glm::uvec4& a, const glm::uvec4& b) { return a.x < b.x; });
    size_t at = 0;
    for (size_t r = 0; r < s.runs.size(); ++r) {
        const uint32_t end = s.runs[r].first + s.runs[r].count;
        const size_t from = at;
        while (at < out.blocks.size() && out.blocks[at].x < end) ++at;
        out.perRun[r] = {uint32_t(from), uint32_t(at - from)};
    }
    return out;
}

uint32_t recordMergedBlocks(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, const MergedBlocks& m, gpu::DrawPush push,
                            uint32_t vertexBudget) {
    uint32_t draws = 0;
    for (size_t r = 0; r < s.runs.size() && r < m.perRun.size(); ++r) {
        const auto [first, count] = m.perRun[r];
        push.basis = s.runs[r].matrix;
        push.basisKind = s.runs[r].basisKind;
        push.patchBase = s.runs[r].first;
        for (uint32_t at = first, n = 0; at < first + count; at += n) {
            // As many blocks as keep their evaluation vertices within the budget (one at least).
            uint32_t vertices = 0;
            for (n = 0; at + n < first + count; ++n) {
                const glm::uvec4& b = m.blocks[at + n];
                const uint32_t v = ((b.z & 255u) * (b.w & 255u) + 1) * ((b.z >> 8u) * (b.w >> 8u) + 1);
                if (n > 0 && vertexBudget != 0 && vertices + v > vertexBudget) break;
                vertices += v;
            }
            vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(gpu::DrawPush), &push);
            vkCmdDraw(cmd, n, 1, at, 0);  // one control point a block: its index
            ++draws;
        }
    }
    return draws;
}

}  // namespace scene
}  // namespace pw::render

#include "render/scene/surface_scene.hpp"

#include <algorithm>

#include <glm/packing.hpp>

#include "core/eval/displacement.hpp"
#include "core/select/picking.hpp"
#include "core/tess/edge_levels.hpp"
#include "core/trim/trim_cells.hpp"
#include "core/trim/trim_loops.hpp"

namespace pw::render {
inline namespace scene {

glm::mat4 basisPushMatrix(Basis basis, double tension) {
    const Mat4 m = basisMatrix(basis, tension);
    glm::mat4 g(1.0f);
    // Column i of the GLSL matrix = row i of M, so (basis * T)[j] = sum_i T_i M[i][j].
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) g[i][j] = float(m[i][j]);
    return g;
}

namespace {
// Each trimmed window's block in binding 7 and its PatchData::trim (core/gpu/trim_math.h): one vec4
// per cell (core/trim/trim_cells.hpp: the first vec4 of its list, its count, its parity), then the
// cells' segments in the window's own (u, v), a segment listed once per cell that needs it.
void windowTrims(const Document& doc, const std::vector<PatchInstance>& inst, std::vector<gpu::PatchData>& pd, SurfaceScene& s) {
    s.trimData.clear();
    s.trimmedWindows = 0;
    WindowTrims trims(doc);
    for (size_t w = 0; w < inst.size() && w < pd.size(); ++w) {
        const std::optional<WindowTrim> found = trims.of(inst[w]);
        if (!found) continue;
        const WindowTrim& t = *found;
        ++s.trimmedWindows;
        const size_t block = s.trimData.size();
        pd[w].trim = glm::uvec4(uint32_t(block), uint32_t(t.segments.size()), t.flags, 0u);
        const std::vector<TrimCell> cells = trimCells(t);
        s.trimData.resize(block + cells.size());
        for (size_t c = 0; c < cells.size(); ++c) {
            // Whole numbers as floats: exact below 2^24 vec4s (a 256 MiB buffer).
            s.trimData[block + c] = glm::vec4(float(s.trimData.size()), float(cells[c].segments.size()), float(cells[c].parity), 0.0f);
            for (uint32_t k : cells[c].segments) {  // its box (umin, vmin, umax, vmax), then its four points
                const TrimSegment& g = t.segments[k];
                const float u0 = float(std::min({g.b[0].x, g.b[1].x, g.b[2].x, g.b[3].x})),
                            u1 = float(std::max({g.b[0].x, g.b[1].x, g.b[2].x, g.b[3].x}));
                s.trimData.emplace_back(u0, float(std::min(g.b[0].y, g.b[3].y)), u1, float(std::max(g.b[0].y, g.b[3].y)));
                s.trimData.emplace_back(float(g.b[0].x), float(g.b[0].y), float(g.b[1].x), float(g.b[1].y));
                s.trimData.emplace_back(float(g.b[2].x), float(g.b[2].y), float(g.b[3].x), float(g.b[3].y));
            }
        }
    }
}
}  // namespace

std::vector<gpu::PatchData> windowPatchData(const Document& doc, const std::vector<PatchInstance>& inst, const HeightMap* map,
                                            const std::vector<HeightMap>* mips, SurfaceScene& s) {
    // Per window, then per triangle: the levels of the shared-edge rule (core/tess/edge_levels.hpp).
    const std::vector<WindowLevels> levels = resolveEdgeLevels(doc, inst);
    std::vector<gpu::PatchData> pd(levels.size());
    s.overrideLevel.assign(inst.size(), 0.0f);
    s.overrideMax = 0.0f;
    const std::vector<WindowDisplacement> disp = windowDisplacements(doc, inst, map, mips);
    for (size_t w = 0; w < pd.size() && w < disp.size(); ++w) {
        const WindowDisplacement& d = disp[w];
        pd[w].uvRect = {d.uvRect[0], d.uvRect[1], d.uvRect[2], d.uvRect[3]};
        const bool own = d.own && map && !map->empty();  // without a map nothing is displaced (no culling margin either)
        pd[w].disp = {own ? d.own->scale : 0.0f, own ? d.own->bias : 0.0f, own ? 1.0f : 0.0f, 0.0f};
        pd[w].detail = {d.detail[0], d.detail[1], d.detail[2], d.detail[3]};
        pd[w].texels = {d.texels[0], d.texels[1], d.texels[2], d.texels[3]};
        for (int e = 0; e < 4; ++e)  // the coarser levels' detail as fractions of level 0's, two halves a word
            for (int k = 0; k < 4; ++k) {
                const float d0 = d.detail[size_t(e)];
                auto frac = [&](int l) {  // within a half's range
                    return d0 > 0.0f ? std::min(d.coarser[size_t(e)][size_t(l)] / d0, 6e4f) : 0.0f;
                };
                pd[w].coarserDetail[e][k] = glm::packHalf2x16(glm::vec2(frac(2 * k), frac(2 * k + 1)));
            }
    }
    windowTrims(doc, inst, pd, s);
    for (size_t w = 0; w < levels.size(); ++w) {
        const WindowLevels& l = levels[w];
        pd[w].outer = {l.outer[0], l.outer[1], l.outer[2], l.outer[3]};
        pd[w].inner = {l.inner ? (*l.inner)[0] : 0.0f, l.inner ? (*l.inner)[1] : 0.0f, l.inner ? 1.0f : 0.0f, float(l.fixedMask)};
        float most = 0.0f;
        for (float f : l.outer) most = std::max(most, f);
        if (l.inner) most = std::max({most, (*l.inner)[0], (*l.inner)[1]});
        s.overrideMax = std::max(s.overrideMax, most);
        if (w < inst.size()) s.overrideLevel[w] = most;
    }
    return pd;
}

SurfaceScene uploadSurfaceScene(Device& dev, const Document& doc, const HeightMap* map, const std::vector<HeightMap>* mips) {
    SurfaceScene s;
    std::vector<float> pts;
    pts.reserve(doc.points.size() * 4);
    for (uint32_t i = 0; i < doc.points.size(); ++i) {
        const Vec3& p = doc.points[i];
        pts.insert(pts.end(), {float(p.x), float(p.y), float(p.z), float(pointWeight(doc, i))});
    }
    const std::vector<PatchInstance> inst = expandPatches(doc);
    std::vector<uint32_t> idx;
    idx.reserve(inst.size() * 16);
    const std::vector<gpu::PatchData> pd = windowPatchData(doc, inst, map, mips, s);
    for (size_t w = 0; w < inst.size(); ++w) {
        const PatchInstance& pi = inst[w];
        idx.insert(idx.end(), pi.idx.begin(), pi.idx.end());
        const uint32_t kind = pi.basis == Basis::Bezier ? 0u : pi.basis == Basis::BSpline ? 1u : 2u;
        if (s.runs.empty() || s.runs.back().basisKind != kind || (kind == 2u && inst[s.runs.back().first].tension != pi.tension)) {
            s.runs.push_back({uint32_t(w), 0, kind, basisPushMatrix(pi.basis, pi.tension)});
        }
        ++s.runs.back().count;
    }
    for (size_t w = 0; w < inst.size();) {  // each net's windows: row after row (expandPatches)
        size_t end = w;
        while (end < inst.size() && inst[end].surface >= 0 && inst[end].surface == inst[w].surface) ++end;
        if (end == w) {
            ++w;
            continue;
        }
        uint32_t cols = 0;
        while (w + cols < end && inst[w + cols].windowRow == inst[w].windowRow) ++cols;
        s.nets.push_back({uint32_t(w), uint32_t((end - w) / cols), cols});
        w = end;
    }
    // Bézier triangles after the windows: indices in their own buffer, overrides appended.
    std::vector<uint32_t> triIdx;
    triIdx.reserve(doc.triangles.size() * 10);
    for (const TrianglePatch& t : doc.triangles) triIdx.insert(triIdx.end(), t.idx.begin(), t.idx.end());
    s.triangleCount = uint32_t(doc.triangles.size());
    if (!triIdx.empty()) s.triIndices = uploadStatic(dev, triIdx, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    std::vector<uint32_t> curveIdx;
    for (const BezierCurve& c : doc.curves)  // one isoline patch per segment
        for (size_t k = 0; k < curveSegmentCount(c); ++k) {
            const std::array<uint32_t, 4> seg = curveSegment(c, k);
            curveIdx.insert(curveIdx.end(), seg.begin(), seg.end());
        }
    s.curveCount = uint32_t(curveIdx.size() / 4);
    if (!curveIdx.empty()) s.curveIndices = uploadStatic(dev, curveIdx, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    s.cpuPoints.reserve(doc.points.size());
    for (const Vec3& p : doc.points) s.cpuPoints.emplace_back(float(p.x), float(p.y), float(p.z));
    s.cpuIndices = idx;
    s.pointCount = uint32_t(doc.points.size());
    s.windowCount = uint32_t(inst.size());
    s.pool = uploadHostWritten(dev, pts, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    s.indices = uploadStatic(dev, idx, VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    s.patchData = uploadStatic(dev, pd, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!s.trimData.empty()) s.trimSegments = uploadStatic(dev, s.trimData, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    const std::vector<bool> used = usedPointMask(doc);
    std::vector<uint32_t> shown;
    for (uint32_t p = 0; p < used.size(); ++p)
        if (used[p]) shown.push_back(p);
    if (!shown.empty() && shown.size() < doc.points.size()) {
        s.shownPoints = uploadStatic(dev, shown, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        s.shownPointCount = uint32_t(shown.size());
    }
    return s;
}

const BasisRun* windowRun(const SurfaceScene& s, uint32_t w) {
    for (const BasisRun& r : s.runs)
        if (w >= r.first && w < r.first + r.count) return &r;
    return nullptr;
}

uint32_t recordWindowDraw(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, uint32_t window, gpu::DrawPush push) {
    const BasisRun* run = windowRun(s, window);
    if (!run) return 0;
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, s.pool.buffer.ptr(), &zero);
    vkCmdBindIndexBuffer(cmd, s.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    push.basis = run->matrix;
    push.basisKind = run->basisKind;
    push.patchBase = window;
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(gpu::DrawPush), &push);
    vkCmdDrawIndexed(cmd, 16, 1, 16 * window, 0, 0);
    return 1;
}

uint32_t recordSurfaceDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const SurfaceScene& s, uint32_t perDraw, gpu::DrawPush push,
                            const std::vector<uint8_t>* levels, uint32_t vertexBudget, const std::vector<uint8_t>* skip) {
    if (s.windowCount == 0) return 0;
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, s.pool.buffer.ptr(), &zero);
    vkCmdBindIndexBuffer(cmd, s.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    uint32_t draws = 0;
    perDraw = std::max(perDraw, 1u);
    const auto skipped = [&](uint32_t w) { return skip && (*skip)[w]; };
    for (const BasisRun& run : s.runs) {
        const uint32_t end = run.first + run.count;
        for (uint32_t first = run.first, n = 0; first < end; first += n) {
            if (skipped(first)) {
                n = 1;
                continue;
            }
            // Grow the batch over windows not skipped: within the evaluation-vertex budget, or perDraw of them.
            uint32_t maxL = 0;
            for (n = 0; first + n < end && !skipped(first + n); ++n) {
                if (levels && vertexBudget != 0) {
                    const uint32_t l = std::max<uint32_t>(maxL, (*levels)[first + n]);
                    if (n > 0 && (n + 1) * (l + 2) * (l + 2) > vertexBudget) break;
                    maxL = l;
                } else if (n == perDraw) {
                    break;
                }
            }
            push.basis = run.matrix;
            push.basisKind = run.basisKind;
            push.patchBase = first;
            vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(gpu::DrawPush), &push);
            vkCmdDrawIndexed(cmd, 16 * n, 1, 16 * first, 0, 0);
            ++draws;
        }
    }
    return draws;
}

}  // namespace scene
}  // namespace pw::render

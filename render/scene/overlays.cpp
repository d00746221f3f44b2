#include "render/scene/overlays.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <set>

#include "core/eval/bezier_triangle.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/gpu/trim_math.h"
#include "core/model/topology.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"

namespace pw::render {
inline namespace scene {

std::vector<uint32_t> controlGridLines(const Document& doc) {
    std::set<std::pair<uint32_t, uint32_t>> seen;
    std::vector<uint32_t> out;
    auto add = [&](uint32_t a, uint32_t b) {
        if (a == b) return;
        auto key = std::minmax(a, b);
        if (seen.insert({key.first, key.second}).second) {
            out.push_back(a);
            out.push_back(b);
        }
    };
    for (const PatchInstance& pi : expandPatches(doc))
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j) {
                add(pi.idx[i * 4 + j], pi.idx[i * 4 + j + 1]);
                add(pi.idx[j * 4 + i], pi.idx[(j + 1) * 4 + i]);
            }
    // Bézier triangles: the edges of the net's six upward sub-triangles (a + b + c = 2).
    for (const TrianglePatch& t : doc.triangles)
        for (int a = 0; a <= 2; ++a)
            for (int b = 0; b <= 2 - a; ++b) {
                const int c = 2 - a - b;
                const uint32_t p[3] = {t.idx[size_t(triSlot(a + 1, b, c))], t.idx[size_t(triSlot(a, b + 1, c))],
                                       t.idx[size_t(triSlot(a, b, c + 1))]};
                add(p[0], p[1]);
                add(p[1], p[2]);
                add(p[2], p[0]);
            }
    return out;
}

std::array<float, 4> continuityColor(const Continuity* c) {
    if (!c) return {0.75f, 0.75f, 0.75f, 1.0f};
    switch (*c) {
        case Continuity::C0:
            return {0.95f, 0.25f, 0.2f, 1.0f};
        case Continuity::C1:
            return {0.2f, 0.85f, 0.3f, 1.0f};
        case Continuity::G1:
            return {0.3f, 0.5f, 1.0f, 1.0f};
        case Continuity::C2:
            return {0.95f, 0.85f, 0.2f, 1.0f};
        case Continuity::G2:
            return {0.75f, 0.45f, 1.0f, 1.0f};
    }
    return {1, 1, 1, 1};
}

std::vector<float> groundGridVertices(double step, bool zUp) {
    constexpr int n = 10;
    std::vector<float> v;
    v.reserve(2 * (2 * n + 1) * 2 * 7);
    auto vertex = [&](double a, double b, const std::array<float, 4>& c) {
        const float x = float(a * step), y = float(b * step);
        const float p[3] = {x, zUp ? y : 0.0f, zUp ? 0.0f : -y};
        v.insert(v.end(), p, p + 3);
        v.insert(v.end(), c.begin(), c.end());
    };
    for (int i = -n; i <= n; ++i)
        for (int dir = 0; dir < 2; ++dir) {
            const std::array<float, 4> c = i != 0     ? std::array<float, 4>{0.59f, 0.59f, 0.59f, 0.18f}
                                           : dir == 0 ? std::array<float, 4>{0.78f, 0.27f, 0.27f, 0.55f}
                                                      : std::array<float, 4>{0.27f, 0.71f, 0.27f, 0.55f};
            if (dir == 0)
                vertex(-n, i, c), vertex(n, i, c);  // along x
            else
                vertex(i, -n, c), vertex(i, n, c);
        }
    return v;
}

std::vector<float> frustumLineVertices(const ViewMatrices& vm, double depth) {
    const glm::mat4 inv = glm::inverse(vm.viewProj);
    const auto unproject = [&](float x, float y, float z) {
        const glm::vec4 h = inv * glm::vec4(x, y, z, 1.0f);
        return glm::vec3(h) / h.w;
    };
    const glm::vec3 fwd = glm::normalize(vm.forward);
    std::array<glm::vec3, 4> nearC, farC;
    const float xs[4] = {-1, 1, 1, -1}, ys[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; ++k) {  // along each corner ray (parallel ones when orthographic) to `depth` in front of the eye
        nearC[size_t(k)] = unproject(xs[k], ys[k], 0.0f);
        const glm::vec3 dir = unproject(xs[k], ys[k], 0.5f) - nearC[size_t(k)];
        const float along = glm::dot(dir, fwd);
        const float t = along > 1e-20f ? (float(depth) - glm::dot(nearC[size_t(k)] - vm.eye, fwd)) / along : 0.0f;
        farC[size_t(k)] = nearC[size_t(k)] + dir * t;
    }
    std::vector<float> v;
    const std::array<float, 4> edge{1.0f, 0.55f, 0.1f, 1.0f}, axis{1.0f, 0.85f, 0.3f, 1.0f};
    auto line = [&](const glm::vec3& a, const glm::vec3& b, const std::array<float, 4>& c) {
        for (const glm::vec3& p : {a, b}) {
            v.insert(v.end(), {p.x, p.y, p.z});
            v.insert(v.end(), c.begin(), c.end());
        }
    };
    for (size_t k = 0; k < 4; ++k) {
        line(nearC[k], farC[k], edge);
        line(farC[k], farC[(k + 1) % 4], edge);
        line(nearC[k], nearC[(k + 1) % 4], edge);
    }
    line(vm.eye, vm.eye + fwd * float(depth), axis);
    return v;
}

OverlayScene uploadOverlayScene(Device& dev, const Document& doc) {
    OverlayScene s;
    const std::vector<uint32_t> lines = controlGridLines(doc);
    s.gridIndexCount = uint32_t(lines.size());
    s.gridIndices = uploadStatic(dev, lines, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

    // Boundary curves: 16 segments per window edge.
    std::vector<float> verts;
    const std::vector<PatchInstance> inst = expandPatches(doc);
    constexpr int kSeg = 16;
    WindowTrims trims(doc);
    const EdgeJoinIndex joined(doc);  // each window edge's join in O(1), not a scan of the joins (O(patches × joins))
    // Every window edge in full, 2 points of 7 floats a segment: reserved at once (growing by
    // doubling copied about twice the final 59 MB at 16 384 windows, the release's largest cost).
    verts.reserve(inst.size() * 4 * kSeg * 2 * 7);
    for (const PatchInstance& pi : inst) {
        const WindowNet net = gatherWindow(doc, pi.idx);
        const std::optional<WindowTrim> trim = trims.of(pi);  // its edges only where the trims keep them (issue 64)
        for (int e = 0; e < 4; ++e) {
            const Edge edge = Edge(e);
            const Continuity* cont = nullptr;
            std::array<float, 4> col;
            if (pi.patch >= 0) {
                if (const int j = joined.at(uint32_t(pi.patch), edge); j >= 0) cont = &doc.joins[size_t(j)].continuity;
                col = continuityColor(cont);
            } else {
                col = {0.2f, 0.85f, 0.9f, 1.0f};
            }
            auto at = [&](int k) {
                const double t = double(k) / kSeg;
                const double u = (edge == Edge::U0) ? 0.0 : (edge == Edge::U1) ? 1.0 : t;
                const double v = (edge == Edge::V0) ? 0.0 : (edge == Edge::V1) ? 1.0 : t;
                return evaluateWindow(net, pi.basis, pi.tension, u, v).p;
            };
            auto kept = [&](int k) {  // the middle of piece k-1..k
                if (!trim) return true;
                if (trim->flags & gpu::kTrimAllGone) return false;
                if (!(trim->flags & gpu::kTrimTest)) return true;
                const double t = (k - 0.5) / kSeg;
                const glm::dvec2 uv((edge == Edge::U0)   ? 0.0
                                    : (edge == Edge::U1) ? 1.0
                                                         : t,
                                    (edge == Edge::V0)   ? 0.0
                                    : (edge == Edge::V1) ? 1.0
                                                         : t);
                return trimKeeps(trim->segments, (trim->flags & gpu::kTrimBaseKept) == 0, uv);
            };
            Vec3 prev = at(0);
            for (int k = 1; k <= kSeg; ++k) {
                const Vec3 cur = at(k);
                if (!kept(k)) {
                    prev = cur;
                    continue;
                }
                for (const Vec3& p : {prev, cur}) {
                    verts.insert(verts.end(), {float(p.x), float(p.y), float(p.z)});
                    verts.insert(verts.end(), col.begin(), col.end());
                }
                prev = cur;
            }
        }
    }
    // Trim edges: every loop on its surface, in the colour of an open boundary (C0 where two
    // surfaces share the cut).
    auto trimEdges = [&](const SurfaceRef& ref, const std::vector<TrimLoop>& loops) {
        if (loops.empty()) return;
        const DomainSurface surface(doc, ref);
        const std::array<float, 4> col = continuityColor(nullptr);
        for (const TrimLoop& l : loops) {
            const std::vector<glm::dvec2> uv = loopPolyline(l, 12);
            for (size_t k = 0; k < uv.size(); ++k) {
                for (const glm::dvec2& q : {uv[k], uv[(k + 1) % uv.size()]}) {
                    const Vec3 p = surface.evaluate({q.x, q.y}).p;
                    verts.insert(verts.end(), {float(p.x), float(p.y), float(p.z)});
                    verts.insert(verts.end(), col.begin(), col.end());
                }
            }
        }
    };
    for (uint32_t p = 0; p < doc.patches.size(); ++p) trimEdges(SurfaceRef{false, p}, doc.patches[p].trims);
    for (uint32_t n = 0; n < doc.surfaces.size(); ++n) trimEdges(SurfaceRef{true, n}, doc.surfaces[n].trims);
    s.boundaryVertexCount = uint32_t(verts.size() / 7);
    s.boundaryVerts = uploadStatic(dev, verts, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    return s;
}

}  // namespace scene
}  // namespace pw::render

#include "core/select/edge_pick.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/eval/bezier_curve.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/topology.hpp"
#include "core/select/picking.hpp"

namespace pw {
inline namespace select {

std::vector<Vec3> boundaryCurve(const Document& doc, uint32_t p, Edge e, int n) {
    std::vector<Vec3> out;
    if (isTriangleEdge(e)) {  // Bézier triangles take no weights: the edge is the cubic of its points
        const std::vector<uint32_t> pool = edgePoolOf(doc, p, e);
        if (pool.size() != 4) return out;
        const std::array<Vec3, 4> q{doc.points[pool[0]], doc.points[pool[1]], doc.points[pool[2]], doc.points[pool[3]]};
        for (int s = 0; s <= n; ++s) out.push_back(evaluateCurve(q, double(s) / n));
        return out;
    }
    if (p >= doc.patches.size()) return out;
    const Patch& pt = doc.patches[p];
    const WindowNet net = gatherWindow(doc, pt.idx);
    out.reserve(size_t(n + 1));
    for (int s = 0; s <= n; ++s) {
        const double t = double(s) / n;
        const double u = e == Edge::U0 ? 0.0 : e == Edge::U1 ? 1.0 : t, v = e == Edge::V0 ? 0.0 : e == Edge::V1 ? 1.0 : t;
        out.push_back(evaluateWindow(net, pt.basis, pt.tension, u, v).p);
    }
    return out;
}

std::optional<PatchEdge> pickBoundaryEdge(const Document& doc, const Camera& cam, double x, double y, int width, int height,
                                          double radiusPx, int skipPatch) {
    const ViewMatrices vm = viewMatrices(cam, double(width) / std::max(height, 1));
    const glm::dvec2 m(x, y);
    struct Candidate {
        PatchEdge edge;
        double distance;
    };
    std::vector<Candidate> near;
    const EdgeJoinIndex joined(doc);
    for (uint32_t p = 0; p < doc.patches.size(); ++p) {
        const Patch& pt = doc.patches[p];
        if (int(p) == skipPatch || pt.hidden || pt.basis != Basis::Bezier) continue;
        for (int e = 0; e < 4; ++e) {
            if (joined.at(p, Edge(e)) >= 0) continue;
            const std::vector<Vec3> curve = boundaryCurve(doc, p, Edge(e));
            double best = radiusPx;
            std::optional<glm::dvec2> prev;
            for (const Vec3& q : curve) {
                const auto s = projectToPixel(vm, q, width, height);
                if (s && prev) best = std::min(best, segmentDistance(m, *prev, *s));
                prev = s;
            }
            if (best < radiusPx) near.push_back({{p, Edge(e)}, best});
        }
    }
    if (near.empty()) return std::nullopt;
    const auto nearest =
        std::min_element(near.begin(), near.end(), [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
    // Edges within 2 px of the nearest lie on top of each other: the patch under the mouse wins.
    if (near.size() < 2) return nearest->edge;
    if (const auto hit = pickSurface(doc, rayThroughPixel(cam, x, y, width, height)); hit && hit->patch >= 0)
        for (const Candidate& c : near)
            if (int(c.edge.patch) == hit->patch && c.distance <= nearest->distance + 2.0) return c.edge;
    return nearest->edge;
}

std::string patchEdgeName(const PatchEdge& e) { return std::to_string(e.patch) + ":" + std::string(edgeName(e.edge)); }

}  // namespace select
}  // namespace pw

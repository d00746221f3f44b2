#include "core/select/symmetry.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/select/picking.hpp"

namespace pw {
inline namespace select {

std::string symmetryName(const Symmetry& s) { return s.on() ? std::string(1, char('X' + s.axis)) : "off"; }

namespace {
Vec3 reflect(Vec3 p, const Symmetry& s) {
    p[s.axis] = 2.0 * s.offset - p[s.axis];
    return p;
}
}  // namespace

std::vector<uint32_t> SymmetryPairs::driven(const std::vector<uint32_t>& moved) const {
    std::vector<uint32_t> sorted = moved;
    std::sort(sorted.begin(), sorted.end());
    std::vector<uint32_t> out = sorted;
    // Partners of the moved points only (pairs made for soft points too leave theirs free).
    for (const auto& pr : partners)
        if (std::binary_search(sorted.begin(), sorted.end(), pr.first)) out.push_back(pr.second);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

SymmetryPairs symmetryPairs(const Document& doc, const std::vector<uint32_t>& moved, const Symmetry& s) {
    SymmetryPairs out;
    if (!s.on()) return out;
    const double tol = 1e-6 * std::max(modelSize(doc), 1e-9);
    const std::vector<bool> used = usedPointMask(doc);
    std::vector<bool> isMoved(doc.points.size(), false);
    for (uint32_t p : moved)
        if (p < isMoved.size()) isMoved[p] = true;
    // Candidates sorted by the mirror axis: each search looks at a thin slab only.
    std::vector<uint32_t> byAxis;
    for (uint32_t i = 0; i < doc.points.size(); ++i)
        if (used[i]) byAxis.push_back(i);
    std::sort(byAxis.begin(), byAxis.end(), [&](uint32_t a, uint32_t b) { return doc.points[a][s.axis] < doc.points[b][s.axis]; });
    for (uint32_t p : moved) {
        if (p >= doc.points.size()) continue;
        if (std::abs(doc.points[p][s.axis] - s.offset) <= tol) {
            out.onPlane.push_back(p);
            continue;
        }
        const Vec3 m = reflect(doc.points[p], s);
        auto it = std::lower_bound(byAxis.begin(), byAxis.end(), m[s.axis] - tol,
                                   [&](uint32_t a, double v) { return doc.points[a][s.axis] < v; });
        int best = -1;
        double bestD = tol;
        for (; it != byAxis.end() && doc.points[*it][s.axis] <= m[s.axis] + tol; ++it) {
            const double d = glm::length(doc.points[*it] - m);
            if (d <= bestD) bestD = d, best = int(*it);
        }
        if (best >= 0 && !isMoved[size_t(best)]) out.partners.emplace_back(p, uint32_t(best));
    }
    return out;
}

std::optional<std::pair<uint32_t, Edge>> mirrorEdge(const Document& doc, uint32_t p, Edge e, const Symmetry& s) {
    if (!s.on() || p >= doc.patches.size()) return std::nullopt;
    std::array<uint32_t, 4> edge{}, image{};
    for (int k = 0; k < 4; ++k) edge[size_t(k)] = doc.patches[p].idx[size_t(edgeSlot(e, k))];
    const SymmetryPairs pairs = symmetryPairs(doc, {edge.begin(), edge.end()}, s);
    for (size_t k = 0; k < 4; ++k) {
        const uint32_t i = edge[k];
        const auto partner = std::find_if(pairs.partners.begin(), pairs.partners.end(), [&](const auto& pq) { return pq.first == i; });
        if (partner != pairs.partners.end())
            image[k] = partner->second;
        else if (std::find(pairs.onPlane.begin(), pairs.onPlane.end(), i) != pairs.onPlane.end())
            image[k] = i;
        else
            return std::nullopt;
    }
    if (image == edge || image == reversedEdgePool(edge)) return std::nullopt;
    for (uint32_t q = 0; q < doc.patches.size(); ++q)
        for (Edge f : {Edge::U0, Edge::U1, Edge::V0, Edge::V1}) {
            std::array<uint32_t, 4> other{};
            for (int k = 0; k < 4; ++k) other[size_t(k)] = doc.patches[q].idx[size_t(edgeSlot(f, k))];
            if (other == image || other == reversedEdgePool(image)) return std::pair{q, f};
        }
    return std::nullopt;
}

void applySymmetry(std::vector<Vec3>& points, const SymmetryPairs& pairs, const Symmetry& s) {
    if (!s.on()) return;
    for (uint32_t p : pairs.onPlane) points[p][s.axis] = s.offset;
    for (const auto& [p, q] : pairs.partners) points[q] = reflect(points[p], s);
}

}  // namespace select
}  // namespace pw

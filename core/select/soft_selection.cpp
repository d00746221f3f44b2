#include "core/select/soft_selection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <queue>

namespace pw {
inline namespace select {

namespace {

constexpr std::array<std::string_view, 4> kFalloffNames{"smooth", "linear", "sharp", "constant"};

// The control polygons as an adjacency list over the pool: neighbouring points of every patch
// (4 × 4), net (rows × cols, wrapping where closed), triangle (its lattice) and curve.
std::vector<std::vector<uint32_t>> netNeighbours(const Document& doc) {
    std::vector<std::vector<uint32_t>> adj(doc.points.size());
    const auto link = [&](uint32_t a, uint32_t b) {
        if (a == b || a >= adj.size() || b >= adj.size()) return;
        adj[a].push_back(b);
        adj[b].push_back(a);
    };
    const auto grid = [&](const uint32_t* idx, uint32_t rows, uint32_t cols, bool wrapU, bool wrapV) {
        for (uint32_t i = 0; i < rows; ++i)
            for (uint32_t j = 0; j < cols; ++j) {
                if (j + 1 < cols || wrapU) link(idx[i * cols + j], idx[i * cols + (j + 1) % cols]);
                if (i + 1 < rows || wrapV) link(idx[i * cols + j], idx[((i + 1) % rows) * cols + j]);
            }
    };
    for (const Patch& p : doc.patches) grid(p.idx.data(), 4, 4, false, false);
    for (const Surface& s : doc.surfaces)
        if (s.idx.size() == size_t(s.rows) * s.cols) grid(s.idx.data(), s.rows, s.cols, s.closedU, s.closedV);
    // A cubic triangle's lattice rows (slots 0 | 1 2 | 3 4 5 | 6 7 8 9): each point to its row
    // neighbour and to the two below it.
    for (const TrianglePatch& t : doc.triangles) {
        int first = 0;
        for (int row = 0; row < 4; first += row + 1, ++row)
            for (int k = 0; k <= row; ++k) {
                const int s = first + k;
                if (k < row) link(t.idx[size_t(s)], t.idx[size_t(s + 1)]);
                if (row < 3) link(t.idx[size_t(s)], t.idx[size_t(s + row + 1)]), link(t.idx[size_t(s)], t.idx[size_t(s + row + 2)]);
            }
    }
    for (const BezierCurve& c : doc.curves)
        for (size_t k = 0; k + 1 < c.idx.size(); ++k) link(c.idx[k], c.idx[k + 1]);
    for (auto& a : adj) {
        std::sort(a.begin(), a.end());
        a.erase(std::unique(a.begin(), a.end()), a.end());
    }
    return adj;
}

}  // namespace

std::string_view falloffName(Falloff f) { return kFalloffNames[size_t(f)]; }

std::optional<Falloff> parseFalloff(std::string_view name) {
    for (size_t i = 0; i < kFalloffNames.size(); ++i)
        if (kFalloffNames[i] == name) return Falloff(i);
    return std::nullopt;
}

double falloffWeight(const SoftSelection& s, double d) {
    if (!(s.radius > 0.0) || d >= s.radius) return 0.0;
    const double x = 1.0 - std::max(d, 0.0) / s.radius;  // 1 at the moved point, 0 at the radius
    switch (s.falloff) {
        case Falloff::Smooth:
            return x * x * (3.0 - 2.0 * x);
        case Falloff::Linear:
            return x;
        case Falloff::Sharp:
            return x * x;
        case Falloff::Constant:
            return 1.0;
    }
    return 0.0;
}

SoftWeights softWeights(const Document& doc, const std::vector<uint32_t>& moved, const SoftSelection& s, const Symmetry& sym) {
    SoftWeights out;
    if (!s.on || !(s.radius > 0.0) || moved.empty()) return out;
    const std::vector<std::vector<uint32_t>> adj = netNeighbours(doc);
    // Dijkstra from every moved point at once, stopping at the radius.
    std::vector<double> dist(doc.points.size(), std::numeric_limits<double>::infinity());
    std::vector<char> isMoved(doc.points.size(), 0);
    for (uint32_t p : moved)
        if (p < isMoved.size()) isMoved[p] = 1;
    using Item = std::pair<double, uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (uint32_t p : moved)
        if (p < dist.size()) dist[p] = 0.0, queue.push({0.0, p});
    while (!queue.empty()) {
        const auto [d, p] = queue.top();
        queue.pop();
        if (d > dist[p]) continue;
        for (uint32_t q : adj[p]) {
            const double nd = d + glm::length(doc.points[q] - doc.points[p]);
            if (nd < dist[q] && nd < s.radius) dist[q] = nd, queue.push({nd, q});
        }
    }
    // The side of the symmetry plane the moved points are on (0: both, or no symmetry).
    const double tol = 1e-6 * std::max(modelSize(doc), 1e-9);
    int side = 0;
    if (sym.on())
        for (uint32_t p : moved) {
            const double d = p < doc.points.size() ? doc.points[p][sym.axis] - sym.offset : 0.0;
            const int sd = d > tol ? 1 : d < -tol ? -1 : 0;
            if (sd == 0) continue;
            if (side != 0 && sd != side) {
                side = 0;
                break;
            }
            side = sd;
        }
    for (uint32_t i = 0; i < dist.size(); ++i)
        if (!isMoved[i] && dist[i] < s.radius && (side == 0 || (doc.points[i][sym.axis] - sym.offset) * side >= -tol)) {
            const double w = falloffWeight(s, dist[i]);
            if (w > 0.0) out.points.push_back(i), out.weights.push_back(w);
        }
    return out;
}

std::string softDescription(const SoftSelection& s) {
    if (!s.on) return "soft off";
    char buf[64];
    std::snprintf(buf, sizeof buf, "soft %.3g %s", s.radius, std::string(falloffName(s.falloff)).c_str());
    return buf;
}

}  // namespace select
}  // namespace pw

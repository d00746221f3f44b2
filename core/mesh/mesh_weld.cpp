#include "core/mesh/mesh_weld.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace pw {
inline namespace mesh {

namespace {

// cos(2°): normals closer than this at one position are one smooth vertex.
constexpr double kWeldSmoothCos = 0.99939082701909573;

struct CellHash {
    size_t operator()(const std::array<int64_t, 3>& c) const {
        uint64_t h = 1469598103934665603ull;
        for (int64_t v : c) h = (h ^ uint64_t(v)) * 1099511628211ull;
        return size_t(h);
    }
};

// Finds the position cluster of each point: a point seen before within `tol` (per coordinate) of it,
// through a grid of cells 16 `tol` wide. A match lies in a cell that the box p ± tol touches: the
// point's own cell, which is searched first (a surface's vertices are each met about six times, at
// one position), and a neighbour only where p is within `tol` of that face, so a search takes one
// or two lookups instead of the 27 of cells `tol` wide (the as-displayed export spent a third of its
// time here).
class PositionClusters {
public:
    explicit PositionClusters(double tol) : tol_(tol), inv_(tol > 0.0 ? 1.0 / (16.0 * tol) : 0.0) {}

    // The cluster of p among those `accept` allows, or a new one.
    template <class Accept>
    uint32_t find(const float p[3], Accept&& accept) {
        const std::array<int64_t, 3> c = cell(p);
        if (tol_ > 0.0) {
            if (auto it = cells_.find(c); it != cells_.end())
                for (uint32_t id : it->second)
                    if (near(reps_[id], p) && accept(id)) return id;
            std::array<int64_t, 3> lo{}, hi{};
            for (int i = 0; i < 3; ++i) {
                lo[size_t(i)] = int64_t(std::floor((double(p[i]) - tol_) * inv_));
                hi[size_t(i)] = int64_t(std::floor((double(p[i]) + tol_) * inv_));
            }
            for (int64_t x = lo[0]; x <= hi[0]; ++x)
                for (int64_t y = lo[1]; y <= hi[1]; ++y)
                    for (int64_t z = lo[2]; z <= hi[2]; ++z) {
                        if (std::array<int64_t, 3>{x, y, z} == c) continue;  // searched above
                        auto it = cells_.find({x, y, z});
                        if (it == cells_.end()) continue;
                        for (uint32_t id : it->second)
                            if (near(reps_[id], p) && accept(id)) return id;
                    }
        } else if (auto it = cells_.find(c); it != cells_.end()) {
            for (uint32_t id : it->second)
                if (reps_[id] == std::array<float, 3>{p[0], p[1], p[2]} && accept(id)) return id;
        }
        const auto id = uint32_t(reps_.size());
        reps_.push_back({p[0], p[1], p[2]});
        cells_[c].push_back(id);
        return id;
    }
    const std::array<float, 3>& position(uint32_t id) const { return reps_[id]; }
    size_t size() const { return reps_.size(); }

private:
    std::array<int64_t, 3> cell(const float p[3]) const {
        if (tol_ <= 0.0) {  // exact: hash the bits
            std::array<int64_t, 3> c{};
            for (int i = 0; i < 3; ++i) c[i] = int64_t(std::hash<float>{}(p[i] == 0.0f ? 0.0f : p[i]));
            return c;
        }
        return {int64_t(std::floor(double(p[0]) * inv_)), int64_t(std::floor(double(p[1]) * inv_)),
                int64_t(std::floor(double(p[2]) * inv_))};
    }
    bool near(const std::array<float, 3>& a, const float p[3]) const {
        for (int i = 0; i < 3; ++i)
            if (std::abs(double(a[i]) - double(p[i])) > tol_) return false;
        return true;
    }
    double tol_, inv_;
    std::unordered_map<std::array<int64_t, 3>, std::vector<uint32_t>, CellHash> cells_;
    std::vector<std::array<float, 3>> reps_;
};

}  // namespace

TriangleMesh weldTriangleSoup(const std::vector<SoupVertex>& soup, size_t windowCount, size_t triangleCount, double tolerance,
                              WeldStats* stats, const std::vector<uint8_t>* collapsedEdges) {
    if (soup.size() % 3 != 0)
        throw std::invalid_argument("the captured surface has " + std::to_string(soup.size()) + " vertices, not whole triangles");
    const size_t items = windowCount + triangleCount, tris = soup.size() / 3;
    // Triangles in item order (the GPU's order within an item), by counting sort.
    std::vector<uint32_t> start(items + 1, 0);
    for (size_t t = 0; t < tris; ++t) {
        const uint32_t item = soup[3 * t].item;
        if (item >= items)
            throw std::invalid_argument("the captured surface names item " + std::to_string(item) + " of " + std::to_string(items));
        ++start[item + 1];
    }
    for (size_t i = 0; i < items; ++i) start[i + 1] += start[i];
    std::vector<uint32_t> order(tris), next(start.begin(), start.end() - 1);
    for (size_t t = 0; t < tris; ++t) order[next[soup[3 * t].item]++] = uint32_t(t);

    TriangleMesh mesh;
    PositionClusters clusters(tolerance);
    // Per cluster, the window vertices in it (item, u, v), one per window and parameter: another
    // vertex of one of those windows at other (u, v) joins it only bit-identical or with both on
    // one collapsed edge (every member is checked: across a seam a cluster holds two windows).
    struct Origin {
        uint32_t item;
        float u, v;
    };
    std::vector<std::vector<Origin>> origins;
    auto onCollapsedEdge = [&](uint32_t item, float u, float v) -> uint8_t {
        const uint8_t bits = (*collapsedEdges)[item];
        return uint8_t(((bits & 1) && u == 0.0f ? 1 : 0) | ((bits & 2) && v == 0.0f ? 2 : 0) | ((bits & 4) && u == 1.0f ? 4 : 0) |
                       ((bits & 8) && v == 1.0f ? 8 : 0));
    };
    // Per position cluster, its vertices so far: (vertex id, first normal); normals summed in `sums`.
    std::vector<std::vector<std::pair<uint32_t, std::array<float, 3>>>> atPosition;
    std::vector<std::array<double, 3>> sums;
    auto vertexOf = [&](const SoupVertex& v) -> uint32_t {
        const bool checked = collapsedEdges && v.item < windowCount && v.item < collapsedEdges->size();
        const uint32_t pc = clusters.find(v.position, [&](uint32_t id) {
            if (!checked || clusters.position(id) == std::array<float, 3>{v.position[0], v.position[1], v.position[2]}) return true;
            for (const Origin& o : origins[id])
                if (o.item == v.item && (o.u != v.uv[0] || o.v != v.uv[1]) &&
                    (onCollapsedEdge(o.item, o.u, o.v) & onCollapsedEdge(v.item, v.uv[0], v.uv[1])) == 0)
                    return false;
            return true;
        });
        if (pc >= origins.size()) origins.resize(pc + 1);
        if (checked && std::none_of(origins[pc].begin(), origins[pc].end(),
                                    [&](const Origin& o) { return o.item == v.item && o.u == v.uv[0] && o.v == v.uv[1]; }))
            origins[pc].push_back({v.item, v.uv[0], v.uv[1]});
        if (pc >= atPosition.size()) atPosition.resize(pc + 1);
        for (auto& [id, n0] : atPosition[pc])
            if (double(n0[0]) * v.normal[0] + double(n0[1]) * v.normal[1] + double(n0[2]) * v.normal[2] > kWeldSmoothCos) {
                for (int i = 0; i < 3; ++i) sums[id][i] += v.normal[i];
                return id;
            }
        const auto id = uint32_t(mesh.positions.size());
        mesh.positions.push_back(clusters.position(pc));
        mesh.normals.push_back({v.normal[0], v.normal[1], v.normal[2]});
        mesh.uvs.push_back({v.uv[0], v.uv[1]});
        sums.push_back({v.normal[0], v.normal[1], v.normal[2]});
        atPosition[pc].push_back({id, {v.normal[0], v.normal[1], v.normal[2]}});
        return id;
    };

    mesh.indices.reserve(soup.size());
    WeldStats st;
    st.soupTriangles = tris;
    for (size_t item = 0; item < items; ++item) {
        MeshRange r;
        r.firstIndex = uint32_t(mesh.indices.size());
        for (uint32_t k = start[item]; k < start[item + 1]; ++k) {
            const size_t t = order[k];
            const uint32_t a = vertexOf(soup[3 * t]), b = vertexOf(soup[3 * t + 1]), c = vertexOf(soup[3 * t + 2]);
            const size_t before = mesh.indices.size();
            mesh.addTriangle(a, b, c);
            if (mesh.indices.size() == before) ++st.degenerateTriangles;
        }
        r.indexCount = uint32_t(mesh.indices.size()) - r.firstIndex;
        (item < windowCount ? mesh.perWindow : mesh.perTriangle).push_back(r);
    }
    for (size_t v = 0; v < mesh.normals.size(); ++v) {
        const auto& s = sums[v];
        const double len = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
        if (len > 1e-12) mesh.normals[v] = {float(s[0] / len), float(s[1] / len), float(s[2] / len)};
    }
    removeUnusedVertices(mesh);  // those only collapsed triangles used
    if (stats) *stats = st;
    return mesh;
}

std::vector<uint8_t> collapsedWindowEdges(const std::vector<PatchInstance>& windows, const std::vector<Vec3>& points) {
    std::vector<uint8_t> bits(windows.size(), 0);
    for (size_t w = 0; w < windows.size(); ++w) {
        if (windows[w].basis != Basis::Bezier) continue;
        for (int e = 0; e < 4; ++e)
            if (windowEdgeCollapsed(points, windows[w], Edge(e))) bits[w] |= uint8_t(1 << e);
    }
    return bits;
}

}  // namespace mesh
}  // namespace pw

#include "core/mesh/mesh_weld.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

namespace pw {
inline namespace mesh {

namespace {

// cos(2°): normals closer than this at one position are one smooth vertex.
constexpr double kWeldSmoothCos = 0.99939082701909573;

// Finds the position cluster of each point: a point seen before within `tol` (per coordinate) of it,
// through a grid of cells 16 `tol` wide. A match lies in a cell that the box p ± tol touches: the
// point's own cell, which is searched first (a surface's vertices are each met about six times, at
// one position), and a neighbour only where p is within `tol` of that face, so a search takes one
// or two lookups instead of the 27 of cells `tol` wide (the as-displayed export spent a third of its
// time here).
class PositionClusters {
public:
    explicit PositionClusters(double tol, size_t expected) : tol_(tol), inv_(tol > 0.0 ? 1.0 / (16.0 * tol) : 0.0) {
        size_t size = 16;
        while (size < 2 * expected) size *= 2;
        slots_.assign(size, Slot{});
        reps_.reserve(expected);
        nextInCell_.reserve(expected);
    }

    // The cluster of p among those `accept` allows, or a new one.
    template <class Accept>
    uint32_t find(const float p[3], Accept&& accept) {
        const std::array<int64_t, 3> c = cell(p);
        const auto scan = [&](uint32_t head, bool exact) {
            for (uint32_t id = head; id != kNone; id = nextInCell_[id])
                if ((exact ? reps_[id] == std::array<float, 3>{p[0], p[1], p[2]} : near(reps_[id], p)) && accept(id)) return id;
            return kNone;
        };
        if (tol_ > 0.0) {
            if (const uint32_t id = scan(head(c), false); id != kNone) return id;
            std::array<int64_t, 3> lo{}, hi{};
            for (int i = 0; i < 3; ++i) {
                lo[size_t(i)] = int64_t(std::floor((double(p[i]) - tol_) * inv_));
                hi[size_t(i)] = int64_t(std::floor((double(p[i]) + tol_) * inv_));
            }
            for (int64_t x = lo[0]; x <= hi[0]; ++x)
                for (int64_t y = lo[1]; y <= hi[1]; ++y)
                    for (int64_t z = lo[2]; z <= hi[2]; ++z) {
                        if (std::array<int64_t, 3>{x, y, z} == c) continue;  // searched above
                        if (const uint32_t id = scan(head({x, y, z}), false); id != kNone) return id;
                    }
        } else if (const uint32_t id = scan(head(c), true); id != kNone) {
            return id;
        }
        const auto id = uint32_t(reps_.size());
        reps_.push_back({p[0], p[1], p[2]});
        auto [cellSlot, isNew] = slot(c);
        nextInCell_.push_back(kNone);  // at the end of its cell's list: clusters are tried in the order they came
        if (isNew)
            cellSlot->head = id;
        else
            nextInCell_[cellSlot->tail] = id;
        cellSlot->tail = id;
        if (isNew && ++used_ * 2 > slots_.size()) grow();
        return id;
    }
    const std::array<float, 3>& position(uint32_t id) const { return reps_[id]; }
    size_t size() const { return reps_.size(); }

private:
    static constexpr uint32_t kNone = 0xffffffffu;
    // An open-addressing table of the cells in use, each the ends of its clusters' list (nextInCell_):
    // no allocation per cell or cluster (a map of vectors spent a fifth of the export in malloc).
    struct Slot {
        std::array<int64_t, 3> key{};
        uint32_t head = kNone, tail = kNone;
    };
    size_t indexOf(const std::array<int64_t, 3>& c) const {
        uint64_t h = 1469598103934665603ull;
        for (int64_t v : c) h = (h ^ uint64_t(v)) * 1099511628211ull;
        return size_t(h ^ (h >> 29)) & (slots_.size() - 1);
    }
    uint32_t head(const std::array<int64_t, 3>& c) const {
        for (size_t i = indexOf(c);; i = (i + 1) & (slots_.size() - 1)) {
            if (slots_[i].head == kNone) return kNone;
            if (slots_[i].key == c) return slots_[i].head;
        }
    }
    // The slot of cell c, and whether it is new (taken now).
    std::pair<Slot*, bool> slot(const std::array<int64_t, 3>& c) {
        for (size_t i = indexOf(c);; i = (i + 1) & (slots_.size() - 1)) {
            if (slots_[i].head == kNone) {
                slots_[i].key = c;
                return {&slots_[i], true};
            }
            if (slots_[i].key == c) return {&slots_[i], false};
        }
    }
    void grow() {
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(old.size() * 2, Slot{});
        for (const Slot& s : old)
            if (s.head != kNone) {
                size_t i = indexOf(s.key);
                while (slots_[i].head != kNone) i = (i + 1) & (slots_.size() - 1);
                slots_[i] = s;
            }
    }
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
    std::vector<Slot> slots_;
    size_t used_ = 0;  // slots holding a cell
    std::vector<std::array<float, 3>> reps_;
    std::vector<uint32_t> nextInCell_;  // per cluster, the next of its cell
};

}  // namespace

struct SoupWelder::State {
    static constexpr uint32_t kNone = 0xffffffffu;
    State(size_t windows, size_t triangles, double tolerance, const std::vector<uint8_t>* collapsed, size_t expected)
        : windowCount(windows), items(windows + triangles), collapsedEdges(collapsed), clusters(tolerance, expected / 4) {
        // A surface's vertex is met about six times in the soup.
        for (auto* v : {&firstVertex, &nextVertex, &firstOrigin}) v->reserve(expected / 5);
        mesh.positions.reserve(expected / 5);
        mesh.normals.reserve(expected / 5);
        mesh.uvs.reserve(expected / 5);
        sums.reserve(expected / 5);
        firstNormal.reserve(expected / 5);
        mesh.indices.reserve(expected);
        mesh.perWindow.reserve(windows);
        mesh.perTriangle.reserve(triangles);
    }

    size_t windowCount, items;
    const std::vector<uint8_t>* collapsedEdges;
    PositionClusters clusters;
    size_t nextItem = 0;  // items before it have their ranges
    TriangleMesh mesh;
    WeldStats st;
    std::vector<uint32_t> start, order, next;  // a piece's counting sort, kept between pieces
    // Per cluster, the window vertices in it (item, u, v), one per window and parameter: another
    // vertex of one of those windows at other (u, v) joins it only bit-identical or with both on
    // one collapsed edge (every member is checked: across a seam a cluster holds two windows).
    // Lists threaded through flat arrays (no allocation per cluster).
    struct Origin {
        uint32_t item;
        float u, v;
        uint32_t next;  // the cluster's next origin
    };
    std::vector<Origin> origins;
    std::vector<uint32_t> firstOrigin;  // per cluster
    // Per position cluster, its vertices so far (firstVertex, then nextVertex), each with its
    // first normal; normals summed in `sums`.
    std::vector<uint32_t> firstVertex, nextVertex;
    std::vector<std::array<float, 3>> firstNormal;
    std::vector<std::array<double, 3>> sums;

    uint8_t onCollapsedEdge(uint32_t item, float u, float v) const {
        const uint8_t bits = (*collapsedEdges)[item];
        return uint8_t(((bits & 1) && u == 0.0f ? 1 : 0) | ((bits & 2) && v == 0.0f ? 2 : 0) | ((bits & 4) && u == 1.0f ? 4 : 0) |
                       ((bits & 8) && v == 1.0f ? 8 : 0));
    }

    uint32_t vertexOf(const SoupVertex& v) {
        const bool checked = collapsedEdges && v.item < windowCount && v.item < collapsedEdges->size();
        const uint32_t pc = clusters.find(v.position, [&](uint32_t id) {
            if (!checked || clusters.position(id) == std::array<float, 3>{v.position[0], v.position[1], v.position[2]}) return true;
            for (uint32_t k = firstOrigin[id]; k != kNone; k = origins[k].next) {
                const Origin& o = origins[k];
                if (o.item == v.item && (o.u != v.uv[0] || o.v != v.uv[1]) &&
                    (onCollapsedEdge(o.item, o.u, o.v) & onCollapsedEdge(v.item, v.uv[0], v.uv[1])) == 0)
                    return false;
            }
            return true;
        });
        if (pc >= firstOrigin.size()) {
            firstOrigin.resize(pc + 1, kNone);
            firstVertex.resize(pc + 1, kNone);
        }
        if (checked) {
            bool known = false;
            for (uint32_t k = firstOrigin[pc]; k != kNone && !known; k = origins[k].next)
                known = origins[k].item == v.item && origins[k].u == v.uv[0] && origins[k].v == v.uv[1];
            if (!known) {
                origins.push_back({v.item, v.uv[0], v.uv[1], firstOrigin[pc]});
                firstOrigin[pc] = uint32_t(origins.size() - 1);
            }
        }
        for (uint32_t id = firstVertex[pc]; id != kNone; id = nextVertex[id]) {
            const auto& n0 = firstNormal[id];
            if (double(n0[0]) * v.normal[0] + double(n0[1]) * v.normal[1] + double(n0[2]) * v.normal[2] > kWeldSmoothCos) {
                for (int i = 0; i < 3; ++i) sums[id][i] += v.normal[i];
                return id;
            }
        }
        const auto id = uint32_t(mesh.positions.size());
        mesh.positions.push_back(clusters.position(pc));
        mesh.normals.push_back({v.normal[0], v.normal[1], v.normal[2]});
        mesh.uvs.push_back({v.uv[0], v.uv[1]});
        sums.push_back({v.normal[0], v.normal[1], v.normal[2]});
        firstNormal.push_back({v.normal[0], v.normal[1], v.normal[2]});
        // Appended at the list's end: the vertices of a cluster are tried in the order they came.
        nextVertex.push_back(kNone);
        if (firstVertex[pc] == kNone) {
            firstVertex[pc] = id;
        } else {
            uint32_t last = firstVertex[pc];
            while (nextVertex[last] != kNone) last = nextVertex[last];
            nextVertex[last] = id;
        }
        return id;
    }

    // Ranges for the items from nextItem up to `end` (exclusive), whose triangles are those of
    // `order` between `start` offsets (relative to item `base`), or none.
    void closeItemsUpTo(size_t end, const SoupVertex* soup, size_t base, SoupWinding winding) {
        const size_t second = winding == SoupWinding::Turned ? 2 : 1, third = 3 - second;
        for (; nextItem < end; ++nextItem) {
            MeshRange r;
            r.firstIndex = uint32_t(mesh.indices.size());
            if (soup && nextItem >= base)
                for (uint32_t k = start[nextItem - base]; k < start[nextItem - base + 1]; ++k) {
                    const size_t t = order[k];
                    const uint32_t a = vertexOf(soup[3 * t]), b = vertexOf(soup[3 * t + second]), c = vertexOf(soup[3 * t + third]);
                    const size_t before = mesh.indices.size();
                    mesh.addTriangle(a, b, c);
                    if (mesh.indices.size() == before) ++st.degenerateTriangles;
                }
            r.indexCount = uint32_t(mesh.indices.size()) - r.firstIndex;
            (nextItem < windowCount ? mesh.perWindow : mesh.perTriangle).push_back(r);
        }
    }
};

SoupWelder::SoupWelder(size_t windowCount, size_t triangleCount, double tolerance, const std::vector<uint8_t>* collapsedEdges,
                       size_t expectedVertices)
    : s_(std::make_unique<State>(windowCount, triangleCount, tolerance, collapsedEdges, expectedVertices)) {}

SoupWelder::~SoupWelder() = default;

void SoupWelder::add(const SoupVertex* soup, size_t vertices, SoupWinding winding) {
    State& s = *s_;
    if (vertices % 3 != 0)
        throw std::invalid_argument("the captured surface has " + std::to_string(vertices) + " vertices, not whole triangles");
    const size_t tris = vertices / 3;
    if (tris == 0) return;
    // Triangles in item order (the GPU's order within an item), by counting sort over this piece's items.
    size_t lo = s.items, hi = 0;
    for (size_t t = 0; t < tris; ++t) {
        const uint32_t item = soup[3 * t].item;
        if (item >= s.items)
            throw std::invalid_argument("the captured surface names item " + std::to_string(item) + " of " + std::to_string(s.items));
        lo = std::min<size_t>(lo, item);
        hi = std::max<size_t>(hi, item);
    }
    if (lo < s.nextItem)
        throw std::invalid_argument("a piece of the captured surface names item " + std::to_string(lo) + ", welded before");
    s.start.assign(hi - lo + 2, 0);
    for (size_t t = 0; t < tris; ++t) ++s.start[soup[3 * t].item - lo + 1];
    for (size_t i = 0; i + 1 < s.start.size(); ++i) s.start[i + 1] += s.start[i];
    s.order.resize(tris);
    s.next.assign(s.start.begin(), s.start.end() - 1);
    for (size_t t = 0; t < tris; ++t) s.order[s.next[soup[3 * t].item - lo]++] = uint32_t(t);
    s.st.soupTriangles += tris;
    s.closeItemsUpTo(hi + 1, soup, lo, winding);
}

TriangleMesh SoupWelder::finish(WeldStats* stats) {
    State& s = *s_;
    s.closeItemsUpTo(s.items, nullptr, 0, SoupWinding::AsGiven);
    TriangleMesh mesh = std::move(s.mesh);
    for (size_t v = 0; v < mesh.normals.size(); ++v) {
        const auto& n = s.sums[v];
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 1e-12) mesh.normals[v] = {float(n[0] / len), float(n[1] / len), float(n[2] / len)};
    }
    removeUnusedVertices(mesh);  // those only collapsed triangles used
    if (stats) *stats = s.st;
    return mesh;
}

TriangleMesh weldTriangleSoup(const std::vector<SoupVertex>& soup, size_t windowCount, size_t triangleCount, double tolerance,
                              WeldStats* stats, const std::vector<uint8_t>* collapsedEdges) {
    SoupWelder welder(windowCount, triangleCount, tolerance, collapsedEdges, soup.size());
    welder.add(soup.data(), soup.size());
    return welder.finish(stats);
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

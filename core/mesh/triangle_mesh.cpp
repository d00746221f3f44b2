#include "core/mesh/triangle_mesh.hpp"

#include <map>

#include "core/eval/bezier_triangle.hpp"

namespace pw {
inline namespace mesh {

namespace {

// Normals of two sides meeting at a welded vertex are averaged when they agree within ~10°;
// otherwise (a crease) the later side gets its own vertex at the same position.
constexpr double kTriangleSmoothCos = 0.985;

// Corner slots at the grid corners: (0,0) is w = 1, (n,0) is u = 1, (0,n) is v = 1.
constexpr int kCornerW = 9, kCornerU = 0, kCornerV = 6;

}  // namespace

void appendBezierTriangles(const Document& doc, int level, TriangleMesh& mesh, const BoundaryVertices* quads) {
    const int n = level;
    mesh.perTriangle.resize(doc.triangles.size());

    // Shared vertices: corners by pool index, edge interiors by canonical edge and k; the quads'
    // boundary vertices to start with, each counting its normal once.
    std::map<uint32_t, uint32_t> cornerVertex;
    std::map<std::array<uint32_t, 4>, std::vector<uint32_t>> edgeVertices;
    std::map<uint32_t, std::pair<Vec3, uint32_t>> normalSum;  // welded vertex → (sum, count)
    if (quads) {
        cornerVertex = quads->corners;
        for (const auto& [key, ids] : quads->edges)
            if (ids.size() == size_t(n > 1 ? n - 1 : 0)) edgeVertices.emplace(key, ids);
        auto seed = [&](uint32_t v) {
            if (v == kNoVertex || v >= mesh.normals.size()) return;
            const auto& q = mesh.normals[v];
            normalSum.try_emplace(v, Vec3(q[0], q[1], q[2]), 1u);
        };
        for (const auto& entry : cornerVertex) seed(entry.second);
        for (const auto& entry : edgeVertices)
            for (uint32_t v : entry.second) seed(v);
    }

    std::vector<TriPoint> grid;
    std::vector<uint32_t> ids(triGridSize(n));
    for (size_t t = 0; t < doc.triangles.size(); ++t) {
        const TrianglePatch& tri = doc.triangles[t];
        const Net10 net = gatherTriangleNet(doc, tri.idx);
        evaluateTriangleGrid(net, tri.idx, n, grid);

        auto newVertex = [&](const TriPoint& tp, int i, int j) {
            const uint32_t id = static_cast<uint32_t>(mesh.positions.size());
            mesh.positions.push_back({float(tp.p.x), float(tp.p.y), float(tp.p.z)});
            mesh.normals.push_back({float(tp.n.x), float(tp.n.y), float(tp.n.z)});
            mesh.uvs.push_back({float(double(i) / n), float(double(j) / n)});
            return id;
        };
        // A welded vertex: reuse `slot` when its first normal agrees with this side's.
        auto shared = [&](uint32_t& slot, const TriPoint& tp, int i, int j) {
            if (slot != kNoVertex) {
                auto& [sum, count] = normalSum[slot];
                const auto& first = mesh.normals[slot];
                const Vec3 f(first[0], first[1], first[2]);
                if (glm::dot(f, tp.n) >= kTriangleSmoothCos) {
                    sum += tp.n;
                    ++count;
                    return slot;
                }
                return newVertex(tp, i, j);
            }
            slot = newVertex(tp, i, j);
            normalSum[slot] = {tp.n, 1u};
            return slot;
        };

        // Per edge: canonical key, direction and whether it collapsed to one position.
        std::array<std::array<uint32_t, 4>, 3> key{};
        std::array<bool, 3> flip{}, collapsed{}, weldable{};
        for (int e = 0; e < 3; ++e) {
            const auto pool = triEdgePool(tri.idx, e);
            const auto rev = reversedEdgePool(pool);
            flip[e] = edgeReversed(pool);
            key[e] = flip[e] ? rev : pool;
            const Vec3& p0 = doc.points[pool[0]];
            collapsed[e] = p0 == doc.points[pool[1]] && p0 == doc.points[pool[2]] && p0 == doc.points[pool[3]];
            weldable[e] = rev != pool;  // a palindrome (closed loop) has no canonical direction
        }

        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n - j; ++i) {
                const TriPoint& tp = grid[triGridIndex(i, j, n)];
                uint32_t& id = ids[triGridIndex(i, j, n)];
                const bool onE0 = i == 0, onE1 = j == 0, onE2 = i + j == n;
                const int cornerSlot = onE0 && onE1 ? kCornerW : onE1 && onE2 ? kCornerU : onE0 && onE2 ? kCornerV : -1;
                if (cornerSlot >= 0) {
                    auto [it, inserted] = cornerVertex.try_emplace(tri.idx[cornerSlot], kNoVertex);
                    id = shared(it->second, tp, i, j);
                    continue;
                }
                const int e = onE0 ? 0 : onE1 ? 1 : onE2 ? 2 : -1;
                if (e < 0) {
                    id = newVertex(tp, i, j);
                    continue;
                }
                if (collapsed[e]) {
                    auto [it, inserted] = cornerVertex.try_emplace(tri.idx[triEdgeSlot(e, 0)], kNoVertex);
                    id = shared(it->second, tp, i, j);
                    continue;
                }
                if (!weldable[e]) {
                    id = newVertex(tp, i, j);
                    continue;
                }
                const int k = e == 0 ? n - j : e == 1 ? i : j;
                const int kc = flip[e] ? n - k : k;
                auto [it, inserted] = edgeVertices.try_emplace(key[e]);
                if (inserted) it->second.assign(size_t(n - 1), kNoVertex);
                id = shared(it->second[size_t(kc - 1)], tp, i, j);
            }

        // Two triangles per grid cell pair, counter-clockwise in (u, v), i.e. seen from du × dv.
        MeshRange& range = mesh.perTriangle[t];
        range.firstIndex = static_cast<uint32_t>(mesh.indices.size());
        auto emit = [&](uint32_t a, uint32_t b, uint32_t c) { mesh.addTriangle(a, b, c); };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n - j; ++i) {
                const uint32_t a = ids[triGridIndex(i, j, n)], b = ids[triGridIndex(i + 1, j, n)];
                const uint32_t c = ids[triGridIndex(i, j + 1, n)];
                emit(a, b, c);
                if (i + 1 < n - j) emit(b, ids[triGridIndex(i + 1, j + 1, n)], c);
            }
        range.indexCount = static_cast<uint32_t>(mesh.indices.size()) - range.firstIndex;
    }

    // Welded vertices: the average of the agreeing sides' normals.
    for (const auto& [vid, sc] : normalSum) {
        if (sc.second < 2) continue;
        const double len = glm::length(sc.first);
        if (!(len > 1e-12)) continue;
        const Vec3 nn = sc.first / len;
        mesh.normals[vid] = {float(nn.x), float(nn.y), float(nn.z)};
    }
}

}  // namespace mesh
}  // namespace pw

// CPU tessellation into a welded mesh (DESIGN §5). Each window is evaluated on a level x level grid
// (evaluateGrid: bit-identical shared Bézier boundaries). Interior grid points are the window's own
// vertices; boundary points are shared through small tables keyed by union-find roots:
//   corners   — incidences (window, corner) united across C1/G1 joins and along collapsed edges;
//   edges     — incidences (window, edge) united across C1/G1 joins, k in the canonical direction
//               of the edge's four pool indices (the lexicographically smaller of both orders).
// C0 and unjoined seams keep separate vertices (same position, own normals). Spline surfaces share
// one vertex grid per surface (their windows are C1/C2 by construction).
#include "core/mesh/mesh_tessellate.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

#include "core/base/limits.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace pw {
inline namespace mesh {

namespace {

// Disjoint sets over incidences (window*4 + corner or edge); the smaller id becomes the root so
// that the result does not depend on the order of the joins.
struct UnionFind {
    std::vector<uint32_t> parent;
    explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        return x;
    }
    void unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return;
        if (a < b)
            parent[b] = a;
        else
            parent[a] = b;
    }
};

// Corner number (0..3) of a net slot that is a corner: slot 0 → 0, 3 → 1, 12 → 2, 15 → 3, which is
// also (r == 0 ? 0 : 2) + (c == 0 ? 0 : 1) on the evaluation grid.
int cornerOfSlot(int slot) { return (slot >= 12 ? 2 : 0) + ((slot & 3) == 3 ? 1 : 0); }

std::array<uint32_t, 4> edgePool(const std::array<uint32_t, 16>& idx, Edge e) {
    return {idx[edgeSlot(e, 0)], idx[edgeSlot(e, 1)], idx[edgeSlot(e, 2)], idx[edgeSlot(e, 3)]};
}

constexpr Edge kEdges[4] = {Edge::U0, Edge::V0, Edge::U1, Edge::V1};

// How the boundary vertices of a window are shared with other windows.
enum class WeldMode : uint8_t {
    Bezier,       // through the pool: joined corners and edges (C1/G1) share vertices
    SurfaceGrid,  // a spline surface's window: one vertex grid for the whole surface
    Isolated,     // a spline-basis patch: its boundary depends on more than its edge points
};

struct SurfaceGridInfo {
    uint32_t gridRows = 0, gridCols = 0;  // vertex rows and columns (closed directions wrap)
    size_t base = 0;                      // offset in the shared id array
};

}  // namespace

namespace {

// The 4x4 windows (patches and surface windows) into `mesh`.
// `boundary` receives the Bézier windows' boundary vertices by pool (triangles weld to them).
void tessellateWindows(const Document& doc, const std::vector<PatchInstance>& windows, int level, TriangleMesh& mesh,
                       BoundaryVertices& boundaryByPool) {
    const size_t W = windows.size();
    const int L = level;
    const int S = L + 1;  // grid points per side
    mesh.perWindow.resize(W);
    if (W == 0) return;

    // Per-edge facts for every window: degenerate (collapsed to one point) and the direction of the
    // canonical order of its four pool indices.
    std::vector<uint8_t> collapsed(W * 4, 0), flip(W * 4, 0);
    UnionFind cornerSets(W * 4), edgeSets(W * 4);
    for (size_t w = 0; w < W; ++w) {
        const PatchInstance& inst = windows[w];
        if (inst.basis != Basis::Bezier) continue;
        for (Edge e : kEdges) {
            const size_t k = w * 4 + static_cast<size_t>(e);
            collapsed[k] = windowEdgeCollapsed(doc.points, inst, e);
            flip[k] = edgeReversed(edgePool(inst.idx, e));
            if (collapsed[k])
                cornerSets.unite(static_cast<uint32_t>(w * 4 + cornerOfSlot(edgeSlot(e, 0))),
                                 static_cast<uint32_t>(w * 4 + cornerOfSlot(edgeSlot(e, 3))));
        }
    }

    // C1/G1 joins between Bézier windows whose edges share the same four pool entries: one vertex
    // (and an averaged normal) along the seam and at its end corners. Bézier nets that keep C1
    // join their neighbouring windows the same way (window indices: patches come first).
    std::vector<Join> welds = doc.joins;
    {
        std::map<std::tuple<int32_t, uint32_t, uint32_t>, uint32_t> netWindow;
        for (size_t w = 0; w < W; ++w)
            if (windows[w].surface >= 0) netWindow[{windows[w].surface, windows[w].windowRow, windows[w].windowCol}] = uint32_t(w);
        for (const auto& entry : netWindow) {
            const uint32_t w = entry.second;
            const int32_t s = std::get<0>(entry.first);
            const uint32_t r = std::get<1>(entry.first), c = std::get<2>(entry.first);
            const Surface& surf = doc.surfaces[size_t(s)];
            if (surf.basis != Basis::Bezier || !surf.keepC1) continue;
            auto next = [&](uint32_t rr, uint32_t cc) {
                auto it = netWindow.find({s, rr, cc});
                return it == netWindow.end() || it->second == w ? -1 : int64_t(it->second);
            };
            if (const int64_t b = next(r, (c + 3) % surf.cols); b >= 0)
                welds.push_back(Join{w, Edge::U1, uint32_t(b), Edge::U0, false, Continuity::C1, 1.0});
            if (const int64_t b = next((r + 3) % surf.rows, c); b >= 0)
                welds.push_back(Join{w, Edge::V1, uint32_t(b), Edge::V0, false, Continuity::C1, 1.0});
        }
    }
    for (const Join& j : welds) {
        if (j.continuity == Continuity::C0 || joinHasTriangle(j)) continue;
        if (j.patchA >= W || j.patchB >= W) continue;
        const PatchInstance& a = windows[j.patchA];
        const PatchInstance& b = windows[j.patchB];
        if (a.basis != Basis::Bezier || b.basis != Basis::Bezier) continue;
        if (j.patchA == j.patchB && j.edgeA == j.edgeB) continue;
        const auto ea = edgePool(a.idx, j.edgeA), eb = edgePool(b.idx, j.edgeB);
        const bool same = ea == eb, rev = ea == reversedEdgePool(eb);
        const size_t ka = j.patchA * size_t{4} + static_cast<size_t>(j.edgeA);
        const size_t kb = j.patchB * size_t{4} + static_cast<size_t>(j.edgeB);
        if (!same && !rev) continue;                  // not a shared boundary: nothing to weld
        if (same && rev && !collapsed[ka]) continue;  // a closed loop: no unambiguous direction
        const uint32_t a0 = static_cast<uint32_t>(j.patchA * 4 + cornerOfSlot(edgeSlot(j.edgeA, 0)));
        const uint32_t a3 = static_cast<uint32_t>(j.patchA * 4 + cornerOfSlot(edgeSlot(j.edgeA, 3)));
        const uint32_t b0 = static_cast<uint32_t>(j.patchB * 4 + cornerOfSlot(edgeSlot(j.edgeB, 0)));
        const uint32_t b3 = static_cast<uint32_t>(j.patchB * 4 + cornerOfSlot(edgeSlot(j.edgeB, 3)));
        cornerSets.unite(a0, same ? b0 : b3);
        cornerSets.unite(a3, same ? b3 : b0);
        if (!collapsed[ka] && !collapsed[kb]) edgeSets.unite(static_cast<uint32_t>(ka), static_cast<uint32_t>(kb));
    }

    // Spline surfaces: one vertex grid per surface (windows overlap by construction, and their
    // shared boundaries are bit-identical, positions and derivatives).
    std::vector<SurfaceGridInfo> surfGrid(doc.surfaces.size());
    size_t surfIdsTotal = 0;
    {
        for (size_t s = 0; s < doc.surfaces.size(); ++s) {
            const Surface& surf = doc.surfaces[s];
            if (surf.basis == Basis::Bezier) continue;
            SurfaceGridInfo& g = surfGrid[s];
            const uint32_t nWR = uint32_t(netWindowCount(surf.rows, surf.closedV, 1));
            const uint32_t nWC = uint32_t(netWindowCount(surf.cols, surf.closedU, 1));
            if (nWR == 0 || nWC == 0) continue;
            g.gridRows = surf.closedV ? nWR * L : nWR * L + 1;
            g.gridCols = surf.closedU ? nWC * L : nWC * L + 1;
            g.base = surfIdsTotal;
            surfIdsTotal += static_cast<size_t>(g.gridRows) * g.gridCols;
        }
    }
    std::vector<uint32_t> surfIds(surfIdsTotal, kNoVertex);

    // Boundary vertices of Bézier windows: a small table of "ordinals" keyed by the union-find root
    // (corners) or by root and canonical k (edge interiors). Normals are summed in double.
    std::vector<uint32_t> cornerOrd(W * 4, kNoVertex);
    std::vector<uint32_t> edgeBase(W * 4, kNoVertex);
    std::vector<uint32_t> edgeOrd;
    edgeOrd.reserve(W * 2 * static_cast<size_t>(L > 1 ? L - 1 : 0));
    std::vector<uint32_t> bVid;
    std::vector<Vec3> bSum;
    std::vector<uint32_t> bCount;

    const size_t gridPoints = static_cast<size_t>(S) * S;
    mesh.positions.reserve(W * gridPoints);
    mesh.normals.reserve(W * gridPoints);
    mesh.uvs.reserve(W * gridPoints);
    mesh.indices.reserve(W * static_cast<size_t>(L) * L * 6);

    std::vector<float> tcoord(S);
    for (int k = 0; k <= L; ++k) tcoord[k] = static_cast<float>(static_cast<double>(k) / L);

    auto newVertex = [&](const SurfacePoint& sp, int r, int c) {
        const uint32_t id = static_cast<uint32_t>(mesh.positions.size());
        mesh.positions.push_back({static_cast<float>(sp.p.x), static_cast<float>(sp.p.y), static_cast<float>(sp.p.z)});
        mesh.normals.push_back({static_cast<float>(sp.n.x), static_cast<float>(sp.n.y), static_cast<float>(sp.n.z)});
        mesh.uvs.push_back({tcoord[c], tcoord[r]});
        return id;
    };
    // A shared boundary vertex through its ordinal slot: created on first use, normal summed after.
    auto sharedVertex = [&](uint32_t& ord, const SurfacePoint& sp, int r, int c) {
        if (ord == kNoVertex) {
            ord = static_cast<uint32_t>(bVid.size());
            bVid.push_back(newVertex(sp, r, c));
            bSum.push_back(sp.n);
            bCount.push_back(1);
        } else {
            bSum[ord] += sp.n;
            ++bCount[ord];
        }
        return bVid[ord];
    };

    // Grid weights, computed once per basis and tension.
    std::vector<GridWeights> weightCache;
    auto weightsFor = [&](Basis basis, double tension) -> const GridWeights& {
        for (const GridWeights& g : weightCache)
            if (g.basis == basis && (basis != Basis::CatmullRom || g.tension == tension)) return g;
        weightCache.push_back(makeGridWeights(basis, tension, L, L));
        return weightCache.back();
    };
    weightCache.reserve(4);

    std::vector<SurfacePoint> pts;
    std::vector<uint32_t> ids(gridPoints);

    for (size_t w = 0; w < W; ++w) {
        const PatchInstance& inst = windows[w];
        const GridWeights& gw = weightsFor(inst.basis, inst.tension);
        const WindowNet net = gatherWindow(doc, inst.idx);
        evaluateWindowGrid(net, inst.idx, gw, pts);

        const WeldMode mode = inst.basis == Basis::Bezier ? WeldMode::Bezier
                              : inst.surface >= 0         ? WeldMode::SurfaceGrid
                                                          : WeldMode::Isolated;

        // Interior points: always this window's own vertices.
        for (int r = 1; r < L; ++r)
            for (int c = 1; c < L; ++c) ids[r * S + c] = newVertex(pts[r * S + c], r, c);

        // Boundary points.
        auto boundary = [&](int r, int c) {
            const SurfacePoint& sp = pts[r * S + c];
            if (mode == WeldMode::Isolated) return newVertex(sp, r, c);
            if (mode == WeldMode::SurfaceGrid) {
                const SurfaceGridInfo& g = surfGrid[inst.surface];
                const uint32_t gr = (inst.windowRow * L + r) % g.gridRows;  // spline windows step by 1
                const uint32_t gc = (inst.windowCol * L + c) % g.gridCols;
                uint32_t& slot = surfIds[g.base + static_cast<size_t>(gr) * g.gridCols + gc];
                if (slot == kNoVertex) slot = newVertex(sp, r, c);
                return slot;
            }
            const bool rEnd = r == 0 || r == L, cEnd = c == 0 || c == L;
            if (rEnd && cEnd) {
                const uint32_t root = cornerSets.find(static_cast<uint32_t>(w * 4 + (r ? 2 : 0) + (c ? 1 : 0)));
                return sharedVertex(cornerOrd[root], sp, r, c);
            }
            const Edge e = c == 0 ? Edge::U0 : c == L ? Edge::U1 : r == 0 ? Edge::V0 : Edge::V1;
            const int k = cEnd ? r : c;
            const size_t ke = w * 4 + static_cast<size_t>(e);
            if (collapsed[ke]) {
                const uint32_t root = cornerSets.find(static_cast<uint32_t>(w * 4 + cornerOfSlot(edgeSlot(e, 0))));
                return sharedVertex(cornerOrd[root], sp, r, c);
            }
            const uint32_t root = edgeSets.find(static_cast<uint32_t>(ke));
            if (edgeBase[root] == kNoVertex) {
                edgeBase[root] = static_cast<uint32_t>(edgeOrd.size());
                edgeOrd.resize(edgeOrd.size() + (L - 1), kNoVertex);
            }
            const int kc = flip[ke] ? L - k : k;
            return sharedVertex(edgeOrd[edgeBase[root] + kc - 1], sp, r, c);
        };
        for (int c = 0; c <= L; ++c) {
            ids[c] = boundary(0, c);
            ids[L * S + c] = boundary(L, c);
        }
        for (int r = 1; r < L; ++r) {
            ids[r * S] = boundary(r, 0);
            ids[r * S + L] = boundary(r, L);
        }
        if (mode == WeldMode::Bezier)
            for (Edge e : kEdges) {  // the vertices a Bézier triangle on this edge welds to
                const auto pool = edgePool(inst.idx, e);
                auto onEdge = [&](int k) {
                    switch (e) {
                        case Edge::U0:
                            return ids[size_t(k * S)];
                        case Edge::U1:
                            return ids[size_t(k * S + L)];
                        case Edge::V0:
                            return ids[size_t(k)];
                        default:
                            return ids[size_t(L * S + k)];
                    }
                };
                boundaryByPool.corners.try_emplace(pool[0], onEdge(0));
                boundaryByPool.corners.try_emplace(pool[3], onEdge(L));
                const size_t ke = w * 4 + static_cast<size_t>(e);
                if (collapsed[ke] || reversedEdgePool(pool) == pool || L < 2) continue;
                auto [it, inserted] = boundaryByPool.edges.try_emplace(flip[ke] ? reversedEdgePool(pool) : pool, size_t(L - 1), kNoVertex);
                for (int k = 1; k < L; ++k) {
                    uint32_t& slot = it->second[size_t((flip[ke] ? L - k : k) - 1)];
                    if (slot == kNoVertex) slot = onEdge(k);
                }
            }

        // Two triangles per grid cell, counter-clockwise seen from du × dv; the triangles that a
        // collapsed edge makes degenerate are left out (the cell becomes one triangle of a fan).
        MeshRange& range = mesh.perWindow[w];
        range.firstIndex = static_cast<uint32_t>(mesh.indices.size());
        auto emit = [&](uint32_t a, uint32_t b, uint32_t c) { mesh.addTriangle(a, b, c); };
        for (int r = 0; r < L; ++r) {
            for (int c = 0; c < L; ++c) {
                const uint32_t a = ids[r * S + c], b = ids[r * S + c + 1];
                const uint32_t d = ids[(r + 1) * S + c], e = ids[(r + 1) * S + c + 1];
                emit(a, b, e);
                emit(a, e, d);
            }
        }
        range.indexCount = static_cast<uint32_t>(mesh.indices.size()) - range.firstIndex;
        const bool trimmed = (inst.patch >= 0 && !doc.patches[size_t(inst.patch)].trims.empty()) ||
                             (inst.surface >= 0 && !doc.surfaces[size_t(inst.surface)].trims.empty());
        if (trimmed) mesh.trimmedGrids.push_back({uint32_t(w), L, ids});
    }

    // Shared boundary vertices: the average of the normals of every window that met there.
    for (size_t o = 0; o < bVid.size(); ++o) {
        if (bCount[o] < 2) continue;
        const double len = glm::length(bSum[o]);
        if (!(len > 1e-12 * bCount[o])) continue;  // opposite normals cancel: keep the first
        const Vec3 n = bSum[o] / len;
        mesh.normals[bVid[o]] = {static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z)};
    }
}

}  // namespace

bool windowEdgeCollapsed(const std::vector<Vec3>& points, const PatchInstance& w, Edge e) {
    const auto ids = edgePool(w.idx, e);
    const Vec3& p0 = points[ids[0]];
    const bool samePoint = ids[0] == ids[1] && ids[0] == ids[2] && ids[0] == ids[3];
    return samePoint || (p0 == points[ids[1]] && p0 == points[ids[2]] && p0 == points[ids[3]]);
}

void removeUnusedVertices(TriangleMesh& mesh) {
    std::vector<uint8_t> used(mesh.positions.size(), 0);
    for (uint32_t i : mesh.indices) used[i] = 1;
    if (std::find(used.begin(), used.end(), uint8_t{0}) != used.end()) {
        std::vector<uint32_t> remap(mesh.positions.size(), kNoVertex);
        uint32_t next = 0;
        for (size_t v = 0; v < used.size(); ++v) {
            if (!used[v]) continue;
            remap[v] = next;
            mesh.positions[next] = mesh.positions[v];
            mesh.normals[next] = mesh.normals[v];
            mesh.uvs[next] = mesh.uvs[v];
            ++next;
        }
        mesh.positions.resize(next);
        mesh.normals.resize(next);
        mesh.uvs.resize(next);
        for (uint32_t& i : mesh.indices) i = remap[i];
        for (TrimmedGrid& g : mesh.trimmedGrids)
            for (uint32_t& i : g.ids) i = i < remap.size() ? remap[i] : kNoVertex;
    }
}

MeshBound meshBound(const Document& doc, int level) {
    double windows = double(doc.patches.size());
    for (const Surface& surf : doc.surfaces)
        windows += double(netWindowCount(surf.rows, surf.closedV, 1)) * double(netWindowCount(surf.cols, surf.closedU, 1));
    const double L = level, S = L + 1.0, tris = double(doc.triangles.size());
    MeshBound b;
    b.vertices = windows * S * S + tris * S * (S + 1) / 2;
    b.triangles = windows * 2 * L * L + tris * L * L;
    b.bytes = b.vertices * 32 + b.triangles * 12;
    return b;
}

int highestLevelWithin(const Document& doc, double maxBytes) {
    int best = 0;
    for (int l = 1; l <= limits::kMaxExportLevel && meshBound(doc, l).bytes <= maxBytes; ++l) best = l;
    return best;
}

TriangleMesh tessellateDocument(const Document& doc, int level) {
    if (level < 1 || level > limits::kMaxExportLevel)
        throw std::invalid_argument("tessellation level " + std::to_string(level) + " is outside 1.." +
                                    std::to_string(limits::kMaxExportLevel));
    const std::vector<PatchInstance> windows = expandPatches(doc);
    if (meshBound(doc, level).vertices >= 4294967295.0)
        throw std::length_error(std::to_string(windows.size() + doc.triangles.size()) + " patches at level " + std::to_string(level) +
                                " would need more than 2^32 vertices; use a lower level");
    TriangleMesh mesh;
    BoundaryVertices quadBoundaries;
    tessellateWindows(doc, windows, level, mesh, quadBoundaries);
    appendBezierTriangles(doc, level, mesh, &quadBoundaries);
    removeUnusedVertices(mesh);
    return mesh;
}

CageLines controlCage(const Document& doc) {
    CageLines cage;
    const std::vector<PatchInstance> windows = expandPatches(doc);
    std::vector<uint64_t> segments;
    segments.reserve(windows.size() * 24);
    for (const PatchInstance& inst : windows) {
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 3; ++j) {
                for (int dir = 0; dir < 2; ++dir) {
                    // dir 0: along a row (u), dir 1: along a column (v); i is the fixed line.
                    const uint32_t a = dir == 0 ? inst.idx[i * 4 + j] : inst.idx[j * 4 + i];
                    const uint32_t b = dir == 0 ? inst.idx[i * 4 + j + 1] : inst.idx[(j + 1) * 4 + i];
                    if (a == b) continue;
                    const uint64_t lo = std::min(a, b), hi = std::max(a, b);
                    segments.push_back(lo << 32 | hi);
                }
            }
        }
    }
    // Bézier triangles: the 18 edges of the net's 6 upward sub-triangles (a + b + c = 2).
    for (const TrianglePatch& tri : doc.triangles) {
        for (int a = 0; a <= 2; ++a)
            for (int b = 0; b <= 2 - a; ++b) {
                const int c = 2 - a - b;
                const uint32_t p[3] = {tri.idx[triSlot(a + 1, b, c)], tri.idx[triSlot(a, b + 1, c)], tri.idx[triSlot(a, b, c + 1)]};
                for (int e = 0; e < 3; ++e) {
                    const uint32_t x = p[e], y = p[(e + 1) % 3];
                    if (x == y) continue;
                    segments.push_back(uint64_t(std::min(x, y)) << 32 | std::max(x, y));
                }
            }
    }
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());

    // Pool points used by a segment, in pool order.
    std::vector<uint32_t> remap(doc.points.size(), kNoVertex);
    for (uint64_t s : segments) {
        remap[static_cast<uint32_t>(s >> 32)] = 0;
        remap[static_cast<uint32_t>(s & 0xFFFFFFFFu)] = 0;
    }
    for (size_t p = 0; p < doc.points.size(); ++p) {
        if (remap[p] == kNoVertex) continue;
        remap[p] = static_cast<uint32_t>(cage.positions.size());
        const Vec3& q = doc.points[p];
        cage.positions.push_back({static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z)});
    }
    cage.indices.reserve(segments.size() * 2);
    for (uint64_t s : segments) {
        cage.indices.push_back(remap[static_cast<uint32_t>(s >> 32)]);
        cage.indices.push_back(remap[static_cast<uint32_t>(s & 0xFFFFFFFFu)]);
    }
    return cage;
}

}  // namespace mesh
}  // namespace pw

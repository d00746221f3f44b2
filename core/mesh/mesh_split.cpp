// Grouping of a welded mesh into export primitives (mesh_split.hpp): triangles get a group
// (connected by shared positions, by patch, or one), then each group's triangles and the vertices
// they use are copied out in order, with indices relative to the group.
#include "core/mesh/mesh_split.hpp"

#include <algorithm>
#include <cstring>
#include <future>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <system_error>
#include <tuple>
#include <utility>

namespace pw {
inline namespace mesh {

namespace {

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t x) {
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

// Group of every triangle, numbered in order of first appearance; `items` gets the patch of each
// group (Patches) or -1.
std::vector<uint32_t> groupTriangles(const TriangleMesh& mesh, MeshGrouping grouping, const std::vector<uint32_t>& pid,
                                     std::vector<int>& items) {
    const size_t T = mesh.indices.size() / 3;
    std::vector<uint32_t> group(T, 0);
    if (grouping == MeshGrouping::Single) {
        if (T > 0) items.push_back(-1);
        return group;
    }
    if (grouping == MeshGrouping::Patches) {
        int item = 0;
        auto take = [&](const std::vector<MeshRange>& ranges) {
            for (const MeshRange& r : ranges) {
                if (r.indexCount > 0) {
                    for (uint32_t t = r.firstIndex / 3; t < (r.firstIndex + r.indexCount) / 3; ++t) group[t] = uint32_t(items.size());
                    items.push_back(item);
                }
                ++item;
            }
        };
        take(mesh.perWindow);
        take(mesh.perTriangle);
        return group;
    }
    std::vector<uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto& I = mesh.indices;
    for (size_t t = 0; t < T; ++t)
        for (int k = 1; k < 3; ++k) {
            const uint32_t a = findRoot(parent, pid[I[3 * t]]), b = findRoot(parent, pid[I[3 * t + k]]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
    std::vector<uint32_t> number(mesh.positions.size(), kNoVertex);
    for (size_t t = 0; t < T; ++t) {
        uint32_t& n = number[findRoot(parent, pid[I[3 * t]])];
        if (n == kNoVertex) {
            n = uint32_t(items.size());
            items.push_back(-1);
        }
        group[t] = n;
    }
    return group;
}

// closed[g]: every edge of group g's triangles, by position, is used by exactly two of them. The
// edges are bucketed by their lower position id (a counting sort) and each bucket, a handful of
// edges, checked alone: linear in the triangles (one sort of all 3T edges cost 60 % of a glb export).
// `byPosition`: a group is a set of positions (connected surfaces, or one group), so an edge's group
// is its lower end's and a bucket holds only the other ends (4 bytes an edge instead of 8: the
// largest temporary of an export).
std::vector<bool> closedGroups(const std::vector<uint32_t>& indices, const std::vector<uint32_t>& group, const std::vector<uint32_t>& pid,
                               size_t groups, bool byPosition) {
    const size_t T = group.size();
    uint32_t top = 0;
    for (size_t i = 0; i < 3 * T; ++i) top = std::max(top, pid[indices[i]]);
    std::vector<uint32_t> start(size_t(top) + 2, 0);
    const auto edge = [&](size_t t, int k) {
        const uint32_t a = pid[indices[3 * t + size_t(k)]], b = pid[indices[3 * t + size_t((k + 1) % 3)]];
        return std::pair{std::min(a, b), std::max(a, b)};
    };
    for (size_t t = 0; t < T; ++t)
        for (int k = 0; k < 3; ++k) ++start[edge(t, k).first + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    // Bucketed by the lower id: the higher id, and (unless byPosition) the group in the next word.
    const size_t words = byPosition ? 1 : 2;
    std::unique_ptr<uint32_t[]> other(new uint32_t[words * 3 * T]);  // every entry written below: no zero-fill
    std::vector<uint32_t> lowerGroup(byPosition ? start.size() : 0);
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t t = 0; t < T; ++t)
        for (int k = 0; k < 3; ++k) {
            const auto [a, b] = edge(t, k);
            const uint32_t at = fill[a]++;
            if (byPosition) {
                other[at] = b;
                lowerGroup[a] = group[t];
            } else {
                other[2 * size_t(at)] = b;
                other[2 * size_t(at) + 1] = group[t];
            }
        }
    std::vector<bool> closed(groups, true);
    if (byPosition) {
        for (size_t a = 0; a + 1 < start.size(); ++a) {
            uint32_t* first = other.get() + start[a];
            uint32_t* last = other.get() + start[a + 1];
            if (first == last || !closed[lowerGroup[a]]) continue;
            if (last - first > 16) std::sort(first, last);  // else: count each one's equals in place
            for (const uint32_t* i = first; i != last; ++i) {
                ptrdiff_t same = 0;
                if (last - first > 16) {
                    const uint32_t* j = i;
                    while (j != last && *j == *i) ++j;
                    same = j - i;
                    i = j - 1;
                } else {
                    for (const uint32_t* j = first; j != last; ++j) same += *j == *i;
                }
                if (same != 2) {
                    closed[lowerGroup[a]] = false;
                    break;
                }
            }
        }
        return closed;
    }
    using Use = std::pair<uint32_t, uint32_t>;  // higher id, group
    std::vector<Use> bucket;
    for (size_t a = 0; a + 1 < start.size(); ++a) {
        bucket.clear();
        for (uint32_t e = start[a]; e < start[a + 1]; ++e) bucket.emplace_back(other[2 * size_t(e)], other[2 * size_t(e) + 1]);
        std::sort(bucket.begin(), bucket.end());
        for (auto i = bucket.begin(); i != bucket.end();) {
            auto j = i;
            while (j != bucket.end() && *j == *i) ++j;
            if (j - i != 2) closed[i->second] = false;
            i = j;
        }
    }
    return closed;
}

}  // namespace

const char* meshGroupingName(MeshGrouping g) {
    switch (g) {
        case MeshGrouping::Surfaces:
            return "surfaces";
        case MeshGrouping::Patches:
            return "patches";
        case MeshGrouping::Single:
            return "single";
    }
    return "surfaces";
}

std::optional<MeshGrouping> parseMeshGrouping(const std::string& name) {
    for (MeshGrouping g : {MeshGrouping::Surfaces, MeshGrouping::Patches, MeshGrouping::Single})
        if (name == meshGroupingName(g)) return g;
    return std::nullopt;
}

std::vector<uint32_t> positionIds(const std::vector<std::array<float, 3>>& positions) {
    // An open-addressing table of first occurrences, keyed by the coordinates' bits (-0 as +0, so
    // that equal floats share a slot): one pass instead of sorting every position (a fifth of a glb
    // export).
    const auto bits = [](float f) {
        uint32_t u;
        f = f == 0.0f ? 0.0f : f;
        std::memcpy(&u, &f, 4);
        return u;
    };
    size_t size = 16;
    while (size < 2 * positions.size()) size *= 2;
    std::vector<uint32_t> slot(size, kNoVertex), id(positions.size());
    for (size_t v = 0; v < positions.size(); ++v) {
        const auto& p = positions[v];
        uint64_t h = 1469598103934665603ull;
        for (float c : p) h = (h ^ bits(c)) * 1099511628211ull;
        size_t i = size_t(h ^ (h >> 29)) & (size - 1);
        while (slot[i] != kNoVertex && positions[slot[i]] != p) i = (i + 1) & (size - 1);
        if (slot[i] == kNoVertex) slot[i] = uint32_t(v);
        id[v] = slot[i];
    }
    return id;
}

namespace {

// Moves element j to position to[j] (a permutation), following its cycles in place: `load(i)`
// reads element i, `store(i, value)` writes it.
template <class Load, class Store>
void permuteInPlace(const std::vector<uint32_t>& to, Load&& load, Store&& store) {
    std::vector<bool> done(to.size(), false);
    for (size_t s = 0; s < to.size(); ++s) {
        if (done[s]) continue;
        auto carry = load(s);
        for (size_t j = s;;) {
            done[j] = true;
            const size_t k = to[j];
            auto next = load(k);
            store(k, carry);
            if (k == s) break;
            carry = std::move(next);
            j = k;
        }
    }
}

// The split of a large mesh grouped by surface or as one, where every vertex belongs to one group:
// the triangles are put in group order and the vertices in first-use order within the mesh's own
// arrays, so that no second copy of the mesh is ever held (the largest exports' peak memory was
// the mesh and its copy). The same arrays as the copy makes. The mesh's arrays are rearranged as
// it goes: on an exception they are left in no useful order (splitMesh consumes the mesh).
SplitMesh splitInPlace(TriangleMesh& mesh, const std::vector<uint32_t>& group, const std::vector<int>& items) {
    const size_t G = items.size(), T = group.size(), V = mesh.positions.size();
    std::vector<uint32_t> start(G + 1, 0);
    for (uint32_t g : group) ++start[g + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    {
        // Triangles by group, stable: triangle t goes to place `to[t]` (its three indices together).
        std::vector<uint32_t> to(T), fill(start.begin(), start.end() - 1);
        for (size_t t = 0; t < T; ++t) to[t] = fill[group[t]]++;
        uint32_t* I = mesh.indices.data();
        permuteInPlace(
            to,
            [&](size_t t) {
                return std::array<uint32_t, 3>{I[3 * t], I[3 * t + 1], I[3 * t + 2]};
            },
            [&](size_t t, const std::array<uint32_t, 3>& tri) { std::copy(tri.begin(), tri.end(), I + 3 * t); });
    }
    // Vertices in first use, group by group; indices relative to their group's first vertex.
    SplitMesh out;
    std::vector<uint32_t> newId(V, kNoVertex);
    uint32_t next = 0;
    for (size_t g = 0; g < G; ++g) {
        MeshGroup mg;
        mg.firstIndex = 3 * start[g];
        mg.indexCount = 3 * (start[g + 1] - start[g]);
        mg.firstVertex = next;
        mg.item = items[g];
        for (size_t i = mg.firstIndex; i < size_t(mg.firstIndex) + mg.indexCount; ++i) {
            uint32_t& v = mesh.indices[i];
            if (newId[v] == kNoVertex) newId[v] = next++;
            if (newId[v] < mg.firstVertex) throw std::logic_error("splitMesh: a vertex in two groups cannot be split in place");
            v = newId[v] - mg.firstVertex;
        }
        mg.vertexCount = next - mg.firstVertex;
        out.groups.push_back(mg);
    }
    const uint32_t used = next;
    for (uint32_t& id : newId)
        if (id == kNoVertex) id = next++;  // unused: after the rest, then cut off
    permuteInPlace(
        newId, [&](size_t v) { return std::make_tuple(mesh.positions[v], mesh.normals[v], mesh.uvs[v]); },
        [&](size_t v, const auto& p) { std::tie(mesh.positions[v], mesh.normals[v], mesh.uvs[v]) = p; });
    mesh.positions.resize(used);
    mesh.normals.resize(used);
    mesh.uvs.resize(used);
    out.positions = std::move(mesh.positions);
    out.normals = std::move(mesh.normals);
    out.uvs = std::move(mesh.uvs);
    out.indices = std::move(mesh.indices);
    return out;
}

}  // namespace

SplitMesh splitMesh(TriangleMesh&& mesh, MeshGrouping grouping, size_t inPlaceFrom) {
    const std::vector<uint32_t> pid = positionIds(mesh.positions);
    std::vector<int> items;
    const std::vector<uint32_t> group = groupTriangles(mesh, grouping, pid, items);
    const size_t bytes = mesh.positions.size() * 32 + mesh.indices.size() * 4;
    const bool sameSizes = mesh.normals.size() == mesh.positions.size() && mesh.uvs.size() == mesh.positions.size();
    if (grouping != MeshGrouping::Patches && bytes >= inPlaceFrom && sameSizes) {
        // Which groups are closed first (it reads the indices the split then rewrites).
        const std::vector<bool> closed = closedGroups(mesh.indices, group, pid, items.size(), true);
        SplitMesh out = splitInPlace(mesh, group, items);
        for (size_t g = 0; g < out.groups.size(); ++g) out.groups[g].closed = closed[g];
        mesh = TriangleMesh{};
        return out;
    }
    // Which groups are closed, on a second thread while the groups are copied out (both only read
    // the mesh's indices, the groups and the position ids): a third of the split each.
    const auto closedOf = [&] { return closedGroups(mesh.indices, group, pid, items.size(), grouping != MeshGrouping::Patches); };
    std::future<std::vector<bool>> closedLater;
    try {
        closedLater = std::async(std::launch::async, closedOf);
    } catch (const std::system_error&) {  // no thread to be had: on this one, after the copy
        closedLater = std::async(std::launch::deferred, closedOf);
    }

    // Triangles by group, stable (counting sort).
    const size_t G = items.size(), T = group.size();
    std::vector<uint32_t> start(G + 1, 0);
    for (uint32_t g : group) ++start[g + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<uint32_t> order(T), fill(start.begin(), start.end() - 1);
    for (size_t t = 0; t < T; ++t) order[fill[group[t]]++] = uint32_t(t);

    SplitMesh out;
    out.indices.reserve(mesh.indices.size());
    out.positions.reserve(mesh.positions.size());
    out.normals.reserve(mesh.positions.size());
    out.uvs.reserve(mesh.positions.size());
    std::vector<uint32_t> local(mesh.positions.size(), kNoVertex), owner(mesh.positions.size(), kNoVertex);
    for (size_t g = 0; g < G; ++g) {
        MeshGroup mg;
        mg.firstIndex = uint32_t(out.indices.size());
        mg.firstVertex = uint32_t(out.positions.size());
        mg.item = items[g];
        for (uint32_t k = start[g]; k < start[g + 1]; ++k)
            for (int c = 0; c < 3; ++c) {
                const uint32_t v = mesh.indices[3 * size_t(order[k]) + c];
                if (owner[v] != g) {
                    owner[v] = uint32_t(g);
                    local[v] = uint32_t(out.positions.size()) - mg.firstVertex;
                    out.positions.push_back(mesh.positions[v]);
                    out.normals.push_back(mesh.normals[v]);
                    out.uvs.push_back(mesh.uvs[v]);
                }
                out.indices.push_back(local[v]);
            }
        mg.indexCount = uint32_t(out.indices.size()) - mg.firstIndex;
        mg.vertexCount = uint32_t(out.positions.size()) - mg.firstVertex;
        out.groups.push_back(mg);
    }
    const std::vector<bool> closed = closedLater.get();
    for (size_t g = 0; g < G; ++g) out.groups[g].closed = closed[g];
    mesh = TriangleMesh{};
    return out;
}

}  // namespace mesh
}  // namespace pw

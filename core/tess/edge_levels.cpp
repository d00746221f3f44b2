// Shared-edge levels (core/tess/edge_levels.hpp): the windows and triangles on each boundary curve
// found by its canonical four pool indices, then one level per curve.
#include "core/tess/edge_levels.hpp"

#include <algorithm>
#include <map>

#include "core/eval/bezier_triangle.hpp"
#include "core/gpu/patch_math.h"

namespace pw {
inline namespace tess {

namespace {

struct Side {
    size_t item;  // index into the result
    int edge;     // outer level slot
    float own;    // the item's own level for this edge; < 0: none
};

}  // namespace

std::vector<WindowLevels> resolveEdgeLevels(const Document& doc, const std::vector<PatchInstance>& windows) {
    std::vector<WindowLevels> out(windows.size() + doc.triangles.size());
    std::map<std::array<uint32_t, 4>, std::vector<Side>> edges;
    const auto addEdge = [&](std::array<uint32_t, 4> pool, Side side) {
        if (edgeReversed(pool)) pool = reversedEdgePool(pool);
        edges[pool].push_back(side);
    };
    for (size_t w = 0; w < windows.size(); ++w) {
        const PatchInstance& pi = windows[w];
        const std::optional<std::array<float, 6>>* own = pi.patch >= 0 ? &doc.patches[size_t(pi.patch)].tessOverride : nullptr;
        if (own && *own) out[w].inner = std::array<float, 2>{(**own)[4], (**own)[5]};
        for (int e = 0; e < 4; ++e) {
            const float level = own && *own ? (**own)[size_t(e)] : -1.0f;
            if (pi.basis != Basis::Bezier) {  // a spline window's boundary is not its control row
                if (level >= 0.0f) out[w].outer[size_t(e)] = level, out[w].fixedMask |= 1u << e;
                continue;
            }
            std::array<uint32_t, 4> pool;
            for (int k = 0; k < 4; ++k) pool[size_t(k)] = pi.idx[size_t(gpu::quadEdgeSlot(e, k, 0))];
            addEdge(pool, {w, e, level});
        }
    }
    for (size_t t = 0; t < doc.triangles.size(); ++t) {
        const TrianglePatch& tri = doc.triangles[t];
        const size_t item = windows.size() + t;
        if (tri.tessOverride) out[item].inner = std::array<float, 2>{(*tri.tessOverride)[3], 0.0f};
        for (int e = 0; e < 3; ++e) addEdge(triEdgePool(tri.idx, e), {item, e, tri.tessOverride ? (*tri.tessOverride)[size_t(e)] : -1.0f});
    }
    for (const auto& [pool, sides] : edges) {
        float level = 0.0f;
        bool allOwn = true;
        for (const Side& s : sides) {
            level = std::max(level, s.own);
            allOwn = allOwn && s.own >= 0.0f;
        }
        for (const Side& s : sides) {
            out[s.item].outer[size_t(s.edge)] = level;
            if (allOwn) out[s.item].fixedMask |= 1u << s.edge;
        }
    }
    return out;
}

}  // namespace tess
}  // namespace pw

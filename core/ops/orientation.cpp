#include "core/ops/orientation.hpp"

#include <vector>

#include "core/eval/rational_eval.hpp"
#include "core/model/topology.hpp"
#include "core/ops/patch_ops.hpp"

namespace pw {
inline namespace ops {

double positionFlux(const Document& doc, int n) {
    const Bounds b = computeBounds(doc.points);
    if (b.empty) return 0.0;
    const Vec3 c = 0.5 * (b.min + b.max);
    double flux = 0.0;
    for (const PatchInstance& inst : expandPatches(doc)) {
        const WindowNet net = gatherWindow(doc, inst.idx);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const SurfacePoint sp = evaluateWindow(net, inst.basis, inst.tension, (j + 0.5) / n, (i + 0.5) / n);
                // (p - c)·(du × dv) du dv is (p - c)·n dA
                flux += glm::dot(sp.p - c, glm::cross(sp.du, sp.dv)) / (double(n) * n);
            }
    }
    return flux;
}

double openBoundaryShare(const Document& doc) {
    size_t curves = 0, open = 0;
    const EdgeJoinIndex joined(doc);
    for (uint32_t p = 0; p < doc.patches.size(); ++p) {
        const Patch& pt = doc.patches[p];
        for (Edge e : {Edge::U0, Edge::V0, Edge::U1, Edge::V1}) {
            bool collapsed = true;
            for (int k = 1; k < 4; ++k) collapsed = collapsed && doc.points[pt.idx[edgeSlot(e, k)]] == doc.points[pt.idx[edgeSlot(e, 0)]];
            if (collapsed) continue;
            ++curves;
            if (joined.at(p, e) < 0) ++open;
        }
    }
    return curves ? double(open) / double(curves) : 1.0;
}

bool orientOutward(Document& doc) {
    if (doc.patches.empty() || openBoundaryShare(doc) > 0.25 || positionFlux(doc) >= 0.0) return false;
    std::vector<uint32_t> all(doc.patches.size());
    for (uint32_t p = 0; p < all.size(); ++p) all[p] = p;
    flipPatches(doc, all);
    return true;
}

}  // namespace ops
}  // namespace pw

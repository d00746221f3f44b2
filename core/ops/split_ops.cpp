#include "core/ops/split_ops.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_map>

#include "core/base/errors.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/construction_refs.hpp"
#include "core/model/topology.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/solve/sheared_joins.hpp"

namespace pw {
inline namespace ops {

namespace {

// The edges the cut line crosses (they run along the split parameter) and those it leaves whole.
bool crossedBy(bool alongU, Edge e) { return alongU ? (e == Edge::V0 || e == Edge::V1) : (e == Edge::U0 || e == Edge::U1); }

// Exact de Casteljau split of patch p (no joins touched): p becomes the first half, the second is
// appended and its index returned.
uint32_t splitGeometry(Document& doc, uint32_t p, bool alongU, double t) {
    if (p < doc.patches.size() && !doc.patches[p].trims.empty())
        throw EditError("patch " + std::to_string(p) + " is trimmed: a split would cut through its trims; `untrim " + std::to_string(p) +
                        "` first, or cut it with `split-by`");
    const Patch src = doc.patches[p];
    // Rational patches split in homogeneous form: each half keeps the exact surface and gets weights.
    const WeightedSplit halves = splitWindowBezier(gatherWindow(doc, src.idx), alongU, t);
    const Net16& first = halves.first.points;
    const Net16& second = halves.second.points;
    const auto weightOf = [](const WindowNet& h, size_t s) { return h.weights ? (*h.weights)[s] : 1.0; };
    // Edges of the first half: the low edge is kept, the far edge is the new seam.
    const Edge low = alongU ? Edge::U0 : Edge::V0, high = alongU ? Edge::U1 : Edge::V1;
    Patch a = src, b = src;
    b.name = (src.name.empty() ? "patch " + std::to_string(p) : src.name) + " b";
    // Slots on the low edge of a and the high edge of b keep the original pool entries; the shared
    // seam gets new points used by both; all other slots get fresh points.
    std::array<bool, 16> keepA{}, keepB{};
    for (int k = 0; k < 4; ++k) {
        keepA[size_t(edgeSlot(low, k, 0))] = true;
        keepB[size_t(edgeSlot(high, k, 0))] = true;
    }
    for (size_t s = 0; s < 16; ++s) {
        if (!keepA[s]) a.idx[s] = addPoint(doc, first[s], weightOf(halves.first, s));
        if (!keepB[s]) b.idx[s] = addPoint(doc, second[s], weightOf(halves.second, s));
    }
    for (int k = 0; k < 4; ++k) b.idx[size_t(edgeSlot(low, k, 0))] = a.idx[size_t(edgeSlot(high, k, 0))];
    // The split curve's end points coincide with the original corners: keep those shared.
    const uint32_t corner[4] = {src.idx[0], src.idx[3], src.idx[12], src.idx[15]};
    const int cornerSlot[4] = {0, 3, 12, 15};
    for (int c = 0; c < 4; ++c) {
        const size_t s = size_t(cornerSlot[c]);
        const auto same = [&](uint32_t i) {
            return doc.points[i] == doc.points[corner[c]] && pointWeight(doc, i) == pointWeight(doc, corner[c]);
        };
        if (same(a.idx[s])) a.idx[s] = corner[c];
        if (same(b.idx[s])) b.idx[s] = corner[c];
    }
    doc.patches[p] = a;
    doc.patches.push_back(b);
    return uint32_t(doc.patches.size() - 1);
}

// Union-find over pool indices: the seam points two joined halves made each for themselves become one.
uint32_t rootOf(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

std::vector<RingCut> splitRingOf(const Document& doc, uint32_t p, bool alongU, double t) {
    checkBezier(doc, p, "split");
    if (!(t > 1e-6 && t < 1.0 - 1e-6)) throw EditError("split parameter must lie strictly between 0 and 1");
    std::vector<RingCut> ring{{p, alongU, t}};
    std::unordered_map<uint32_t, size_t> seen{{p, 0}};
    const EdgeJoinIndex joinOn(doc);
    for (size_t i = 0; i < ring.size(); ++i) {
        const RingCut cut = ring[i];
        for (Edge e : {Edge::U0, Edge::U1, Edge::V0, Edge::V1}) {
            if (!crossedBy(cut.alongU, e)) continue;
            const int found = joinOn.at(cut.patch, e);
            if (found < 0) continue;
            const Join& jn = doc.joins[size_t(found)];
            const bool isA = jn.patchA == cut.patch && jn.edgeA == e;
            const uint32_t q = isA ? jn.patchB : jn.patchA;
            const Edge eq = isA ? jn.edgeB : jn.edgeA;
            if (isTriangleEdge(eq))  // a Bézier triangle is not split: its join would be lost
                throw EditError("the split would cut edge " + std::string(edgeName(e)) + " of patch " + std::to_string(cut.patch) +
                                ", which is joined to triangle " + std::to_string(q) + " " + std::string(edgeName(eq)) +
                                "; unjoin it first, or split the other way");
            // Along q's edge the parameter runs the same way unless the join pairs its points reversed.
            const RingCut next{q, eq == Edge::V0 || eq == Edge::V1, jn.reversed ? 1.0 - cut.t : cut.t};
            const auto it = seen.find(q);
            if (it == seen.end()) {
                if (doc.patches[q].basis != Basis::Bezier)
                    throw EditError("the split runs through the join into patch " + std::to_string(q) +
                                    ", which is not Bézier; convert it or unjoin it first");
                seen.emplace(q, ring.size());
                ring.push_back(next);
                continue;
            }
            const RingCut& had = ring[it->second];
            if (had.alongU != next.alongU || std::abs(had.t - next.t) > 1e-9)
                throw EditError("the split comes back to patch " + std::to_string(q) + " along " + (next.alongU ? "u" : "v") + " at " +
                                std::to_string(next.t) + " where it already cuts it along " + (had.alongU ? "u" : "v") + " at " +
                                std::to_string(had.t) + "; split at 0.5 or unjoin a seam of the ring first");
        }
    }
    return ring;
}

std::vector<std::pair<RingCut, uint32_t>> splitRing(Document& doc, uint32_t p, bool alongU, double t) {
    const std::vector<RingCut> ring = splitRingOf(doc, p, alongU, t);
    std::unordered_map<uint32_t, std::pair<RingCut, uint32_t>> cutOf;  // patch → its cut and second half
    // A live construction whose input is an edge of a cut patch: the far edge moves to the second
    // half with it; an edge the cut crosses would become two, so the split is refused.
    for (Construction& k : doc.constructions)
        for (CurveInput& in : k.inputs) {
            if (in.curve >= 0) continue;
            const auto c = std::find_if(ring.begin(), ring.end(), [&](const RingCut& r) { return r.patch == in.patch; });
            if (c == ring.end() || !crossedBy(c->alongU, in.edge)) continue;
            throw EditError("the split would cut edge " + curveInputName(in) +
                            ", an input of a live surface; bake that surface first (bake), or split elsewhere");
        }
    std::vector<std::pair<RingCut, uint32_t>> made;
    for (const RingCut& c : ring) {
        made.emplace_back(c, splitGeometry(doc, c.patch, c.alongU, c.t));
        cutOf.emplace(c.patch, made.back());
    }
    for (Construction& k : doc.constructions)
        for (CurveInput& in : k.inputs)
            if (const auto c = cutOf.find(in.patch);
                in.curve < 0 && c != cutOf.end() && in.edge == (c->second.first.alongU ? Edge::U1 : Edge::V1))
                in.patch = c->second.second;
    std::vector<Join> joins;
    std::vector<Join> across;
    std::vector<size_t> rescaled;  // joins whose rows a cut shortened
    for (Join j : doc.joins) {
        const auto ca = isTriangleEdge(j.edgeA) ? cutOf.end() : cutOf.find(j.patchA);
        const auto cb = isTriangleEdge(j.edgeB) ? cutOf.end() : cutOf.find(j.patchB);
        const bool crossA = ca != cutOf.end() && crossedBy(ca->second.first.alongU, j.edgeA);
        const bool crossB = cb != cutOf.end() && crossedBy(cb->second.first.alongU, j.edgeB);
        if (crossA != crossB)
            throw EditError("the split meets an edge joined twice (patch " + std::to_string(j.patchA) + " " +
                            std::string(edgeName(j.edgeA)) + ", patch " + std::to_string(j.patchB) + " " + std::string(edgeName(j.edgeB)) +
                            "); unjoin one of them first");
        if (crossA) {
            // A's first half (parameters 0..t along the edge) meets B's first half, or its second
            // when the join pairs the points reversed; the cross-boundary rows split alike, so α and
            // β2 hold as they were.
            Join first = j, second = j;
            if (j.fitted) {  // restricted exactly (its rows were never all met: a fit would change it)
                const double t = ca->second.first.t;
                first = restrictedJoin(j, 0.0, t), second = restrictedJoin(j, t, 1.0);
            }
            second.patchA = ca->second.second;
            (j.reversed ? first : second).patchB = cb->second.second;
            across.push_back(first);
            across.push_back(second);
            continue;
        }
        // A join on a cut patch's low edge stays with the first half, one on its high edge moves to
        // the second; both are measured again below (the halves' tangent rows are shorter).
        for (int side = 0; side < 2; ++side) {
            uint32_t& pt = side == 0 ? j.patchA : j.patchB;
            if (isTriangleEdge(side == 0 ? j.edgeA : j.edgeB)) continue;
            const auto c = cutOf.find(pt);
            if (c == cutOf.end()) continue;
            if ((side == 0 ? j.edgeA : j.edgeB) == (c->second.first.alongU ? Edge::U1 : Edge::V1)) pt = c->second.second;
            rescaled.push_back(joins.size());
        }
        joins.push_back(j);
    }
    // The joins across the cut: the halves' edge points on either side become one pool entry.
    std::vector<uint32_t> parent(doc.points.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (const Join& j : across) {
        if (hasShear(j) && !j.fitted) rescaled.push_back(joins.size());  // β(t) restricted to a half: fitted again
        const Patch &A = doc.patches[j.patchA], &B = doc.patches[j.patchB];
        for (int k = 0; k < 4; ++k) {
            const uint32_t ia = rootOf(parent, A.idx[size_t(edgeSlot(j.edgeA, k, 0))]);
            const uint32_t ib = rootOf(parent, B.idx[size_t(edgeSlot(j.edgeB, j.reversed ? 3 - k : k, 0))]);
            if (ia != ib) parent[ib] = ia;
        }
        joins.push_back(j);
    }
    forEachPointIndex(doc, [&](uint32_t& i) {
        if (i < parent.size()) i = rootOf(parent, i);
    });
    // The seam inside each cut patch.
    for (const auto& [cut, q] : made) {
        const double alpha = (1.0 - cut.t) / cut.t;
        const bool c1 = std::abs(alpha - 1.0) < 1e-12;
        const Edge low = cut.alongU ? Edge::U0 : Edge::V0, high = cut.alongU ? Edge::U1 : Edge::V1;
        rescaled.push_back(joins.size());  // a rational patch's seam: its weights set the ratio
        joins.push_back(Join{cut.patch, high, q, low, false, c1 ? Continuity::C1 : Continuity::G1, c1 ? 1.0 : alpha});
    }
    doc.joins = std::move(joins);
    for (size_t j : rescaled) remeasureJoin(doc, j);
    // A live blend's (or open loft's) end on a cut patch: its join was measured again above, and the
    // construction makes its surface with that ratio from now on. It kept the ratio it was made with,
    // so holding the join moved the input's rows again at every reopen (issue 73).
    for (Construction& k : doc.constructions) {
        if (!((k.kind == ConstructionKind::Loft && !k.closed) || k.kind == ConstructionKind::Blend) || k.inputs.empty()) continue;
        for (size_t end = 0; end < 2; ++end) {
            const CurveInput& in = end == 0 ? k.inputs.front() : k.inputs.back();
            const bool cut = in.curve < 0 && std::any_of(made.begin(), made.end(),
                                                         [&](const auto& m) { return m.first.patch == in.patch || m.second == in.patch; });
            if (!cut) continue;
            for (const Join& j : doc.joins)
                if (j.patchA == in.patch && j.edgeA == in.edge &&
                    std::find(k.patches.begin(), k.patches.end(), j.patchB) != k.patches.end()) {
                    k.endAlpha[end] = j.alpha;
                    break;
                }
        }
    }
    compactPool(doc);
    return made;
}

std::pair<uint32_t, uint32_t> splitPatch(Document& doc, uint32_t p, bool alongU, double t) {
    const auto made = splitRing(doc, p, alongU, t);
    return {p, made.front().second};
}

}  // namespace ops
}  // namespace pw

#include "core/model/topology.hpp"

#include "core/gpu/patch_math.h"

namespace pw {
inline namespace model {

int findJoin(const Document& doc, uint32_t p, Edge e) {
    for (size_t i = 0; i < doc.joins.size(); ++i) {
        const Join& j = doc.joins[i];
        if ((j.patchA == p && j.edgeA == e) || (j.patchB == p && j.edgeB == e)) return int(i);
    }
    return -1;
}

EdgeJoinIndex::EdgeJoinIndex(const Document& doc) {
    quads_.assign(doc.patches.size(), {-1, -1, -1, -1});
    triangles_.assign(doc.triangles.size(), {-1, -1, -1});
    // Backwards, so that an edge named by two joins answers the first, as findJoin does.
    for (size_t j = doc.joins.size(); j-- > 0;) add(doc.joins[j], j);
}

void EdgeJoinIndex::set(uint32_t item, Edge e, int32_t index) {
    if (isTriangleEdge(e)) {
        if (item < triangles_.size()) triangles_[item][size_t(triangleEdgeNumber(e))] = index;
    } else if (item < quads_.size()) {
        quads_[item][size_t(e)] = index;
    }
}

void EdgeJoinIndex::add(const Join& j, size_t index) {
    set(j.patchA, j.edgeA, int32_t(index));
    set(j.patchB, j.edgeB, int32_t(index));
}

int EdgeJoinIndex::at(uint32_t item, Edge e) const {
    if (isTriangleEdge(e)) return item < triangles_.size() ? triangles_[item][size_t(triangleEdgeNumber(e))] : -1;
    return item < quads_.size() ? quads_[item][size_t(e)] : -1;
}

std::string joinSideRef(uint32_t item, Edge e) {
    return (isTriangleEdge(e) ? "t" : "") + std::to_string(item) + ":" + std::string(edgeName(e));
}
std::string joinSideRef(const Join& j, bool sideB) { return sideB ? joinSideRef(j.patchB, j.edgeB) : joinSideRef(j.patchA, j.edgeA); }
std::string joinSideName(uint32_t item, Edge e) {
    return (isTriangleEdge(e) ? "triangle " : "patch ") + std::to_string(item) + " " + std::string(edgeName(e));
}
std::string joinSideName(const Join& j, bool sideB) { return sideB ? joinSideName(j.patchB, j.edgeB) : joinSideName(j.patchA, j.edgeA); }

std::vector<uint32_t> edgePoolOf(const Document& doc, uint32_t p, Edge e) {
    std::vector<uint32_t> out;
    if (isTriangleEdge(e)) {
        if (p < doc.triangles.size())
            for (int k = 0; k < 4; ++k) out.push_back(doc.triangles[p].idx[size_t(gpu::triEdgeSlot(triangleEdgeNumber(e), k))]);
    } else if (p < doc.patches.size()) {
        for (int k = 0; k < 4; ++k) out.push_back(doc.patches[p].idx[size_t(edgeSlot(e, k))]);
    }
    return out;
}

std::vector<std::array<uint32_t, 3>> netC1Triples(const Document& doc) {
    std::vector<std::array<uint32_t, 3>> out;
    for (const Surface& s : doc.surfaces) {
        if (s.basis != Basis::Bezier || !s.keepC1) continue;
        const uint32_t wu = uint32_t(netWindowCount(s.cols, s.closedU, 3)), wv = uint32_t(netWindowCount(s.rows, s.closedV, 3));
        if (wu == 0 || wv == 0) continue;
        const uint32_t usedRows = s.closedV ? s.rows : 3 * wv + 1, usedCols = s.closedU ? s.cols : 3 * wu + 1;
        auto at = [&](uint32_t r, uint32_t c) { return s.idx[size_t(r % s.rows) * s.cols + c % s.cols]; };
        for (uint32_t k = s.closedU ? 0 : 1; k < wu; ++k)
            for (uint32_t r = 0; r < usedRows; ++r) {
                const uint32_t c = 3 * k;
                out.push_back({at(r, c + s.cols - 1), at(r, c), at(r, c + 1)});
            }
        for (uint32_t k = s.closedV ? 0 : 1; k < wv; ++k)
            for (uint32_t c = 0; c < usedCols; ++c) {
                const uint32_t r = 3 * k;
                out.push_back({at(r + s.rows - 1, c), at(r, c), at(r + 1, c)});
            }
    }
    return out;
}

int edgeLoopSign(Edge e) { return e == Edge::V0 || e == Edge::U1 ? 1 : -1; }

bool edgesPairReversed(const Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb) {
    const Patch &A = doc.patches[a], &B = doc.patches[b];
    auto pa = [&](int k) { return doc.points[A.idx[size_t(edgeSlot(ea, k, 0))]]; };
    auto pb = [&](int k) { return doc.points[B.idx[size_t(edgeSlot(eb, k, 0))]]; };
    const double straight = glm::length(pa(0) - pb(0)) + glm::length(pa(3) - pb(3));
    const double crossed = glm::length(pa(0) - pb(3)) + glm::length(pa(3) - pb(0));
    return crossed < straight;
}

}  // namespace model
}  // namespace pw

#include "core/model/document_merge.hpp"

namespace pw {
inline namespace model {

namespace {

template <class Item>
uint32_t appendRenumbered(std::vector<Item>& into, const std::vector<Item>& from, uint32_t pointBase) {
    const uint32_t first = uint32_t(into.size());
    for (Item item : from) {
        for (uint32_t& i : item.idx) i += pointBase;
        into.push_back(std::move(item));
    }
    return first;
}

}  // namespace

MergedRange mergeDocument(Document& into, const Document& from) {
    MergedRange r;
    r.firstPoint = uint32_t(into.points.size());
    r.pointCount = uint32_t(from.points.size());
    into.points.insert(into.points.end(), from.points.begin(), from.points.end());
    if (!from.weights.empty()) {  // the weights come along, at their points' new places
        into.weights.resize(r.firstPoint, 1.0);
        into.weights.insert(into.weights.end(), from.weights.begin(), from.weights.end());
        trimWeights(into.weights);
    }
    r.firstPatch = appendRenumbered(into.patches, from.patches, r.firstPoint);
    r.patchCount = uint32_t(from.patches.size());
    r.firstSurface = appendRenumbered(into.surfaces, from.surfaces, r.firstPoint);
    r.surfaceCount = uint32_t(from.surfaces.size());
    r.firstTriangle = appendRenumbered(into.triangles, from.triangles, r.firstPoint);
    r.triangleCount = uint32_t(from.triangles.size());
    r.firstCurve = appendRenumbered(into.curves, from.curves, r.firstPoint);
    r.curveCount = uint32_t(from.curves.size());
    r.firstJoin = uint32_t(into.joins.size());
    r.joinCount = uint32_t(from.joins.size());
    for (Join j : from.joins) {
        j.patchA += isTriangleEdge(j.edgeA) ? r.firstTriangle : r.firstPatch;
        j.patchB += isTriangleEdge(j.edgeB) ? r.firstTriangle : r.firstPatch;
        into.joins.push_back(j);
    }
    for (Construction c : from.constructions) {  // live in the new document too
        for (uint32_t& i : c.grid) i += r.firstPoint;
        for (uint32_t& p : c.patches) p += r.firstPatch;
        for (CurveInput& in : c.inputs) {
            if (in.curve >= 0)
                in.curve += int32_t(r.firstCurve);
            else
                in.patch += r.firstPatch;
        }
        into.constructions.push_back(std::move(c));
    }
    return r;
}

}  // namespace model
}  // namespace pw

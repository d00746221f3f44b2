// Mirror copies joined across the plane (core/ops/mirror.hpp).
#include "core/ops/mirror.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/base/errors.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/model/join_detect.hpp"
#include "core/model/topology.hpp"

namespace pw {
inline namespace ops {

MirrorResult mirrorItems(Document& doc, const std::vector<uint32_t>& selected, int axis, double planeAt) {
    if (axis < 0 || axis > 2) throw EditError("mirror: the axis must be X, Y or Z");
    const std::vector<uint32_t> patches = wholeItems(doc.patches, selected), triangles = wholeItems(doc.triangles, selected),
                                curves = wholeItems(doc.curves, selected);
    if (patches.empty() && triangles.empty() && curves.empty())
        throw EditError("mirror: select whole patches, triangles or curves (nets are not mirrored)");

    // Points within a hair of the plane stay shared (and are put on it exactly); the rest get copies.
    const double tol = 1e-9 * std::max(modelSize(doc), 1.0);
    std::map<uint32_t, uint32_t> image;
    const auto mirrored = [&](uint32_t p) {
        if (auto it = image.find(p); it != image.end()) return it->second;
        Vec3 q = doc.points[p];
        uint32_t out = p;
        if (std::abs(q[axis] - planeAt) <= tol) {
            doc.points[p][axis] = planeAt;
        } else {
            q[axis] = 2.0 * planeAt - q[axis];
            out = uint32_t(doc.points.size());
            doc.points.push_back(q);
            if (pointWeight(doc, p) != 1.0) setPointWeight(doc, out, pointWeight(doc, p));
        }
        image[p] = out;
        return out;
    };
    MirrorResult r;
    const uint32_t firstPatch = uint32_t(doc.patches.size());
    for (uint32_t i : patches) {
        Patch m = doc.patches[i];
        // Reflection turns the surface inside out; reversing u turns it back.
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col) m.idx[size_t(row * 4 + col)] = mirrored(doc.patches[i].idx[size_t(row * 4 + 3 - col)]);
        m.name = (m.name.empty() ? "patch " + std::to_string(i) : m.name) + " mirror";
        r.patches.push_back(uint32_t(doc.patches.size()));
        doc.patches.push_back(std::move(m));
    }
    for (uint32_t i : triangles) {
        TrianglePatch m = doc.triangles[i];
        // Swapping the u and v corners (b_ijk → b_jik) reverses the orientation.
        for (int a = 0; a <= 3; ++a)
            for (int b = 0; a + b <= 3; ++b) {
                const int c = 3 - a - b;
                m.idx[size_t(triSlot(b, a, c))] = mirrored(doc.triangles[i].idx[size_t(triSlot(a, b, c))]);
            }
        m.name = (m.name.empty() ? "triangle " + std::to_string(i) : m.name) + " mirror";
        r.triangles.push_back(uint32_t(doc.triangles.size()));
        doc.triangles.push_back(std::move(m));
    }
    for (uint32_t i : curves) {
        BezierCurve m = doc.curves[i];
        for (uint32_t& p : m.idx) p = mirrored(p);
        m.name = (m.name.empty() ? "curve " + std::to_string(i) : m.name) + " mirror";
        r.curves.push_back(uint32_t(doc.curves.size()));
        doc.curves.push_back(std::move(m));
    }
    // Joins: every boundary the new patches share with an item (each other, the originals on the
    // plane), with the continuity the geometry has; edges already joined keep their joins.
    EdgeJoinIndex joined(doc);
    for (const Join& j : detectJoins(doc)) {
        if (j.patchA < firstPatch && j.patchB < firstPatch) continue;
        if (joined.at(j.patchA, j.edgeA) >= 0 || joined.at(j.patchB, j.edgeB) >= 0) continue;
        const bool seam = (j.patchA < firstPatch) != (j.patchB < firstPatch);
        joined.add(j, doc.joins.size());
        doc.joins.push_back(j);
        if (seam) ++r.seamJoins;
    }
    for (const auto& [from, to] : image) (void)from, r.points.push_back(to);
    for (uint32_t t : r.triangles)
        for (uint32_t p : doc.triangles[t].idx) r.points.push_back(p);
    std::sort(r.points.begin(), r.points.end());
    r.points.erase(std::unique(r.points.begin(), r.points.end()), r.points.end());
    return r;
}

}  // namespace ops
}  // namespace pw

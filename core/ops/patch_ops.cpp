#include "core/ops/patch_ops.hpp"

#include "core/trim/trim_edits.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/eval/bezier_triangle.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/construction_refs.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/sheared_joins.hpp"
#include "core/trim/trim_edits.hpp"

namespace pw {
inline namespace ops {

namespace {

template <class Item>
void checkItem(const std::vector<Item>& items, uint32_t i, const char* kind) {
    if (i >= items.size())
        throw EditError(std::string(kind) + " " + std::to_string(i) + " does not exist (the document has " + std::to_string(items.size()) +
                        ")");
}

void checkPatch(const Document& doc, uint32_t p) { checkItem(doc.patches, p, "patch"); }

// Removes item i and the pool points only it used.
template <class Item>
void eraseItem(Document& doc, std::vector<Item>& items, uint32_t i) {
    items.erase(items.begin() + i);
    compactPool(doc);
}

}  // namespace

void checkBezier(const Document& doc, uint32_t p, const char* what) {
    checkPatch(doc, p);
    if (doc.patches[p].basis != Basis::Bezier)
        throw EditError(std::string(what) + " needs a Bézier patch; patch " + std::to_string(p) + " uses another basis");
}

void checkPolynomial(const Document& doc, uint32_t p, const std::string& needs) {
    for (uint32_t i : doc.patches[p].idx)
        if (pointWeight(doc, i) != 1.0) throw EditError("patch " + std::to_string(p) + " is rational; " + needs);
}

uint32_t addPoint(Document& doc, const Vec3& v, double weight) {
    doc.points.push_back(v);
    const uint32_t i = uint32_t(doc.points.size() - 1);
    if (weight != 1.0) setPointWeight(doc, i, weight);
    return i;
}

Edge oppositeEdge(Edge e) {
    switch (e) {
        case Edge::U0:
            return Edge::U1;
        case Edge::U1:
            return Edge::U0;
        case Edge::V0:
            return Edge::V1;
        default:
            return Edge::V0;
    }
}

namespace {

// Joins with a side on item p (a patch, or a Bézier triangle when `triangle`) removed; that kind's
// indices above p shifted down.
void dropItemFromJoins(Document& doc, uint32_t p, bool triangle) {
    const auto on = [&](uint32_t i, Edge e) { return i == p && isTriangleEdge(e) == triangle; };
    std::erase_if(doc.joins, [&](const Join& j) { return on(j.patchA, j.edgeA) || on(j.patchB, j.edgeB); });
    for (Join& j : doc.joins) {
        if (j.patchA > p && isTriangleEdge(j.edgeA) == triangle) --j.patchA;
        if (j.patchB > p && isTriangleEdge(j.edgeB) == triangle) --j.patchB;
    }
}

}  // namespace

Edge nearestEdge(double u, double v) {
    const double d[4] = {u, v, 1.0 - u, 1.0 - v};
    return Edge(std::min_element(d, d + 4) - d);
}

uint32_t addFlatPatch(Document& doc, const Vec3& center, double size, bool zUp) {
    Patch patch;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const double a = (j / 3.0 - 0.5) * size, b = (i / 3.0 - 0.5) * size;
            const Vec3 off = zUp ? Vec3(a, b, 0.0) : Vec3(a, 0.0, -b);
            patch.idx[size_t(i * 4 + j)] = addPoint(doc, center + off);
        }
    patch.name = "patch " + std::to_string(doc.patches.size());
    doc.patches.push_back(patch);
    return uint32_t(doc.patches.size() - 1);
}

namespace {
// A copy of items[k] (a patch or a triangle) with fresh points moved by `offset`, appended.
template <class Item>
uint32_t duplicateWithOwnPoints(Document& doc, std::vector<Item>& items, uint32_t k, const Vec3& offset, const char* kind) {
    Item copy = items[k];
    for (uint32_t& i : copy.idx) i = addPoint(doc, doc.points[i] + offset, pointWeight(doc, i));
    copy.name = (copy.name.empty() ? std::string(kind) + " " + std::to_string(k) : copy.name) + " copy";
    items.push_back(std::move(copy));
    return uint32_t(items.size() - 1);
}
}  // namespace

uint32_t duplicatePatch(Document& doc, uint32_t p, const Vec3& offset) {
    checkPatch(doc, p);
    const uint32_t copy = duplicateWithOwnPoints(doc, doc.patches, p, offset, "patch");
    detachTrims(doc.patches[copy].trims);  // the live curve lies on the original
    return copy;
}

void deletePatch(Document& doc, uint32_t p) {
    checkPatch(doc, p);
    dropItemFromJoins(doc, p, false);
    dropPatchFromConstructions(doc, p);
    dropSurfaceFromTrims(doc, SurfaceRef{false, p});
    eraseItem(doc, doc.patches, p);
}

// Where flipPatch moves net slot s (0..15, row-major): the same row, the column mirrored.
int flippedSlot(int s) { return (s / 4) * 4 + 3 - s % 4; }

void flipPatches(Document& doc, const std::vector<uint32_t>& patches) {
    std::vector<char> flipped(doc.patches.size(), 0);  // each patch once, however often it is named
    for (uint32_t p : patches) {
        checkPatch(doc, p);
        flipped[p] = 1;
    }
    const auto turned = [&](uint32_t item) { return item < flipped.size() && flipped[item]; };
    // A live surface's input edge on a turned patch: u0 and u1 trade names (the same points in the
    // same order); a v edge would run backwards and change the surface, so that is refused. Checked
    // before anything changes. (Its inputs used to keep their names: the surface was made from the
    // other edge at the next reopen; issue 73.)
    for (size_t k = 0; k < doc.constructions.size(); ++k)
        for (const CurveInput& in : doc.constructions[k].inputs)
            if (in.curve < 0 && turned(in.patch) && (in.edge == Edge::V0 || in.edge == Edge::V1))
                throw EditError("edge " + std::string(edgeName(in.edge)) + " of patch " + std::to_string(in.patch) +
                                " is an input of live surface k" + std::to_string(k) +
                                "; turning the patch would run it backwards: bake that surface first (bake k" + std::to_string(k) + ")");
    for (Construction& c : doc.constructions)
        for (CurveInput& in : c.inputs)
            if (in.curve < 0 && turned(in.patch)) in.edge = oppositeEdge(in.edge);
    for (uint32_t p = 0; p < flipped.size(); ++p) {
        if (!flipped[p]) continue;
        Patch& pt = doc.patches[p];
        for (int s = 0; s < 16; ++s)
            if (s % 4 < 2) std::swap(pt.idx[size_t(s)], pt.idx[size_t(flippedSlot(s))]);
        if (pt.tessOverride) {
            auto& o = *pt.tessOverride;
            std::swap(o[0], o[2]);  // outer u=0 <-> u=1
        }
        flipTrimsU(pt.trims);
    }
    // Edge U0 <-> U1 (k along v unchanged); on V0/V1 the parameter k runs the other way. One pass
    // over the joins for all of them (a .bpt import flips every patch: O(patches × joins) before).
    for (Join& j : doc.joins) {
        for (int side = 0; side < 2; ++side) {
            const bool isA = side == 0;
            Edge& e = isA ? j.edgeA : j.edgeB;
            const uint32_t item = isA ? j.patchA : j.patchB;
            if (isTriangleEdge(e) || !turned(item)) continue;
            if (e == Edge::U0 || e == Edge::U1) {
                e = oppositeEdge(e);
            } else {
                j.reversed = !j.reversed;
                if (isA) j = reversedAlongEdge(j);  // α(t) and β(t) run along A's edge
            }
        }
    }
}

void flipPatch(Document& doc, uint32_t p) { flipPatches(doc, {p}); }

uint32_t extrudeEdge(Document& doc, uint32_t p, Edge e) {
    checkBezier(doc, p, "extrude");
    if (findJoin(doc, p, e) >= 0)
        throw EditError("edge " + std::string(edgeName(e)) + " of patch " + std::to_string(p) +
                        " is already joined; extrude an open boundary edge");
    const Patch src = doc.patches[p];
    const Edge ne = oppositeEdge(e);  // the new patch's edge on the seam keeps both parameter directions
    Patch np;
    np.name = "patch " + std::to_string(doc.patches.size());
    for (int k = 0; k < 4; ++k) {
        const uint32_t b0 = src.idx[size_t(edgeSlot(e, k, 0))];
        const Vec3 a1 = doc.points[src.idx[size_t(edgeSlot(e, k, 1))]];
        const Vec3 d = doc.points[b0] - a1;  // C1: B1 - B0 = A0 - A1
        np.idx[size_t(edgeSlot(ne, k, 0))] = b0;
        for (int depth = 1; depth < 4; ++depth) np.idx[size_t(edgeSlot(ne, k, depth))] = addPoint(doc, doc.points[b0] + double(depth) * d);
    }
    doc.patches.push_back(np);
    const uint32_t q = uint32_t(doc.patches.size() - 1);
    doc.joins.push_back(Join{p, e, q, ne, false, Continuity::C1, 1.0});
    return q;
}

uint32_t addCurve(Document& doc, const Vec3& center, double size, bool zUp) {
    BezierCurve c;
    c.idx.resize(4);
    const double xs[4] = {-0.5, -0.25, 0.25, 0.5}, ys[4] = {0.0, 0.5, 0.5, 0.0};
    for (int k = 0; k < 4; ++k) {
        const double a = xs[k] * size, b = ys[k] * size;
        c.idx[size_t(k)] = addPoint(doc, center + (zUp ? Vec3(a, b, 0.0) : Vec3(a, 0.0, -b)));
    }
    c.name = "curve " + std::to_string(doc.curves.size());
    doc.curves.push_back(c);
    return uint32_t(doc.curves.size() - 1);
}

uint32_t curveFromEdge(Document& doc, uint32_t p, Edge e) {
    checkBezier(doc, p, "take a curve from");
    BezierCurve c;
    c.idx.resize(4);
    for (int k = 0; k < 4; ++k) c.idx[size_t(k)] = doc.patches[p].idx[size_t(edgeSlot(e, k, 0))];
    c.name = (doc.patches[p].name.empty() ? "patch " + std::to_string(p) : doc.patches[p].name) + " edge " + std::string(edgeName(e));
    doc.curves.push_back(c);
    return uint32_t(doc.curves.size() - 1);
}

void deleteCurve(Document& doc, uint32_t c) {
    checkItem(doc.curves, c, "curve");
    dropCurveFromConstructions(doc, c);
    dropCurveFromTrims(doc, c);
    eraseItem(doc, doc.curves, c);
}

uint32_t addTriangle(Document& doc, const Vec3& center, double size, bool zUp) {
    // Corners u, v, w of an equilateral triangle, counter-clockwise seen from above (normal up).
    const double r = size / std::sqrt(3.0);
    auto corner = [&](double deg) {
        const double a = deg * 3.14159265358979323846 / 180.0;
        const double x = r * std::cos(a), y = r * std::sin(a);
        return zUp ? Vec3(x, y, 0.0) : Vec3(x, 0.0, -y);
    };
    const Vec3 U = corner(-30.0), V = corner(90.0), W = corner(210.0);
    TrianglePatch t;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3 - i; ++j) {
            const int k = 3 - i - j;
            t.idx[size_t(triSlot(i, j, k))] = addPoint(doc, center + (double(i) * U + double(j) * V + double(k) * W) / 3.0);
        }
    t.name = "triangle " + std::to_string(doc.triangles.size());
    doc.triangles.push_back(t);
    return uint32_t(doc.triangles.size() - 1);
}

uint32_t duplicateTriangle(Document& doc, uint32_t t, const Vec3& offset) {
    checkItem(doc.triangles, t, "triangle");
    return duplicateWithOwnPoints(doc, doc.triangles, t, offset, "triangle");
}

void deleteTriangle(Document& doc, uint32_t t) {
    checkItem(doc.triangles, t, "triangle");
    dropItemFromJoins(doc, t, true);
    eraseItem(doc, doc.triangles, t);
}

void compactPool(Document& doc) {
    std::vector<uint32_t> remap(doc.points.size(), UINT32_MAX);
    forEachPointIndex(std::as_const(doc), [&](uint32_t i) { remap[i] = 0; });
    std::vector<Vec3> pts;
    pts.reserve(doc.points.size());
    for (size_t i = 0; i < doc.points.size(); ++i)
        if (remap[i] == 0) {
            remap[i] = uint32_t(pts.size());
            pts.push_back(doc.points[i]);
        }
    if (pts.size() == doc.points.size()) return;
    remapWeights(doc, remap, pts.size());
    doc.points = std::move(pts);
    forEachPointIndex(doc, [&](uint32_t& i) { i = remap[i]; });
}

}  // namespace ops
}  // namespace pw

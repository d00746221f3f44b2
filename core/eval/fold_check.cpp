#include "core/eval/fold_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/eval/bezier_triangle.hpp"
#include "core/eval/rational_eval.hpp"

namespace pw {
inline namespace eval {

namespace {

// A grid triangle turned over: its geometric normal against the surface normals at its corners
// (SurfacePoint or TriPoint: both have p and n). A triangle of no area (two corners on a pole, where
// a collapsed edge's points coincide up to rounding) has no direction and is not counted: `minArea2`
// is the squared doubled area below which a triangle counts as such.
template <class Point>
bool turnedOver(const Point& a, const Point& b, const Point& c, double minArea2) {
    const Vec3 g = glm::cross(b.p - a.p, c.p - a.p);
    return glm::dot(g, g) > minArea2 && glm::dot(g, a.n + b.n + c.n) < 0.0;
}

// The squared size (bounding-box diagonal) of a control net.
template <class Net>
double netSize2(const Net& points) {
    Vec3 lo = points[0], hi = points[0];
    for (const Vec3& q : points) lo = glm::min(lo, q), hi = glm::max(hi, q);
    return glm::dot(hi - lo, hi - lo);
}

// The squared doubled area below which a grid triangle has no direction: (1e-9 of the net's
// squared size)², the collapsed-corner test's scale.
double minTriangleArea2(double size2) { return 1e-18 * size2 * size2; }

}  // namespace

PatchShape patchShape(const Document& doc, uint32_t p, int level) {
    const Patch& patch = doc.patches[p];
    const WindowNet net = gatherWindow(doc, patch.idx);
    const int n = std::max(level, 1);
    std::vector<SurfacePoint> grid(size_t(n + 1) * size_t(n + 1));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            grid[size_t(j * (n + 1) + i)] = evaluateWindow(net, patch.basis, patch.tension, double(i) / n, double(j) / n);
    // The patch's own scale: a corner's tangent plane counts as vanished when |du × dv| is below
    // 1e-9 of the squared size of its control net.
    const double size2 = netSize2(net.points);
    const double minArea2 = minTriangleArea2(size2);
    PatchShape shape;
    auto at = [&](int i, int j) -> const SurfacePoint& { return grid[size_t(j * (n + 1) + i)]; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const SurfacePoint &a = at(i, j), &b = at(i + 1, j), &c = at(i, j + 1), &d = at(i + 1, j + 1);
            shape.invertedTriangles += int(turnedOver(a, b, d, minArea2)) + int(turnedOver(a, d, c, minArea2));
        }
    for (const SurfacePoint* c : {&at(0, 0), &at(n, 0), &at(0, n), &at(n, n)})
        if (size2 > 0.0 && glm::length(glm::cross(c->du, c->dv)) <= 1e-9 * size2) ++shape.collapsedCorners;
    return shape;
}

PatchShape triangleShape(const Document& doc, uint32_t t, int level) {
    const TrianglePatch& tri = doc.triangles[t];
    const int n = std::max(level, 1);
    std::vector<TriPoint> grid;
    const Net10 net = gatherTriangleNet(doc, tri.idx);
    evaluateTriangleGrid(net, tri.idx, n, grid);
    const double minArea2 = minTriangleArea2(netSize2(net));
    PatchShape shape;
    const auto turned = [&](size_t a, size_t b, size_t c) { return turnedOver(grid[a], grid[b], grid[c], minArea2); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
            // (i, j) → (i+1, j) → (i, j+1) turns like (u, v): du × dv
            shape.invertedTriangles += int(turned(triGridIndex(i, j, n), triGridIndex(i + 1, j, n), triGridIndex(i, j + 1, n)));
            if (i + j + 1 < n)
                shape.invertedTriangles += int(turned(triGridIndex(i + 1, j, n), triGridIndex(i + 1, j + 1, n), triGridIndex(i, j + 1, n)));
        }
    return shape;
}

namespace {

// A patch's (or triangle's) shape as a number: its points, weights, basis and tension (an FNV-1a
// hash), so that a patch whose pool entries an edit only renumbered counts as unchanged.
template <class Item>
uint64_t shapeKey(const Document& d, const Item& p) {
    uint64_t h = 1469598103934665603ull;
    auto mix = [&](const void* data, size_t n) {
        const auto* b = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    };
    for (uint32_t i : p.idx) {
        const Vec3 q = i < d.points.size() ? d.points[i] : Vec3(0.0);
        const double w = pointWeight(d, i);
        mix(&q, sizeof q);
        mix(&w, sizeof w);
    }
    if constexpr (requires { p.basis; }) {
        mix(&p.basis, sizeof p.basis);
        mix(&p.tension, sizeof p.tension);
    }
    return h;
}

// Whether the 16 control points of `a` map onto those of `b` by a similarity (a rigid motion or a
// mirror, with a uniform scale): every inner product of the points' offsets from the first scales
// by one factor. The surface's shape is then the same, so are its folds.
bool similarNets(const WindowNet& a, const WindowNet& b) {
    if (a.weights.has_value() != b.weights.has_value() || (a.weights && *a.weights != *b.weights)) return false;
    std::array<Vec3, 16> da, db;
    double na = 0.0, nb = 0.0;
    for (size_t i = 0; i < 16; ++i) {
        da[i] = a.points[i] - a.points[0], db[i] = b.points[i] - b.points[0];
        na += glm::dot(da[i], da[i]), nb += glm::dot(db[i], db[i]);
    }
    if (!(na > 0.0) || !(nb > 0.0)) return false;
    const double s2 = nb / na, tol = 1e-9 * nb;
    for (size_t i = 1; i < 16; ++i)
        for (size_t j = i; j < 16; ++j)
            if (std::abs(glm::dot(db[i], db[j]) - s2 * glm::dot(da[i], da[j])) > tol) return false;
    return true;
}

// "" when patch p of `after` is not folded further than patch p of `before`, else what was.
std::string patchFoldedFurther(const Document& before, const Document& after, uint32_t p, bool turnedOnly = false) {
    const Patch &pb = before.patches[p], &pa = after.patches[p];
    if (pb.basis == pa.basis && pb.tension == pa.tension && similarNets(gatherWindow(before, pb.idx), gatherWindow(after, pa.idx)))
        return "";
    const PatchShape is = patchShape(after, p), was = patchShape(before, p);
    if (turnedOnly ? is.invertedTriangles <= was.invertedTriangles : !foldedFurther(was, is)) return "";
    return "patch " + std::to_string(p) + " (" +
           (is.invertedTriangles > was.invertedTriangles ? std::to_string(is.invertedTriangles) + " of its triangles turned over"
                                                         : std::string("a corner's tangent plane collapsed")) +
           ")";
}

std::string trianglesFoldedFurther(const Document& before, const Document& after) {
    for (size_t t = 0; t < before.triangles.size() && t < after.triangles.size(); ++t) {
        if (shapeKey(before, before.triangles[t]) == shapeKey(after, after.triangles[t])) continue;
        const PatchShape is = triangleShape(after, uint32_t(t)), was = triangleShape(before, uint32_t(t));
        if (foldedFurther(was, is))
            return "triangle " + std::to_string(t) + " (" + std::to_string(is.invertedTriangles) + " of its triangles turned over)";
    }
    return "";
}

}  // namespace

std::string foldMadeBy(const Document& before, const Document& after) {
    for (size_t p = 0; p < before.patches.size() && p < after.patches.size(); ++p) {
        if (shapeKey(before, before.patches[p]) == shapeKey(after, after.patches[p])) continue;
        if (std::string fold = patchFoldedFurther(before, after, uint32_t(p)); !fold.empty()) return fold;
    }
    return trianglesFoldedFurther(before, after);
}

std::string foldMadeIn(const Document& before, const Document& after, const std::vector<bool>& changed, bool turnedOnly, int* foldedPatch) {
    for (size_t p = 0; p < before.patches.size() && p < after.patches.size() && p < changed.size(); ++p) {
        if (!changed[p]) continue;
        if (std::string fold = patchFoldedFurther(before, after, uint32_t(p), turnedOnly); !fold.empty()) {
            if (foldedPatch) *foldedPatch = int(p);
            return fold;
        }
    }
    return "";
}

std::string newFoldIn(const Document& before, const Document& after) {
    std::string found;
    for (size_t p = before.patches.size(); p < after.patches.size() && found.empty(); ++p)
        if (const int n = patchShape(after, uint32_t(p)).invertedTriangles)
            found = "new patch " + std::to_string(p) + " (" + std::to_string(n) + " of its triangles turned over)";
    for (size_t t = before.triangles.size(); t < after.triangles.size() && found.empty(); ++t)
        if (const int n = triangleShape(after, uint32_t(t)).invertedTriangles)
            found = "new triangle " + std::to_string(t) + " (" + std::to_string(n) + " of its triangles turned over)";
    if (found.empty()) return "";
    // Only now, and only once, the whole model before: was any of it turned over already?
    for (size_t p = 0; p < before.patches.size(); ++p)
        if (patchShape(before, uint32_t(p)).invertedTriangles) return "";
    for (size_t t = 0; t < before.triangles.size(); ++t)
        if (triangleShape(before, uint32_t(t)).invertedTriangles) return "";
    return found;
}

}  // namespace eval
}  // namespace pw

#include "core/eval/fold_check.hpp"

#include <algorithm>
#include <vector>

#include "core/eval/bezier_triangle.hpp"
#include "core/eval/rational_eval.hpp"

namespace pw {
inline namespace eval {

namespace {

// A grid triangle turned over: its geometric normal against the surface normals at its corners
// (SurfacePoint or TriPoint: both have p and n).
template <class Point>
bool turnedOver(const Point& a, const Point& b, const Point& c) {
    return glm::dot(glm::cross(b.p - a.p, c.p - a.p), a.n + b.n + c.n) < 0.0;
}

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
    Vec3 lo = net.points[0], hi = net.points[0];
    for (const Vec3& q : net.points) lo = glm::min(lo, q), hi = glm::max(hi, q);
    const double size2 = glm::dot(hi - lo, hi - lo);
    PatchShape shape;
    auto at = [&](int i, int j) -> const SurfacePoint& { return grid[size_t(j * (n + 1) + i)]; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const SurfacePoint &a = at(i, j), &b = at(i + 1, j), &c = at(i, j + 1), &d = at(i + 1, j + 1);
            shape.invertedTriangles += int(turnedOver(a, b, d)) + int(turnedOver(a, d, c));
        }
    for (const SurfacePoint* c : {&at(0, 0), &at(n, 0), &at(0, n), &at(n, n)})
        if (size2 > 0.0 && glm::length(glm::cross(c->du, c->dv)) <= 1e-9 * size2) ++shape.collapsedCorners;
    return shape;
}

PatchShape triangleShape(const Document& doc, uint32_t t, int level) {
    const TrianglePatch& tri = doc.triangles[t];
    const int n = std::max(level, 1);
    std::vector<TriPoint> grid;
    evaluateTriangleGrid(gatherTriangleNet(doc, tri.idx), tri.idx, n, grid);
    PatchShape shape;
    const auto turned = [&](size_t a, size_t b, size_t c) { return turnedOver(grid[a], grid[b], grid[c]); };
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

}  // namespace

std::string foldMadeBy(const Document& before, const Document& after) {
    for (size_t p = 0; p < before.patches.size() && p < after.patches.size(); ++p) {
        if (shapeKey(before, before.patches[p]) == shapeKey(after, after.patches[p])) continue;
        const PatchShape is = patchShape(after, uint32_t(p)), was = patchShape(before, uint32_t(p));
        if (!foldedFurther(was, is)) continue;
        return "patch " + std::to_string(p) + " (" +
               (is.invertedTriangles > was.invertedTriangles ? std::to_string(is.invertedTriangles) + " of its triangles turned over"
                                                             : std::string("a corner's tangent plane collapsed")) +
               ")";
    }
    for (size_t t = 0; t < before.triangles.size() && t < after.triangles.size(); ++t) {
        if (shapeKey(before, before.triangles[t]) == shapeKey(after, after.triangles[t])) continue;
        const PatchShape is = triangleShape(after, uint32_t(t)), was = triangleShape(before, uint32_t(t));
        if (foldedFurther(was, is))
            return "triangle " + std::to_string(t) + " (" + std::to_string(is.invertedTriangles) + " of its triangles turned over)";
    }
    return "";
}

}  // namespace eval
}  // namespace pw

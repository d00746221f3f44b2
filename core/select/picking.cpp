#include "core/select/picking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "core/eval/bezier_triangle.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/gpu/trim_math.h"
#include "core/select/selection.hpp"
#include "core/trim/trim_loops.hpp"

namespace pw {
inline namespace select {

Ray rayThroughPixel(const Camera& cam, double x, double y, int width, int height) {
    const double aspect = double(std::max(width, 1)) / double(std::max(height, 1));
    const ViewMatrices vm = viewMatrices(cam, aspect);
    const glm::dmat4 inv = glm::inverse(glm::dmat4(vm.viewProj));
    // Pixel centre -> normalised device coordinates (Vulkan: y down, depth 0..1).
    const double nx = 2.0 * x / double(std::max(width, 1)) - 1.0;
    const double ny = 2.0 * y / double(std::max(height, 1)) - 1.0;
    glm::dvec4 n = inv * glm::dvec4(nx, ny, 0.0, 1.0);
    glm::dvec4 f = inv * glm::dvec4(nx, ny, 1.0, 1.0);
    const glm::dvec3 pn = glm::dvec3(n) / n.w, pf = glm::dvec3(f) / f.w;
    Ray r;
    r.dir = glm::normalize(pf - pn);
    r.origin = cam.orthographic ? pn : cameraEye(cam);
    return r;
}

std::vector<std::optional<glm::dvec2>> projectPoints(const Camera& cam, const std::vector<Vec3>& points, int width, int height) {
    const double aspect = double(std::max(width, 1)) / double(std::max(height, 1));
    const ViewMatrices vm = viewMatrices(cam, aspect);
    std::vector<std::optional<glm::dvec2>> out(points.size());
    for (size_t i = 0; i < points.size(); ++i) out[i] = projectToPixel(vm, points[i], width, height);
    return out;
}

int pickPoint(const Camera& cam, const std::vector<Vec3>& points, double x, double y, int width, int height, double radiusPx,
              const std::vector<bool>* used) {
    const double aspect = double(std::max(width, 1)) / double(std::max(height, 1));
    const ViewMatrices vm = viewMatrices(cam, aspect);
    const glm::dvec3 eye = cameraEye(cam);
    int best = -1;
    double bestD2 = radiusPx * radiusPx, bestDepth = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < points.size(); ++i) {
        if (used && (i >= used->size() || !(*used)[i])) continue;
        const auto p = projectToPixel(vm, points[i], width, height);
        if (!p) continue;
        const double d2 = (p->x - x) * (p->x - x) + (p->y - y) * (p->y - y);
        if (d2 > radiusPx * radiusPx) continue;
        const double depth = glm::length(points[i] - eye);
        // Within a pixel of the best, the nearer one to the eye wins.
        if (d2 + 1.0 < bestD2 || (std::abs(d2 - bestD2) <= 1.0 && depth < bestDepth) || best < 0) {
            best = int(i);
            bestD2 = d2;
            bestDepth = depth;
        }
    }
    return best;
}

std::vector<uint32_t> pointsInBox(const Camera& cam, const std::vector<Vec3>& points, glm::dvec2 a, glm::dvec2 b, int width, int height,
                                  const std::vector<bool>* used) {
    const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
    const double aspect = double(std::max(width, 1)) / double(std::max(height, 1));
    const ViewMatrices vm = viewMatrices(cam, aspect);
    std::vector<uint32_t> out;
    for (size_t i = 0; i < points.size(); ++i) {
        if (used && (i >= used->size() || !(*used)[i])) continue;
        const auto p = projectToPixel(vm, points[i], width, height);
        if (p && p->x >= lo.x && p->x <= hi.x && p->y >= lo.y && p->y <= hi.y) out.push_back(uint32_t(i));
    }
    return out;
}

std::vector<bool> usedPointMask(const Document& doc) {
    std::vector<bool> used(doc.points.size(), false);
    forEachPointIndex(doc, [&](uint32_t i) {
        if (i < used.size()) used[i] = true;
    });
    return used;
}

std::optional<double> intersectTriangle(const Ray& ray, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(ray.dir, e2);
    const double det = glm::dot(e1, p);
    const double scale = std::max({glm::length(e1), glm::length(e2), 1e-300});
    if (std::abs(det) < 1e-14 * scale * scale) return std::nullopt;
    const double inv = 1.0 / det;
    const glm::dvec3 s = ray.origin - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.dir, q) * inv;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double t = glm::dot(e2, q) * inv;
    if (t < 0.0) return std::nullopt;
    return t;
}

namespace {
// False when the ray misses the sphere around the points' centroid that holds them all (the
// control net bounds its patch): the patch cannot be hit.
template <class It>
bool raySphereMayHit(const Ray& ray, It first, It last) {
    glm::dvec3 c(0.0);
    double n = 0.0;
    for (It p = first; p != last; ++p, n += 1.0) c += *p;
    c /= std::max(n, 1.0);
    double r2 = 0.0;
    for (It p = first; p != last; ++p) r2 = std::max(r2, glm::dot(*p - c, *p - c));
    const glm::dvec3 oc = c - ray.origin;
    const double along = glm::dot(oc, ray.dir);
    const double perp2 = glm::dot(oc, oc) - along * along;
    return perp2 <= r2 * 1.0001 + 1e-18;
}
}  // namespace

std::optional<SurfaceHit> pickSurface(const Document& doc, const Ray& ray, int level, const std::vector<bool>* skip) {
    const auto skipped = [&](const auto& idx) { return skip && usesAnyPoint(idx, *skip); };
    level = std::clamp(level, 1, 64);
    const std::vector<PatchInstance> inst = expandPatches(doc);
    std::optional<SurfaceHit> best;
    WindowTrims trims(doc);  // hits on trimmed-away parts go on to what lies behind (issue 64)
    std::vector<SurfacePoint> grid;
    GridWeights weights;
    for (size_t w = 0; w < inst.size(); ++w) {
        const PatchInstance& pi = inst[w];
        if (skipped(pi.idx) || windowHidden(doc, pi)) continue;
        const WindowNet net = gatherWindow(doc, pi.idx);
        // Bounding-sphere rejection first (the control net bounds the Bézier/spline window).
        if (!raySphereMayHit(ray, net.points.begin(), net.points.end())) continue;
        if (weights.basis != pi.basis || weights.tension != pi.tension || weights.nu != level)
            weights = makeGridWeights(pi.basis, pi.tension, level, level);
        evaluateWindowGrid(net, pi.idx, weights, grid);
        const std::optional<WindowTrim> trim = trims.of(pi);
        if (trim && (trim->flags & gpu::kTrimAllGone)) continue;
        const bool tested = trim && (trim->flags & gpu::kTrimTest);
        const int n1 = level + 1;
        for (int r = 0; r < level; ++r)
            for (int col = 0; col < level; ++col) {
                const glm::dvec3& p00 = grid[size_t(r * n1 + col)].p;
                const glm::dvec3& p01 = grid[size_t(r * n1 + col + 1)].p;
                const glm::dvec3& p10 = grid[size_t((r + 1) * n1 + col)].p;
                const glm::dvec3& p11 = grid[size_t((r + 1) * n1 + col + 1)].p;
                for (int tri = 0; tri < 2; ++tri) {
                    const auto t = tri == 0 ? intersectTriangle(ray, p00, p01, p11) : intersectTriangle(ray, p00, p11, p10);
                    if (t && tested) {  // the hit's (u, v) from its barycentric place in the grid triangle
                        const glm::dvec3 a = p00, b = tri == 0 ? p01 : p11, c = tri == 0 ? p11 : p10;
                        const glm::dvec3 h = ray.origin + *t * ray.dir;
                        const glm::dvec3 n = glm::cross(b - a, c - a);
                        const double nn = std::max(glm::dot(n, n), 1e-300);
                        const double wb = glm::dot(glm::cross(h - a, c - a), n) / nn, wc = glm::dot(glm::cross(b - a, h - a), n) / nn;
                        const glm::dvec2 ua(col, r), ub = tri == 0 ? glm::dvec2(col + 1, r) : glm::dvec2(col + 1, r + 1),
                                                     uc = tri == 0 ? glm::dvec2(col + 1, r + 1) : glm::dvec2(col, r + 1);
                        const glm::dvec2 uv = (ua + wb * (ub - ua) + wc * (uc - ua)) / double(level);
                        if (!trimKeeps(trim->segments, (trim->flags & gpu::kTrimBaseKept) == 0, uv)) continue;
                    }
                    if (t && (!best || *t < best->t)) {
                        best = SurfaceHit{int(w), pi.patch, pi.surface, -1, *t, (col + 0.5) / level, (r + 0.5) / level};
                    }
                }
            }
    }
    std::vector<TriPoint> tgrid;
    for (size_t k = 0; k < doc.triangles.size(); ++k) {
        const TrianglePatch& tri = doc.triangles[k];
        if (skipped(tri.idx) || tri.hidden) continue;
        const Net10 net = gatherTriangleNet(doc, tri.idx);
        if (!raySphereMayHit(ray, net.begin(), net.end())) continue;
        evaluateTriangleGrid(net, tri.idx, level, tgrid);
        for (int j = 0; j < level; ++j)
            for (int i = 0; i < level - j; ++i) {
                const auto at = [&](int a, int b) { return tgrid[triGridIndex(a, b, level)].p; };
                auto hit = [&](std::optional<double> t, double cu, double cv) {
                    if (t && (!best || *t < best->t)) best = SurfaceHit{-1, -1, -1, int(k), *t, cu / level, cv / level};
                };
                hit(intersectTriangle(ray, at(i, j), at(i + 1, j), at(i, j + 1)), i + 1.0 / 3.0, j + 1.0 / 3.0);
                if (i + 1 < level - j)
                    hit(intersectTriangle(ray, at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)), i + 2.0 / 3.0, j + 2.0 / 3.0);
            }
    }
    return best;
}

double segmentDistance(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 ab = b - a;
    const double t = glm::dot(ab, ab) > 0.0 ? std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

std::optional<glm::dvec3> intersectPlane(const Ray& ray, const glm::dvec3& point, const glm::dvec3& normal) {
    const double denom = glm::dot(ray.dir, normal);
    if (std::abs(denom) < 1e-12) return std::nullopt;
    const double t = glm::dot(point - ray.origin, normal) / denom;
    if (t < 0.0) return std::nullopt;
    return ray.origin + ray.dir * t;
}

std::optional<AxisOnScreen> axisOnScreen(const Camera& cam, int width, int height, const glm::dvec3& at, const glm::dvec3& axis) {
    const ViewMatrices vm = viewMatrices(cam, double(width) / std::max(height, 1));
    glm::dvec3 right, up, fwd;
    cameraAxes(cam, right, up, fwd);
    const double len = std::max(cam.distance, 1e-9) * 1e-3;  // short enough to stay in front of the eye
    const auto p0 = projectToPixel(vm, at, width, height);
    const auto pa = projectToPixel(vm, at + axis * len, width, height);
    const auto pr = projectToPixel(vm, at + right * len, width, height);
    if (!p0 || !pa || !pr) return std::nullopt;
    return AxisOnScreen{(*pa - *p0) / len, glm::length(*pr - *p0) / len};
}

glm::dvec3 closestPointOnAxis(const Ray& ray, const glm::dvec3& origin, const glm::dvec3& axis) {
    const glm::dvec3 a = glm::normalize(axis);
    const glm::dvec3 w = origin - ray.origin;
    const double b = glm::dot(a, ray.dir);
    const double d = glm::dot(a, w), e = glm::dot(ray.dir, w);
    const double denom = 1.0 - b * b;
    if (denom < 1e-12) return origin;  // axis parallel to the ray: no motion
    const double s = (b * e - d) / denom;
    return origin + a * s;
}

glm::dvec3 snapToGrid(const glm::dvec3& v, double step) {
    if (step <= 0.0) return v;
    return glm::dvec3(std::round(v.x / step) * step, std::round(v.y / step) * step, std::round(v.z / step) * step);
}

double niceGridStep(double modelSize) {
    const double target = std::max(modelSize, 1e-9) / 10.0;
    const double e = std::pow(10.0, std::floor(std::log10(target)));
    const double m = target / e;
    return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * e;
}

}  // namespace select
}  // namespace pw

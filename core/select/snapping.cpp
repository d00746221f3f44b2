// Snap targets under the mouse: control points, boundary edges, surfaces (core/select/snapping.hpp).
#include "core/select/snapping.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/base/enum_names.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/picking.hpp"
#include "core/select/selection_ops.hpp"

namespace pw {
inline namespace select {

namespace {

constexpr std::array<std::string_view, 4> kSnapNames{"grid", "points", "edges", "surfaces"};

// The nearest point, in pixels, of boundary curves given as parameter → point functions.
struct EdgeSearch {
    const ViewMatrices& vm;
    int width, height;
    glm::dvec2 mouse;
    double best2;
    std::optional<Vec3> hit;

    double dist2(const Vec3& p) const {
        const auto px = projectToPixel(vm, p, width, height);
        if (!px) return 1e300;
        const glm::dvec2 d = *px - mouse;
        return glm::dot(d, d);
    }
    // Samples the curve, then narrows the best interval by golden-section search on the distance.
    template <class F>
    void curve(const F& at) {
        constexpr int kSamples = 24;
        int bestK = -1;
        double bestD = 1e300;
        for (int k = 0; k <= kSamples; ++k) {
            const double d = dist2(at(double(k) / kSamples));
            if (d < bestD) bestD = d, bestK = k;
        }
        if (bestK < 0) return;
        double a = std::max(0.0, (bestK - 1.0) / kSamples), b = std::min(1.0, (bestK + 1.0) / kSamples);
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int it = 0; it < 40; ++it) {
            const double c = b - g * (b - a), d = a + g * (b - a);
            if (dist2(at(c)) < dist2(at(d)))
                b = d;
            else
                a = c;
        }
        const Vec3 p = at(0.5 * (a + b));
        const double dp = dist2(p);
        if (dp < best2) best2 = dp, hit = p;
    }
};

}  // namespace

std::string_view snapTargetName(SnapTarget t) { return enumName(t, kSnapNames); }
std::optional<SnapTarget> parseSnapTarget(std::string_view name) { return parseEnum<SnapTarget>(name, kSnapNames); }

std::optional<Vec3> snapPoint(const Document& doc, const std::vector<bool>& moved, SnapTarget target, const Camera& cam, int width,
                              int height, double x, double y, double radiusPx) {
    switch (target) {
        case SnapTarget::Grid:
            return std::nullopt;
        case SnapTarget::Points: {
            std::vector<bool> mask = visiblePointMask(doc);
            for (size_t i = 0; i < mask.size() && i < moved.size(); ++i) mask[i] = mask[i] && !moved[i];
            const int p = pickPoint(cam, doc.points, x, y, width, height, radiusPx, &mask);
            if (p < 0) return std::nullopt;
            return doc.points[size_t(p)];
        }
        case SnapTarget::Edges: {
            const ViewMatrices vm = viewMatrices(cam, double(width) / std::max(height, 1));
            EdgeSearch s{vm, width, height, {x, y}, radiusPx * radiusPx, std::nullopt};
            for (const PatchInstance& pi : expandPatches(doc)) {
                if (usesAnyPoint(pi.idx, moved) || windowHidden(doc, pi)) continue;
                const WindowNet net = gatherWindow(doc, pi.idx);
                const auto eval = [&](double u, double v) { return evaluateWindow(net, pi.basis, pi.tension, u, v).p; };
                s.curve([&](double t) { return eval(0.0, t); });
                s.curve([&](double t) { return eval(1.0, t); });
                s.curve([&](double t) { return eval(t, 0.0); });
                s.curve([&](double t) { return eval(t, 1.0); });
            }
            for (const TrianglePatch& tri : doc.triangles) {
                if (usesAnyPoint(tri.idx, moved) || tri.hidden) continue;
                const Net10 net = gatherTriangleNet(doc, tri.idx);
                s.curve([&](double t) { return evaluateTriangle(net, 0.0, t).p; });      // u = 0
                s.curve([&](double t) { return evaluateTriangle(net, t, 0.0).p; });      // v = 0
                s.curve([&](double t) { return evaluateTriangle(net, t, 1.0 - t).p; });  // w = 0
            }
            return s.hit;
        }
        case SnapTarget::Surfaces: {
            const Ray ray = rayThroughPixel(cam, x, y, width, height);
            const auto hit = pickSurface(doc, ray, 16, &moved);
            if (!hit) return std::nullopt;
            return ray.origin + ray.dir * hit->t;
        }
    }
    return std::nullopt;
}

}  // namespace select
}  // namespace pw

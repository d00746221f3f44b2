#include "core/eval/occlusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/mat4x4.hpp>

#include "core/eval/bezier_triangle.hpp"
#include "core/eval/rational_eval.hpp"

namespace pw {
inline namespace eval {

namespace {

// A depth buffer of the view: per pixel the nearest surface's distance along the view direction.
// Perspective interpolates 1/depth across a triangle on screen (exact), orthographic the depth.
class DepthBuffer {
public:
    DepthBuffer(const Camera& cam, int width, int height)
        : w_(std::max(width, 1)),
          h_(std::max(height, 1)),
          vm_(viewMatrices(cam, double(w_) / h_)),
          ortho_(cam.orthographic),
          depth_(size_t(w_) * size_t(h_), std::numeric_limits<float>::infinity()) {}

    struct Vertex {
        double x = 0, y = 0, q = 0;  // pixel, and 1/depth (perspective) or depth (ortho)
        bool ok = false;
    };
    Vertex project(const Vec3& p) const {
        const glm::dvec4 v = glm::dmat4(vm_.view) * glm::dvec4(p, 1.0);
        const double d = -v.z;
        const auto s = projectToPixel(vm_, p, w_, h_);
        if (!s || d <= 0.0) return {};
        return {s->x, s->y, ortho_ ? d : 1.0 / d, true};
    }
    double depthOf(double q) const { return ortho_ ? q : 1.0 / q; }

    void triangle(const Vertex& a, const Vertex& b, const Vertex& c) {
        if (!a.ok || !b.ok || !c.ok) return;
        const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (std::abs(area) < 1e-12) return;
        const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x})))),
                  x1 = std::min(w_ - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y})))),
                  y1 = std::min(h_ - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                const double wa = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
                const double wb = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
                const double wc = 1.0 - wa - wb;
                if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
                float& d = depth_[size_t(y) * size_t(w_) + size_t(x)];
                d = std::min(d, float(depthOf(wa * a.q + wb * b.q + wc * c.q)));
            }
    }

    // True when the surface lies in front of p by more than `tolerance` at p's pixel and all
    // eight around it.
    bool hides(const Vec3& p, double tolerance) const {
        const Vertex v = project(p);
        if (!v.ok) return false;
        const int cx = int(std::floor(v.x)), cy = int(std::floor(v.y));
        const double d = depthOf(v.q);
        for (int y = cy - 1; y <= cy + 1; ++y)
            for (int x = cx - 1; x <= cx + 1; ++x) {
                if (x < 0 || y < 0 || x >= w_ || y >= h_) return false;
                if (!(double(depth_[size_t(y) * size_t(w_) + size_t(x)]) < d - tolerance)) return false;
            }
        return true;
    }

private:
    int w_, h_;
    ViewMatrices vm_;
    bool ortho_;
    std::vector<float> depth_;
};

}  // namespace

std::vector<uint32_t> unoccludedPoints(const Document& doc, const Camera& cam, int width, int height,
                                       const std::vector<uint32_t>& candidates, int level) {
    if (candidates.empty()) return {};
    level = std::clamp(level, 1, 64);
    DepthBuffer depth(cam, width, height);
    std::vector<DepthBuffer::Vertex> v;
    std::vector<SurfacePoint> grid;
    GridWeights weights;
    for (const PatchInstance& pi : expandPatches(doc)) {
        if (windowHidden(doc, pi)) continue;
        if (weights.basis != pi.basis || weights.tension != pi.tension || weights.nu != level)
            weights = makeGridWeights(pi.basis, pi.tension, level, level);
        evaluateWindowGrid(gatherWindow(doc, pi.idx), pi.idx, weights, grid);
        v.resize(grid.size());
        for (size_t i = 0; i < grid.size(); ++i) v[i] = depth.project(grid[i].p);
        const int n1 = level + 1;
        for (int r = 0; r < level; ++r)
            for (int c = 0; c < level; ++c) {
                const size_t i00 = size_t(r * n1 + c), i01 = i00 + 1, i10 = i00 + size_t(n1), i11 = i10 + 1;
                depth.triangle(v[i00], v[i01], v[i11]);
                depth.triangle(v[i00], v[i11], v[i10]);
            }
    }
    std::vector<TriPoint> tgrid;
    for (const TrianglePatch& tri : doc.triangles) {
        if (tri.hidden) continue;
        evaluateTriangleGrid(gatherTriangleNet(doc, tri.idx), tri.idx, level, tgrid);
        auto at = [&](int a, int b) { return depth.project(tgrid[triGridIndex(a, b, level)].p); };
        for (int j = 0; j < level; ++j)
            for (int i = 0; i < level - j; ++i) {
                depth.triangle(at(i, j), at(i + 1, j), at(i, j + 1));
                if (i + 1 < level - j) depth.triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            }
    }
    const double tolerance = 0.01 * modelSize(doc);
    std::vector<uint32_t> out;
    for (uint32_t p : candidates)
        if (p < doc.points.size() && !depth.hides(doc.points[p], tolerance)) out.push_back(p);
    return out;
}

}  // namespace eval
}  // namespace pw

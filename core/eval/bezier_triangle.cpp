#include "core/eval/bezier_triangle.hpp"

#include <Eigen/Dense>
#include <algorithm>

#include "core/base/net_scale.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/gpu/patch_math.h"
#include "core/model/document.hpp"

namespace pw {
inline namespace eval {

namespace {

struct TriDerivs {
    Vec3 p{0.0}, du{0.0}, dv{0.0};
};

// Cubic Bernstein sum for p, quadratic sums of the differences for the two derivatives.
TriDerivs triEval(const Net10& net, double u, double v, double w) {
    const double U[4] = {1.0, u, u * u, u * u * u};
    const double V[4] = {1.0, v, v * v, v * v * v};
    const double Wp[4] = {1.0, w, w * w, w * w * w};
    static const double fact[4] = {1, 1, 2, 6};
    TriDerivs d;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3 - i; ++j) {
            const int k = 3 - i - j;
            d.p += (6.0 / (fact[i] * fact[j] * fact[k])) * U[i] * V[j] * Wp[k] * net[triSlot(i, j, k)];
        }
    for (int a = 0; a <= 2; ++a)
        for (int b = 0; b <= 2 - a; ++b) {
            const int c = 2 - a - b;
            const double B = 3.0 * (2.0 / (fact[a] * fact[b] * fact[c])) * U[a] * V[b] * Wp[c];
            const Vec3& toW = net[triSlot(a, b, c + 1)];
            d.du += B * (net[triSlot(a + 1, b, c)] - toW);
            d.dv += B * (net[triSlot(a, b + 1, c)] - toW);
        }
    return d;
}

}  // namespace

int triSlot(int i, int j, int k) {
    (void)j;
    return (3 - i) * (4 - i) / 2 + k;
}

int triEdgeSlot(int edge, int k) { return gpu::triEdgeSlot(edge, k); }

TriPoint evaluateTriangle(const Net10& net, double u, double v) { return evaluateTriangle(net, u, v, 1.0 - u - v); }

TriPoint evaluateTriangle(const Net10& net, double u, double v, double w) {
    const TriDerivs d = triEval(net, u, v, w);
    TriPoint tp;
    tp.p = d.p;
    tp.du = d.du;
    tp.dv = d.dv;
    tp.n = triangleNormalAt(net, u, v, w, d.du, d.dv);
    return tp;
}

Vec3 triangleNormalAt(const Net10& net, double u, double v, double w, const Vec3& du, const Vec3& dv) {
    const double scale = netScale(net), scale2 = scale * scale;
    Vec3 n = glm::cross(du, dv);
    if (!degenerateCross(n, scale2)) return n / glm::length(n);
    // A small step towards the centroid: inside, the tangent plane is defined again and has the
    // orientation of the interior.
    const double third = 1.0 / 3.0;
    for (double s : {1e-7, 1e-5, 1e-3, 1e-2, 1e-1, 1.0}) {
        const TriDerivs e = triEval(net, u + (third - u) * s, v + (third - v) * s, w + (third - w) * s);
        n = glm::cross(e.du, e.dv);
        if (!degenerateCross(n, scale2)) return n / glm::length(n);
    }
    return Vec3(0, 0, 1);
}

Vec3 evaluateTriangleBernsteinSum(const Net10& net, double u, double v, double w) { return triEval(net, u, v, w).p; }

Net10 gatherTriangleNet(const Document& doc, const std::array<uint32_t, 10>& idx) {
    Net10 net;
    for (int k = 0; k < 10; ++k) net[k] = doc.points[idx[k]];
    return net;
}

std::array<uint32_t, 4> triEdgePool(const std::array<uint32_t, 10>& idx, int edge) {
    return {idx[triEdgeSlot(edge, 0)], idx[triEdgeSlot(edge, 1)], idx[triEdgeSlot(edge, 2)], idx[triEdgeSlot(edge, 3)]};
}

std::array<int, 2> triGridEdgePoint(int edge, int k, int n) {
    switch (edge) {
        case 0:
            return {0, n - k};
        case 1:
            return {k, 0};
        default:
            return {n - k, k};
    }
}

void evaluateTriangleGrid(const Net10& net, const std::array<uint32_t, 10>& poolIdx, int n, std::vector<TriPoint>& out) {
    out.resize(triGridSize(n));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n - j; ++i)
            out[triGridIndex(i, j, n)] =
                evaluateTriangle(net, static_cast<double>(i) / n, static_cast<double>(j) / n, static_cast<double>(n - i - j) / n);
    for (int e = 0; e < 3; ++e) {
        std::array<Vec3, 4> pts;
        for (int k = 0; k < 4; ++k) pts[k] = net[triEdgeSlot(e, k)];
        const std::array<uint32_t, 4> ids = triEdgePool(poolIdx, e);
        for (int k = 0; k <= n; ++k) {
            const auto [i, j] = triGridEdgePoint(e, k, n);
            out[triGridIndex(i, j, n)].p = evaluateSharedBezierEdge(pts, ids, k, n);
        }
    }
}

Net16 triangleAsCollapsedQuad(const Net10& net) {
    // Interpolation at s, t in {0, 1/3, 2/3, 1} is exact for a bicubic: P = B⁻¹ S B⁻ᵀ with B the
    // cubic Bernstein basis at those nodes.
    static constexpr double kInv[4][4] = {{1, 0, 0, 0}, {-5.0 / 6, 3, -1.5, 1.0 / 3}, {1.0 / 3, -1.5, 3, -5.0 / 6}, {0, 0, 0, 1}};
    auto build = [&](bool flip) {
        std::array<std::array<Vec3, 4>, 4> S;  // [s node][t node]
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) {
                const double sv = a / 3.0, tv = (flip ? 3 - b : b) / 3.0;
                S[a][b] = a == 0 ? net[0] : evaluateTriangleBernsteinSum(net, 1.0 - sv, sv * (1.0 - tv), sv * tv);
            }
        Net16 out;
        for (int i = 0; i < 4; ++i)        // t
            for (int j = 0; j < 4; ++j) {  // s
                Vec3 sum(0.0);
                for (int a = 0; a < 4; ++a)
                    for (int b = 0; b < 4; ++b) sum += kInv[j][a] * kInv[i][b] * S[a][b];
                out[size_t(i * 4 + j)] = j == 0 ? net[0] : sum;
            }
        return out;
    };
    Net16 quad = build(false);
    // Orientation: compare normals at the middle of the triangle's image.
    const SurfacePoint q = evaluateNet(quad, Basis::Bezier, 0.5, 0.5, 0.5);
    const TriPoint t = evaluateTriangle(net, 0.5, 0.25, 0.25);
    if (glm::dot(glm::cross(q.du, q.dv), t.n) < 0.0) quad = build(true);
    return quad;
}

std::optional<Net10> collapsedQuadAsTriangle(const Net16& quad, double tol) {
    // The cubic triangle interpolating the quad at the ten nodes (i, j, k) / 3 of the triangle,
    // read at (s, t) = (1 - u, w / (1 - u)) and, for the other row order, (s, 1 - t); kept when
    // collapsing it again gives the quad back.
    Eigen::Matrix<double, 10, 10> basis;
    std::array<std::array<double, 3>, 10> nodes;
    size_t n = 0;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; i + j <= 3; ++j) nodes[n++] = {i / 3.0, j / 3.0, (3 - i - j) / 3.0};
    for (size_t c = 0; c < 10; ++c) {
        Net10 unit{};
        unit[c] = Vec3(1.0, 0.0, 0.0);
        for (size_t r = 0; r < 10; ++r)
            basis(long(r), long(c)) = evaluateTriangleBernsteinSum(unit, nodes[r][0], nodes[r][1], nodes[r][2]).x;
    }
    const Eigen::PartialPivLU<Eigen::Matrix<double, 10, 10>> lu(basis);
    for (bool flip : {false, true}) {
        Eigen::Matrix<double, 10, 3> values;
        for (size_t r = 0; r < 10; ++r) {
            const double s = 1.0 - nodes[r][0];
            const double t = s > 0.0 ? nodes[r][2] / s : 0.0;
            const Vec3 q = evaluateNet(quad, Basis::Bezier, 0.5, s, flip ? 1.0 - t : t).p;
            values.row(long(r)) << q.x, q.y, q.z;
        }
        const Eigen::Matrix<double, 10, 3> coef = lu.solve(values);
        Net10 net;
        for (size_t c = 0; c < 10; ++c) net[c] = Vec3(coef(long(c), 0), coef(long(c), 1), coef(long(c), 2));
        const Net16 again = triangleAsCollapsedQuad(net);
        double worst = 0.0;
        for (size_t k = 0; k < 16; ++k) worst = std::max(worst, glm::length(again[k] - quad[k]));
        if (worst <= tol) return net;
    }
    return std::nullopt;
}

}  // namespace eval
}  // namespace pw

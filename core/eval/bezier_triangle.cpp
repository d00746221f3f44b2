#include "core/eval/bezier_triangle.hpp"

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
    // The quad's rows t = 0 and t = 1 are the triangle's edges w = 0 (b300 b210 b120 b030: slots
    // 0 1 3 6) and v = 0 (b300 b201 b102 b003: 0 2 5 9), or the other way round when its rows were
    // turned, and its column s = 1 the edge u = 0 (6 7 8 9); the centre b111 (slot 4) follows from the quad's value at (2/3, 1/2), the
    // image of (1/3, 1/3, 1/3), where b111 weighs 6/27. Kept when collapsing it again gives the quad back.
    static constexpr size_t kEdgeW0[4] = {0, 1, 3, 6}, kEdgeV0[4] = {0, 2, 5, 9};
    for (bool flip : {false, true}) {
        Net10 net{};
        for (size_t j = 0; j < 4; ++j) {
            net[kEdgeW0[j]] = quad[(flip ? 12 : 0) + j];
            net[kEdgeV0[j]] = quad[(flip ? 0 : 12) + j];
        }
        net[7] = quad[(flip ? 2 : 1) * 4 + 3];  // column s = 1 is the edge u = 0: b030 b021 b012 b003
        net[8] = quad[(flip ? 1 : 2) * 4 + 3];
        const Vec3 centre = evaluateNet(quad, Basis::Bezier, 0.5, 2.0 / 3.0, 0.5).p;
        net[4] = (centre - evaluateTriangleBernsteinSum(net, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0)) * (27.0 / 6.0);
        const Net16 again = triangleAsCollapsedQuad(net);
        double worst = 0.0;
        for (size_t k = 0; k < 16; ++k) worst = std::max(worst, glm::length(again[k] - quad[k]));
        if (worst <= tol) return net;
    }
    return std::nullopt;
}

}  // namespace eval
}  // namespace pw

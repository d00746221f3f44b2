#include "core/eval/rational_eval.hpp"

#include <glm/vec4.hpp>

#include "core/base/net_scale.hpp"
#include "core/eval/tensor_sums.hpp"
#include "core/gpu/patch_math.h"
#include "core/gpu/rational_math.h"
#include "core/model/basis.hpp"

namespace pw {
inline namespace eval {

namespace {

using Vec4 = glm::dvec4;
using gpu::rationalDerivative;
using gpu::rationalPoint;
using gpu::rationalSecondDerivative;

using HomogeneousNet = std::array<Vec4, 16>;

HomogeneousNet homogeneous(const WindowNet& net) {
    HomogeneousNet out;
    for (size_t k = 0; k < 16; ++k) out[k] = gpu::homogeneousPoint<double>(net.points[k], net.weights ? (*net.weights)[k] : 1.0);
    return out;
}

// The homogeneous sums and their first and second partial derivatives.
using HomogeneousJet = TensorSums<Vec4>;

HomogeneousJet homogeneousJet(const HomogeneousNet& net, const BasisWeights& wu, const BasisWeights& wv) { return tensorSums(net, wu, wv); }

SurfaceJet rationalJet(const HomogeneousJet& h) {
    SurfaceJet s;
    s.p = rationalPoint(h.p);
    s.du = rationalDerivative(h.p, h.du, s.p);
    s.dv = rationalDerivative(h.p, h.dv, s.p);
    s.duu = rationalSecondDerivative(h.p, h.du, h.du, h.duu, s.p, s.du, s.du);
    s.duv = rationalSecondDerivative(h.p, h.du, h.dv, h.duv, s.p, s.du, s.dv);
    s.dvv = rationalSecondDerivative(h.p, h.dv, h.dv, h.dvv, s.p, s.dv, s.dv);
    return s;
}

SurfaceJet jetAt(const HomogeneousNet& net, Basis basis, double tension, double u, double v) {
    return rationalJet(homogeneousJet(net, basisWeights(basis, tension, u), basisWeights(basis, tension, v)));
}

// normalAt (core/eval/patch_eval.cpp) for a rational window: du × dv; at a collapsed row or column the
// limit from inside through the mixed derivative; else the normal a small step towards the centre.
Vec3 rationalNormal(const HomogeneousNet& hn, double scale, Basis basis, double tension, double u, double v, const SurfaceJet& j) {
    const double scale2 = scale * scale;
    Vec3 n = glm::cross(j.du, j.dv);
    if (!degenerateCross(n, scale2)) return n / glm::length(n);
    const double tiny = 1e-9 * scale;
    const bool duZero = glm::length(j.du) <= tiny, dvZero = glm::length(j.dv) <= tiny;
    if (duZero && !dvZero)
        n = glm::cross(j.duv, j.dv) * (v < 0.5 ? 1.0 : -1.0);
    else if (dvZero && !duZero)
        n = glm::cross(j.du, j.duv) * (u < 0.5 ? 1.0 : -1.0);
    if (!degenerateCross(n, scale2)) return n / glm::length(n);
    for (double step : {1e-7, 1e-5, 1e-3, 1e-2}) {
        const SurfaceJet e = jetAt(hn, basis, tension, u + (0.5 - u) * step * 2.0, v + (0.5 - v) * step * 2.0);
        n = glm::cross(e.du, e.dv);
        if (!degenerateCross(n, scale2)) return n / glm::length(n);
    }
    return Vec3(0, 0, 1);
}

}  // namespace

WindowNet gatherWindow(const Document& doc, const std::array<uint32_t, 16>& idx) { return {gatherNet(doc, idx), gatherWeights(doc, idx)}; }

SurfaceJet evaluateWindowJet(const WindowNet& net, Basis basis, double tension, double u, double v) {
    if (!net.weights) return evaluateJet(net.points, basis, tension, u, v);
    const HomogeneousNet hn = homogeneous(net);
    SurfaceJet j = jetAt(hn, basis, tension, u, v);
    j.n = rationalNormal(hn, netScale(net.points), basis, tension, u, v, j);
    return j;
}

SurfacePoint evaluateWindow(const WindowNet& net, Basis basis, double tension, double u, double v) {
    if (!net.weights) return evaluateNet(net.points, basis, tension, u, v);
    const SurfaceJet j = evaluateWindowJet(net, basis, tension, u, v);
    return {j.p, j.du, j.dv, j.n};
}

void evaluateWindowGrid(const WindowNet& net, const std::array<uint32_t, 16>& poolIdx, const GridWeights& gw,
                        std::vector<SurfacePoint>& out) {
    if (!net.weights) return evaluateGrid(net.points, poolIdx, gw, out);
    const int nu = gw.nu, nv = gw.nv, stride = nu + 1;
    out.resize(size_t(stride) * size_t(nv + 1));
    const HomogeneousNet hn = homogeneous(net);
    const double scale = netScale(net.points);
    for (int r = 0; r <= nv; ++r)
        for (int c = 0; c <= nu; ++c) {
            const SurfaceJet j = rationalJet(homogeneousJet(hn, gw.u[size_t(c)], gw.v[size_t(r)]));
            SurfacePoint& sp = out[size_t(r) * size_t(stride) + size_t(c)];
            sp = {j.p, j.du, j.dv, rationalNormal(hn, scale, gw.basis, gw.tension, double(c) / nu, double(r) / nv, j)};
        }
    if (gw.basis != Basis::Bezier) return;
    // Boundary positions from each boundary's points alone, in its canonical direction (the sums in
    // evaluateSharedBezierEdge's order, so weights 1 give its bits).
    for (Edge e : {Edge::U0, Edge::V0, Edge::U1, Edge::V1}) {
        std::array<uint32_t, 4> ids;
        for (int k = 0; k < 4; ++k) ids[size_t(k)] = poolIdx[size_t(edgeSlot(e, k))];
        const bool flip = edgeReversed(ids);
        const bool alongU = e == Edge::V0 || e == Edge::V1;
        const int n = alongU ? nu : nv;
        for (int k = 0; k <= n; ++k) {
            const int kk = flip ? n - k : k;
            const BasisWeights w = bernsteinWeights(double(kk) / n, double(n - kk) / n);
            Vec3 h{0.0};
            double g = 0.0;
            for (int i = 0; i < 4; ++i) {
                const Vec4& q = hn[size_t(edgeSlot(e, flip ? 3 - i : i))];
                h += w.w[i] * Vec3(q);
                g += w.w[i] * q.w;
            }
            const int r = alongU ? (e == Edge::V0 ? 0 : nv) : k;
            const int c = alongU ? k : (e == Edge::U0 ? 0 : nu);
            out[size_t(r) * size_t(stride) + size_t(c)].p = h / (1.0 + g);
        }
    }
}

WeightedSplit splitWindowBezier(const WindowNet& net, bool alongU, double t) {
    if (!net.weights) {
        const auto [a, b] = alongU ? splitBezierU(net.points, t) : splitBezierV(net.points, t);
        return {{a, std::nullopt}, {b, std::nullopt}};
    }
    // De Casteljau is linear: split the weighted points w·P and the weights w (as points) alike.
    Net16 wp, ww;
    for (size_t k = 0; k < 16; ++k) {
        wp[k] = net.points[k] * (*net.weights)[k];
        ww[k] = Vec3((*net.weights)[k], 0.0, 0.0);
    }
    const auto [a, b] = alongU ? splitBezierU(wp, t) : splitBezierV(wp, t);
    const auto [wa, wb] = alongU ? splitBezierU(ww, t) : splitBezierV(ww, t);
    WeightedSplit s{{{}, Weights16{}}, {{}, Weights16{}}};
    for (size_t k = 0; k < 16; ++k) {
        (*s.first.weights)[k] = wa[k].x;
        (*s.second.weights)[k] = wb[k].x;
        s.first.points[k] = a[k] / wa[k].x;
        s.second.points[k] = b[k] / wb[k].x;
    }
    return s;
}

CurveJet evaluateRationalCurve(const std::array<Vec3, 4>& p, const std::array<double, 4>& w, double t) {
    const BasisWeights b = bernsteinWeights(t, 1.0 - t);
    Vec4 h{0.0}, h1{0.0}, h2{0.0};
    for (size_t i = 0; i < 4; ++i) {
        const Vec4 q = gpu::homogeneousPoint<double>(p[i], w[i]);
        h += b.w[i] * q;
        h1 += b.dw[i] * q;
        h2 += b.ddw[i] * q;
    }
    CurveJet j;
    j.p = rationalPoint(h);
    j.d1 = rationalDerivative(h, h1, j.p);
    j.d2 = rationalSecondDerivative(h, h1, h1, h2, j.p, j.d1, j.d1);
    return j;
}

}  // namespace eval
}  // namespace pw

#include "core/eval/patch_eval.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/net_scale.hpp"
#include "core/eval/tensor_sums.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace eval {

namespace {

struct Derivs {
    Vec3 p{0.0}, du{0.0}, dv{0.0}, duv{0.0};
};

Derivs tensorEval(const Net16& net, const BasisWeights& wu, const BasisWeights& wv) {
    Derivs d;
    for (int i = 0; i < 4; ++i) {
        Vec3 row{0.0}, rowDu{0.0};
        for (int j = 0; j < 4; ++j) {
            row += wu.w[j] * net[i * 4 + j];
            rowDu += wu.dw[j] * net[i * 4 + j];
        }
        d.p += wv.w[i] * row;
        d.dv += wv.dw[i] * row;
        d.du += wv.w[i] * rowDu;
        d.duv += wv.dw[i] * rowDu;
    }
    return d;
}

}  // namespace

SurfacePoint evaluateNet(const Net16& net, Basis basis, double tension, double u, double v) {
    const Derivs d = tensorEval(net, basisWeights(basis, tension, u), basisWeights(basis, tension, v));
    SurfacePoint sp;
    sp.p = d.p;
    sp.du = d.du;
    sp.dv = d.dv;
    sp.n = normalAt(net, basis, tension, u, v, d.du, d.dv);
    return sp;
}

SurfaceJet evaluateJet(const Net16& net, Basis basis, double tension, double u, double v) {
    const TensorSums<Vec3> s = tensorSums(net, basisWeights(basis, tension, u), basisWeights(basis, tension, v));
    SurfaceJet j{s.p, s.du, s.dv, s.duu, s.duv, s.dvv, Vec3(0.0)};
    j.n = normalAt(net, basis, tension, u, v, j.du, j.dv);
    return j;
}

Vec3 normalAt(const Net16& net, Basis basis, double tension, double u, double v, const Vec3& du, const Vec3& dv) {
    const double scale = netScale(net);
    const double scale2 = scale * scale;
    Vec3 n = glm::cross(du, dv);
    if (!degenerateCross(n, scale2)) return n / glm::length(n);

    // Limit from inside: near a collapsed row du(v) ≈ (v - v_edge)·duv, near a collapsed column
    // dv(u) ≈ (u - u_edge)·duv; the sign keeps the orientation of the interior.
    const Derivs d = tensorEval(net, basisWeights(basis, tension, u), basisWeights(basis, tension, v));
    const double tiny = 1e-9 * scale;
    const bool duZero = glm::length(du) <= tiny;
    const bool dvZero = glm::length(dv) <= tiny;
    if (duZero && !dvZero)
        n = glm::cross(d.duv, dv) * (v < 0.5 ? 1.0 : -1.0);
    else if (dvZero && !duZero)
        n = glm::cross(du, d.duv) * (u < 0.5 ? 1.0 : -1.0);
    if (!degenerateCross(n, scale2)) return n / glm::length(n);

    // Last resort: the normal a small step towards the centre of the domain.
    for (double step : {1e-7, 1e-5, 1e-3, 1e-2}) {
        const double uu = u + (0.5 - u) * step * 2.0, vv = v + (0.5 - v) * step * 2.0;
        const Derivs e = tensorEval(net, basisWeights(basis, tension, uu), basisWeights(basis, tension, vv));
        n = glm::cross(e.du, e.dv);
        if (!degenerateCross(n, scale2)) return n / glm::length(n);
    }
    return Vec3(0, 0, 1);  // a net collapsed to a point or a line has no normal
}

Vec3 evaluateBezierBernsteinSum(const Net16& net, double u, double v) {
    auto bern = [](int i, double t) {
        static const double binom[4] = {1, 3, 3, 1};
        return binom[i] * std::pow(t, i) * std::pow(1.0 - t, 3 - i);
    };
    Vec3 p{0.0};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p += bern(i, v) * bern(j, u) * net[i * 4 + j];
    return p;
}

Vec3 evaluateMatrixForm(const Net16& net, const Mat4& m, double u, double v) {
    const double U[4] = {u * u * u, u * u, u, 1.0};
    const double V[4] = {v * v * v, v * v, v, 1.0};
    double vm[4] = {0, 0, 0, 0}, um[4] = {0, 0, 0, 0};  // V·M and U·M
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            vm[c] += V[r] * m[r][c];
            um[c] += U[r] * m[r][c];
        }
    Vec3 p{0.0};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p += vm[i] * net[i * 4 + j] * um[j];
    return p;
}

namespace {

// de Casteljau on four points: returns the point at t and fills the left/right control polygons.
Vec3 casteljau4(const Vec3 (&p)[4], double t, Vec3 (&left)[4], Vec3 (&right)[4]) {
    const Vec3 a = glm::mix(p[0], p[1], t), b = glm::mix(p[1], p[2], t), c = glm::mix(p[2], p[3], t);
    const Vec3 d = glm::mix(a, b, t), e = glm::mix(b, c, t);
    const Vec3 f = glm::mix(d, e, t);
    left[0] = p[0];
    left[1] = a;
    left[2] = d;
    left[3] = f;
    right[0] = f;
    right[1] = e;
    right[2] = c;
    right[3] = p[3];
    return f;
}

}  // namespace

Vec3 evaluateBezierDeCasteljau(const Net16& net, double u, double v) {
    Vec3 col[4], l[4], r[4];
    for (int i = 0; i < 4; ++i) {
        const Vec3 row[4] = {net[i * 4], net[i * 4 + 1], net[i * 4 + 2], net[i * 4 + 3]};
        col[i] = casteljau4(row, u, l, r);
    }
    return casteljau4(col, v, l, r);
}

std::pair<Net16, Net16> splitBezierU(const Net16& net, double u) {
    Net16 a, b;
    for (int i = 0; i < 4; ++i) {
        const Vec3 row[4] = {net[i * 4], net[i * 4 + 1], net[i * 4 + 2], net[i * 4 + 3]};
        Vec3 l[4], r[4];
        casteljau4(row, u, l, r);
        for (int j = 0; j < 4; ++j) {
            a[i * 4 + j] = l[j];
            b[i * 4 + j] = r[j];
        }
    }
    return {a, b};
}

std::pair<Net16, Net16> splitBezierV(const Net16& net, double v) {
    auto transpose = [](const Net16& n) {
        Net16 t;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) t[j * 4 + i] = n[i * 4 + j];
        return t;
    };
    auto [a, b] = splitBezierU(transpose(net), v);
    return {transpose(a), transpose(b)};
}

Vec3 evaluateSharedBezierEdge(const std::array<Vec3, 4>& pts, const std::array<uint32_t, 4>& poolIdx, int k, int n) {
    const bool flip = edgeReversed(poolIdx);
    const int kk = flip ? n - k : k;
    const double t = static_cast<double>(kk) / n, s = static_cast<double>(n - kk) / n;
    const BasisWeights w = bernsteinWeights(t, s);
    Vec3 p{0.0};
    for (int i = 0; i < 4; ++i) p += w.w[i] * pts[flip ? 3 - i : i];
    return p;
}

GridWeights makeGridWeights(Basis basis, double tension, int nu, int nv) {
    GridWeights g;
    g.basis = basis;
    g.tension = tension;
    g.nu = nu;
    g.nv = nv;
    auto fill = [&](int n, std::vector<BasisWeights>& out) {
        out.resize(n + 1);
        for (int k = 0; k <= n; ++k) {
            const double t = static_cast<double>(k) / n;
            out[k] = basis == Basis::Bezier ? bernsteinWeights(t, static_cast<double>(n - k) / n) : basisWeights(basis, tension, t);
        }
    };
    fill(nu, g.u);
    fill(nv, g.v);
    return g;
}

void evaluateGrid(const Net16& net, const std::array<uint32_t, 16>& poolIdx, const GridWeights& gw, std::vector<SurfacePoint>& out) {
    const int nu = gw.nu, nv = gw.nv, stride = nu + 1;
    out.resize(static_cast<size_t>(stride) * (nv + 1));
    const double scale = netScale(net), scale2 = scale * scale;
    for (int r = 0; r <= nv; ++r) {
        const BasisWeights& wv = gw.v[r];
        Vec3 q[4], dq[4];  // the net collapsed along v: four points and their v-derivatives
        for (int j = 0; j < 4; ++j) {
            q[j] = wv.w[0] * net[j] + wv.w[1] * net[4 + j] + wv.w[2] * net[8 + j] + wv.w[3] * net[12 + j];
            dq[j] = wv.dw[0] * net[j] + wv.dw[1] * net[4 + j] + wv.dw[2] * net[8 + j] + wv.dw[3] * net[12 + j];
        }
        for (int c = 0; c <= nu; ++c) {
            const BasisWeights& wu = gw.u[c];
            SurfacePoint& sp = out[static_cast<size_t>(r) * stride + c];
            sp.p = wu.w[0] * q[0] + wu.w[1] * q[1] + wu.w[2] * q[2] + wu.w[3] * q[3];
            sp.du = wu.dw[0] * q[0] + wu.dw[1] * q[1] + wu.dw[2] * q[2] + wu.dw[3] * q[3];
            sp.dv = wu.w[0] * dq[0] + wu.w[1] * dq[1] + wu.w[2] * dq[2] + wu.w[3] * dq[3];
            const Vec3 n = glm::cross(sp.du, sp.dv);
            if (!degenerateCross(n, scale2))
                sp.n = n / glm::length(n);
            else
                sp.n = normalAt(net, gw.basis, gw.tension, static_cast<double>(c) / nu, static_cast<double>(r) / nv, sp.du, sp.dv);
        }
    }
    if (gw.basis != Basis::Bezier) return;
    // Boundary positions from each boundary curve alone, in its canonical direction.
    for (Edge e : {Edge::U0, Edge::V0, Edge::U1, Edge::V1}) {
        std::array<Vec3, 4> pts;
        std::array<uint32_t, 4> ids;
        for (int k = 0; k < 4; ++k) {
            pts[k] = net[edgeSlot(e, k)];
            ids[k] = poolIdx[edgeSlot(e, k)];
        }
        const bool alongU = e == Edge::V0 || e == Edge::V1;
        const int n = alongU ? nu : nv;
        for (int k = 0; k <= n; ++k) {
            const int r = alongU ? (e == Edge::V0 ? 0 : nv) : k;
            const int c = alongU ? k : (e == Edge::U0 ? 0 : nu);
            out[static_cast<size_t>(r) * stride + c].p = evaluateSharedBezierEdge(pts, ids, k, n);
        }
    }
}

}  // namespace eval
}  // namespace pw

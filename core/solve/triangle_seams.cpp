#include "core/solve/triangle_seams.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/eval/bezier_curve.hpp"
#include "core/eval/bezier_triangle.hpp"

namespace pw {
inline namespace solve {

namespace {

double binomial(int n, int k) {
    if (k < 0 || k > n) return 0.0;
    double r = 1.0;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

double bernstein(int n, int i, double t) { return binomial(n, i) * std::pow(t, i) * std::pow(1.0 - t, n - i); }

// Barycentric (i, j, k) of point m (0..3) along triangle edge `edge`, and of the point one row in
// from the edge between points m and m + 1 (m = 0..2): the edge's zero index raised to one.
std::array<int, 3> edgeIndex(int edge, int m) {
    switch (edge) {
        case 0:
            return {0, 3 - m, m};  // u = 0, from the v corner to the w corner
        case 1:
            return {m, 0, 3 - m};  // v = 0, from w to u
        default:
            return {3 - m, m, 0};  // w = 0, from u to v
    }
}
std::array<int, 3> innerIndex(int edge, int m) {
    const std::array<int, 3> a = edgeIndex(edge, m), b = edgeIndex(edge, m + 1);
    std::array<int, 3> f{std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2])};
    ++f[size_t(edge)];
    return f;
}
uint32_t triPoint(const TrianglePatch& t, const std::array<int, 3>& ijk) { return t.idx[size_t(triSlot(ijk[0], ijk[1], ijk[2]))]; }

// Bernstein coefficients of degree n raised to degree N (N >= n).
std::vector<PointCombination> elevated(const std::vector<PointCombination>& c, int N) {
    const int n = int(c.size()) - 1;
    std::vector<PointCombination> out(size_t(N + 1));
    for (int l = 0; l <= N; ++l)
        for (int i = std::max(0, l - (N - n)); i <= std::min(n, l); ++i) {
            const double w = binomial(n, i) * binomial(N - n, l - i) / binomial(N, l);
            for (const auto& [idx, coef] : c[size_t(i)]) out[size_t(l)].emplace_back(idx, w * coef);
        }
    return out;
}

// β(t)·c'(t) for the unit β that is Bernstein basis function i of degree 2, as degree-4 coefficients.
std::vector<PointCombination> shearTerm(const SeamSide& a, int i) {
    std::vector<PointCombination> out(5);
    for (int j = 0; j < 3; ++j) {
        const double w = shearWeight(i, j);
        out[size_t(i + j)].insert(out[size_t(i + j)].end(), {{a.edge[size_t(j + 1)], w}, {a.edge[size_t(j)], -w}});
    }
    return out;
}

Vec3 evaluate(const Document& doc, const std::vector<PointCombination>& c, double t) {
    Vec3 s(0.0);
    const int n = int(c.size()) - 1;
    for (int i = 0; i <= n; ++i) s += bernstein(n, i, t) * valueOf(doc, c[size_t(i)]);
    return s;
}

Vec3 evaluateEdge(const Document& doc, const std::array<uint32_t, 4>& e, double t) {
    return evaluateCurve({doc.points[e[0]], doc.points[e[1]], doc.points[e[2]], doc.points[e[3]]}, t);
}

// α(t)·D_A(t) at degree N: α constant, or running linearly from α at t = 0 to endAlpha at t = 1
// ((1−t)·B^n_i = (n+1−i)/(n+1)·B^(n+1)_i, t·B^n_i = (i+1)/(n+1)·B^(n+1)_(i+1)).
std::vector<PointCombination> alphaTerm(const Join& join, const SeamSide& a, int N) {
    if (join.alphaEnd == 0.0) {
        auto out = elevated(a.cross, N);
        for (auto& c : out)
            for (auto& term : c) term.second *= join.alpha;
        return out;
    }
    const int n = int(a.cross.size()) - 1;
    std::vector<PointCombination> product(size_t(n + 2));
    for (int i = 0; i <= n; ++i)
        for (const auto& [idx, coef] : a.cross[size_t(i)]) {
            product[size_t(i)].emplace_back(idx, join.alpha * coef * (n + 1 - i) / (n + 1));
            product[size_t(i + 1)].emplace_back(idx, join.alphaEnd * coef * (i + 1) / (n + 1));
        }
    return elevated(product, N);
}

int identityDegree(const Join& join, const SeamSide& a, const SeamSide& b) {
    int d = int(std::max(b.cross.size(), a.cross.size() + (join.alphaEnd != 0.0 ? 1 : 0))) - 1;
    return join.shear != std::array<double, 3>{} ? std::max(d, 4) : d;
}

}  // namespace

Vec3 valueOf(const Document& doc, const PointCombination& c) {
    Vec3 s(0.0);
    for (const auto& [idx, coef] : c) s += coef * doc.points[idx];
    return s;
}

std::optional<SeamSide> seamSide(const Document& doc, const Join& join, bool sideB) {
    const uint32_t item = sideB ? join.patchB : join.patchA;
    const Edge e = sideB ? join.edgeB : join.edgeA;
    const bool reversed = sideB && join.reversed;
    SeamSide s;
    if (isTriangleEdge(e)) {
        if (item >= doc.triangles.size()) return std::nullopt;
        const TrianglePatch& t = doc.triangles[item];
        const int edge = triangleEdgeNumber(e);
        for (int k = 0; k < 4; ++k) s.edge[size_t(k)] = triPoint(t, edgeIndex(edge, reversed ? 3 - k : k));
        for (int m = 0; m < 3; ++m) {
            const int mm = reversed ? 2 - m : m;
            s.cross.push_back({{triPoint(t, innerIndex(edge, mm)), 1.0},
                               {triPoint(t, edgeIndex(edge, mm)), -0.5},
                               {triPoint(t, edgeIndex(edge, mm + 1)), -0.5}});
        }
    } else {
        if (item >= doc.patches.size()) return std::nullopt;
        const Patch& p = doc.patches[item];
        for (int k = 0; k < 4; ++k) {
            const int kk = reversed ? 3 - k : k;
            s.edge[size_t(k)] = p.idx[size_t(edgeSlot(e, kk, 0))];
            s.cross.push_back({{p.idx[size_t(edgeSlot(e, kk, 1))], 1.0}, {s.edge[size_t(k)], -1.0}});
        }
    }
    const size_t n = doc.points.size();
    for (uint32_t i : s.edge)
        if (i >= n) return std::nullopt;
    for (const auto& c : s.cross)
        for (const auto& term : c)
            if (term.first >= n) return std::nullopt;
    return s;
}

void appendTriangleJoinRows(const Document& doc, const Join& join, uint32_t ji, std::vector<solver_detail::ConstraintRow>& rows) {
    const auto a = seamSide(doc, join, false), b = seamSide(doc, join, true);
    if (!a || !b) return;
    auto push = [&](PointCombination terms) {
        solver_detail::ConstraintRow row = solver_detail::makeRow(std::move(terms), ji);
        if (!row.terms.empty()) rows.push_back(std::move(row));
    };
    for (int k = 0; k < 4; ++k)
        if (a->edge[size_t(k)] != b->edge[size_t(k)]) push({{a->edge[size_t(k)], 1.0}, {b->edge[size_t(k)], -1.0}});
    if (join.continuity != Continuity::G1) return;
    // A collapsed edge (a pole) has no tangent plane along it to hold.
    if (a->edge[0] == a->edge[1] && a->edge[1] == a->edge[2] && a->edge[2] == a->edge[3]) return;
    const int N = identityDegree(join, *a, *b);
    const auto da = alphaTerm(join, *a, N), db = elevated(b->cross, N);
    std::array<std::vector<PointCombination>, 3> shear;
    for (int i = 0; i < 3; ++i)
        if (join.shear[size_t(i)] != 0.0) shear[size_t(i)] = elevated(shearTerm(*a, i), N);
    for (int l = 0; l <= N; ++l) {
        PointCombination terms = db[size_t(l)];
        terms.insert(terms.end(), da[size_t(l)].begin(), da[size_t(l)].end());
        for (int i = 0; i < 3; ++i)
            if (!shear[size_t(i)].empty())
                for (const auto& [idx, c] : shear[size_t(i)][size_t(l)]) terms.emplace_back(idx, -join.shear[size_t(i)] * c);
        push(std::move(terms));
    }
}

std::optional<ShearFit> fitTriangleSeam(const Document& doc, const Join& join) {
    const auto a = seamSide(doc, join, false), b = seamSide(doc, join, true);
    if (!a || !b) return std::nullopt;
    // At each end of the seam the identity involves that end's values alone, fixed by the sides'
    // boundaries and corners: D_B + α·D_A = β·c' there, solved exactly in the plane (α0, s0 at
    // t = 0; α1, s2 at t = 1). The middle coefficient s1 by least squares over the inner rows.
    const auto endValue = [&](const std::vector<PointCombination>& c, bool end) { return valueOf(doc, end ? c.back() : c.front()); };
    std::array<double, 2> alphaAt{}, betaAt{};
    for (const bool end : {false, true}) {
        const Vec3 dA = endValue(a->cross, end), dB = endValue(b->cross, end);
        const Vec3 c = end ? doc.points[a->edge[3]] - doc.points[a->edge[2]] : doc.points[a->edge[1]] - doc.points[a->edge[0]];
        Eigen::Matrix<double, 3, 2> M;
        Eigen::Vector3d rhs;
        for (int k = 0; k < 3; ++k) M(k, 0) = dA[k], M(k, 1) = -c[k], rhs(k) = -dB[k];
        const Eigen::ColPivHouseholderQR<Eigen::Matrix<double, 3, 2>> qr(M);
        if (qr.rank() < 2) return std::nullopt;
        const Eigen::Vector2d x = qr.solve(rhs);
        alphaAt[end ? 1 : 0] = x(0), betaAt[end ? 1 : 0] = x(1);
    }
    Join trial = join;
    trial.alpha = alphaAt[0];
    trial.alphaEnd = std::abs(alphaAt[1] - alphaAt[0]) <= 1e-12 * std::abs(alphaAt[0]) ? 0.0 : alphaAt[1];
    trial.shear = {betaAt[0], 0.0, betaAt[1]};
    // Rows l = 1..3 at degree 4: residual r_l + s1·S1_l = 0 with r the identity's value at s1 = 0.
    const auto da = alphaTerm(trial, *a, 4), db = elevated(b->cross, 4);
    std::array<std::vector<PointCombination>, 3> shear;
    for (int i = 0; i < 3; ++i) shear[size_t(i)] = shearTerm(*a, i);
    double num = 0.0, den = 0.0;
    for (int l = 1; l <= 3; ++l) {
        const Vec3 r = valueOf(doc, db[size_t(l)]) + valueOf(doc, da[size_t(l)]) - betaAt[0] * valueOf(doc, shear[0][size_t(l)]) -
                       betaAt[1] * valueOf(doc, shear[2][size_t(l)]);
        const Vec3 S = valueOf(doc, shear[1][size_t(l)]);
        num += glm::dot(r, S), den += glm::dot(S, S);
    }
    if (!(den > 0.0)) return std::nullopt;
    ShearFit fit;
    fit.alpha = trial.alpha;
    fit.alphaEnd = trial.alphaEnd;
    fit.shear = {betaAt[0], num / den, betaAt[1]};
    // Coefficients that vanish to rounding are dropped, so a seam that needs no lean keeps its
    // lower-degree rows.
    const double scale = std::max(1.0, std::abs(fit.alpha));
    for (double& v : fit.shear)
        if (std::abs(v) < 1e-12 * scale) v = 0.0;
    return fit;
}

SeamPoint measureTriangleSeam(const Document& doc, const Join& join, double t) {
    SeamPoint s;
    const auto a = seamSide(doc, join, false), b = seamSide(doc, join, true);
    if (!a || !b) return s;
    s.a = evaluateEdge(doc, a->edge, t);
    s.b = evaluateEdge(doc, b->edge, t);
    std::vector<PointCombination> tangent;
    for (int j = 0; j < 3; ++j) tangent.push_back({{a->edge[size_t(j + 1)], 1.0}, {a->edge[size_t(j)], -1.0}});
    const Vec3 c = evaluate(doc, tangent, t);
    const Vec3 na = glm::cross(c, -evaluate(doc, a->cross, t)), nb = glm::cross(c, evaluate(doc, b->cross, t));
    const double la = glm::length(na), lb = glm::length(nb), lc = glm::length(c);
    const double floor = 1e-12 * lc * lc;
    s.planes = la > floor && lb > floor;
    if (s.planes) s.na = na / la, s.nb = nb / lb;
    return s;
}

}  // namespace solve
}  // namespace pw

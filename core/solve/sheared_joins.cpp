#include "core/solve/sheared_joins.hpp"

#include <cmath>

#include <Eigen/Dense>

#include "core/solve/solver_constraints.hpp"

namespace pw {
inline namespace solve {

double shearWeight(int i, int j) {
    static constexpr double kC2[3] = {1, 2, 1}, kC4[5] = {1, 4, 6, 4, 1};
    return kC2[i] * kC2[j] / kC4[i + j];
}

double elevationWeight(int l, int k) {
    if (k == l - 1) return l / 4.0;
    if (k == l) return 1.0 - l / 4.0;
    return 0.0;
}

double alphaWeight(int l, int k, int end) {
    if (end == 0) return k == l && l <= 3 ? (4.0 - l) / 4.0 : 0.0;  // (1−t)·B³_k = (4−k)/4 B⁴_k
    return k == l - 1 ? l / 4.0 : 0.0;                              // t·B³_k = (k+1)/4 B⁴_(k+1)
}

std::array<double, 5> fittedWeights(const Join& join) {
    // B⁴₂(t) = 6 t²(1−t)²: its blossom at (x1..x4) sums x_i x_j (1−x_k)(1−x_l) over the six ways
    // of choosing i, j; coefficient l on [t0, t1] is the blossom at t0 (4 − l times) and t1 (l times).
    const auto [t0, t1] = join.fittedSpan;
    std::array<double, 5> w{};
    for (int l = 0; l <= 4; ++l) {
        double x[4];
        for (int i = 0; i < 4; ++i) x[i] = i < 4 - l ? t0 : t1;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                double term = x[i] * x[j];
                for (int k = 0; k < 4; ++k)
                    if (k != i && k != j) term *= 1.0 - x[k];
                w[size_t(l)] += term;
            }
    }
    return w;
}

std::vector<std::array<double, 5>> heldCoefficients(const Join& join) {
    std::vector<std::array<double, 5>> letGo, held;
    if (join.fitted) letGo = {{0, 0, 1, 0, 0}, fittedWeights(join)};
    auto dot = [](const std::array<double, 5>& a, const std::array<double, 5>& b) {
        double d = 0.0;
        for (size_t l = 0; l < 5; ++l) d += a[l] * b[l];
        return d;
    };
    // Gram–Schmidt: what is let go first (an orthonormal basis of it), then the unit coefficients
    // in order, each less its parts along everything before; those that remain are held.
    std::vector<std::array<double, 5>> basis;
    auto add = [&](std::array<double, 5> v) {
        const double size = std::sqrt(dot(v, v));  // (a short part's term is small: judged relative to it)
        for (const auto& b : basis) {
            const double d = dot(v, b);
            for (size_t l = 0; l < 5; ++l) v[l] -= d * b[l];
        }
        const double norm = std::sqrt(dot(v, v));
        if (norm <= 1e-9 * size) return false;
        for (double& x : v) x /= norm;
        basis.push_back(v);
        return true;
    };
    for (const auto& v : letGo) add(v);
    for (size_t l = 0; l < 5; ++l) {
        std::array<double, 5> unit{};
        unit[l] = 1.0;
        if (add(unit)) held.push_back(basis.back());
    }
    return held;
}

Join reversedAlongEdge(const Join& join) {
    Join out = join;
    if (join.alphaEnd != 0.0) out.alpha = join.alphaEnd, out.alphaEnd = join.alpha;
    out.shear = {-join.shear[2], -join.shear[1], -join.shear[0]};
    for (double& s : out.shear) s = s == 0.0 ? 0.0 : s;  // no −0 in files
    out.fittedSpan = {1.0 - join.fittedSpan[1], 1.0 - join.fittedSpan[0]};
    return out;
}

Join restrictedJoin(const Join& join, double from, double to) {
    Join out = join;
    const double s0 = join.fittedSpan[0], s1 = join.fittedSpan[1];
    out.fittedSpan = {s0 + from * (s1 - s0), s0 + to * (s1 - s0)};
    const double a0 = join.alpha, a1 = endAlpha(join);
    out.alpha = a0 + from * (a1 - a0);
    out.alphaEnd = a0 + to * (a1 - a0);
    // The quadratic's Bernstein coefficients on [from, to] (blossoms), over the part's length.
    const auto& s = join.shear;
    auto blossom = [&](double x, double y) { return (1 - x) * (1 - y) * s[0] + ((1 - x) * y + x * (1 - y)) * s[1] + x * y * s[2]; };
    const double len = to - from;
    out.shear = {blossom(from, from) / len, blossom(from, to) / len, blossom(to, to) / len};
    return out;
}

std::optional<ShearFit> fitShear(const Document& doc, const Join& join) {
    solver_detail::JoinPoints jp;
    if (!solver_detail::joinPoints(doc, join, jp) || !solver_detail::joinPointsInPool(jp, doc.points.size())) return std::nullopt;
    const auto& P = doc.points;
    // Row l: E_l − α0 F0_l − α1 F1_l − Σ_i s_i W_li = 0 with E = elevated (B1 − A0) and F the
    // products of (1−t) and t with (A0 − A1): unknowns α0, α1 (when α varies), s0, s1, s2.
    const bool varying = join.alphaEnd != 0.0;
    const int unknowns = varying ? 5 : 4, shearColumn = varying ? 2 : 1;
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(15, unknowns);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(15);
    for (int l = 0; l <= 4; ++l)
        for (int c = 0; c < 3; ++c) {
            const int r = l * 3 + c;
            for (int k = 0; k < 4; ++k) {
                const double w = elevationWeight(l, k);
                if (w == 0.0) continue;
                rhs(r) += w * (P[jp.b1[k]][c] - P[jp.a0[k]][c]);
                const double f = P[jp.a0[k]][c] - P[jp.a1[k]][c];
                if (varying) {
                    M(r, 0) += alphaWeight(l, k, 0) * f;
                    M(r, 1) += alphaWeight(l, k, 1) * f;
                } else {
                    M(r, 0) += w * f;
                }
            }
            for (int i = 0; i < 3; ++i) {
                const int j = l - i;
                if (j < 0 || j > 2) continue;
                M(r, shearColumn + i) += shearWeight(i, j) * (P[jp.a0[j + 1]][c] - P[jp.a0[j]][c]);
            }
        }
    if (join.fitted) {  // only the combinations the solver holds
        const auto held = heldCoefficients(join);
        Eigen::MatrixXd M2 = Eigen::MatrixXd::Zero(15, unknowns);
        Eigen::VectorXd rhs2 = Eigen::VectorXd::Zero(15);
        for (size_t h = 0; h < held.size(); ++h)
            for (int l = 0; l <= 4; ++l)
                for (int c = 0; c < 3; ++c) {
                    M2.row(int(h) * 3 + c) += held[h][size_t(l)] * M.row(l * 3 + c);
                    rhs2(int(h) * 3 + c) += held[h][size_t(l)] * rhs(l * 3 + c);
                }
        M = M2, rhs = rhs2;
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(M);
    if (qr.rank() < unknowns) return std::nullopt;
    const Eigen::VectorXd x = qr.solve(rhs);
    ShearFit fit;
    fit.alpha = x(0);
    if (varying) fit.alphaEnd = x(1);
    for (int i = 0; i < 3; ++i) fit.shear[size_t(i)] = x(shearColumn + i);
    return fit;
}

}  // namespace solve
}  // namespace pw

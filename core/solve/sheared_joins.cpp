#include "core/solve/sheared_joins.hpp"

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

Join restrictedJoin(const Join& join, double from, double to) {
    Join out = join;
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
            if (join.fitted && l == 2) continue;  // a fitted join lets its middle coefficient go
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

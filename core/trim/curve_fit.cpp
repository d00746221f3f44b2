#include "core/trim/curve_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace pw {
inline namespace trim {

namespace {

// Uniform cubic B-spline basis on one span, t in [0, 1]: the weights of its four control points.
std::array<double, 4> uniformBasis(double t) {
    const double s = 1.0 - t;
    return {s * s * s / 6.0, (3 * t * t * t - 6 * t * t + 4) / 6.0, (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6.0, t * t * t / 6.0};
}

// Clamped cubic B-spline on knots 0,0,0,0,1,…,n−1,n,n,n,n: the n + 3 basis values at x (Cox–de Boor).
std::vector<double> clampedBasis(double x, size_t n) {
    std::vector<double> knots;
    for (int k = 0; k < 3; ++k) knots.push_back(0.0);
    for (size_t k = 0; k <= n; ++k) knots.push_back(double(k));
    for (int k = 0; k < 3; ++k) knots.push_back(double(n));
    const size_t m = knots.size();  // n + 7
    x = std::clamp(x, 0.0, double(n));
    std::vector<double> N(m - 1, 0.0);
    for (size_t i = 0; i + 1 < m; ++i) {
        const bool last = x >= double(n) && knots[i + 1] == double(n) && knots[i] < knots[i + 1];
        N[i] = ((knots[i] <= x && x < knots[i + 1]) || last) ? 1.0 : 0.0;
    }
    for (size_t p = 1; p <= 3; ++p)
        for (size_t i = 0; i + p + 1 < m; ++i) {
            double v = 0.0;
            if (knots[i + p] > knots[i]) v += (x - knots[i]) / (knots[i + p] - knots[i]) * N[i];
            if (knots[i + p + 1] > knots[i + 1]) v += (knots[i + p + 1] - x) / (knots[i + p + 1] - knots[i + 1]) * N[i + 1];
            N[i] = v;
        }
    N.resize(n + 3);
    return N;
}

}  // namespace

CurveFit fitCubicChain(const std::vector<Vec3>& samples, bool closed, size_t n) {
    CurveFit out;
    const size_t m = samples.size();
    if (m < 2 || n < 1) return out;
    // Chord-length parameters over [0, n].
    std::vector<double> len(m + (closed ? 1 : 0), 0.0);
    for (size_t i = 1; i < len.size(); ++i) len[i] = len[i - 1] + glm::length(samples[i % m] - samples[i - 1]);
    const double total = std::max(len.back(), 1e-300);
    std::vector<double> par(m);
    for (size_t i = 0; i < m; ++i) par[i] = len[i] / total * double(n);

    const size_t nc = closed ? n : n + 3;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(Eigen::Index(m), Eigen::Index(nc));
    for (size_t i = 0; i < m; ++i) {
        if (closed) {
            const size_t span = std::min(size_t(par[i]), n - 1);
            const auto w = uniformBasis(par[i] - double(span));
            for (size_t k = 0; k < 4; ++k) A(Eigen::Index(i), Eigen::Index((span + k) % n)) += w[k];
        } else {
            const std::vector<double> w = clampedBasis(par[i], n);
            for (size_t k = 0; k < nc; ++k) A(Eigen::Index(i), Eigen::Index(k)) = w[k];
        }
    }
    Eigen::MatrixXd B(Eigen::Index(m), 3);
    for (size_t i = 0; i < m; ++i) B.row(Eigen::Index(i)) << samples[i].x, samples[i].y, samples[i].z;
    Eigen::MatrixXd C;
    if (closed) {
        // A little smoothing keeps the system well posed where samples are sparse.
        Eigen::MatrixXd AtA = A.transpose() * A + 1e-10 * Eigen::MatrixXd::Identity(Eigen::Index(nc), Eigen::Index(nc));
        C = AtA.ldlt().solve(A.transpose() * B);
    } else {
        // The ends are the first and last samples exactly; the inner control points by least squares.
        const Eigen::Index inner = Eigen::Index(nc) - 2;
        Eigen::MatrixXd rhs = B - A.col(0) * B.row(0) - A.col(Eigen::Index(nc) - 1) * B.row(Eigen::Index(m) - 1);
        Eigen::MatrixXd Ai = A.middleCols(1, inner);
        Eigen::MatrixXd AtA = Ai.transpose() * Ai + 1e-10 * Eigen::MatrixXd::Identity(inner, inner);
        Eigen::MatrixXd Ci = AtA.ldlt().solve(Ai.transpose() * rhs);
        C = Eigen::MatrixXd(Eigen::Index(nc), 3);
        C.row(0) = B.row(0);
        C.middleRows(1, inner) = Ci;
        C.row(Eigen::Index(nc) - 1) = B.row(Eigen::Index(m) - 1);
    }
    auto evalAt = [&](double x) {
        Vec3 p(0.0);
        if (closed) {
            const size_t span = std::min(size_t(std::max(x, 0.0)), n - 1);
            const auto w = uniformBasis(x - double(span));
            for (size_t k = 0; k < 4; ++k) {
                const Eigen::Index r = Eigen::Index((span + k) % n);
                p += w[k] * Vec3(C(r, 0), C(r, 1), C(r, 2));
            }
        } else {
            const std::vector<double> w = clampedBasis(x, n);
            for (size_t k = 0; k < nc; ++k) p += w[k] * Vec3(C(Eigen::Index(k), 0), C(Eigen::Index(k), 1), C(Eigen::Index(k), 2));
        }
        return p;
    };
    // Each span's cubic as Bézier points: from its values at 0, 1/3, 2/3, 1 (exact for a cubic).
    std::vector<Vec3> bez;
    for (size_t s = 0; s < n; ++s) {
        const Vec3 p0 = evalAt(double(s)), p1 = evalAt(s + 1.0 / 3.0), p2 = evalAt(s + 2.0 / 3.0), p3 = evalAt(double(s + 1));
        // Solve the Bernstein system for the inner two: p(1/3) = (8 b0 + 12 b1 + 6 b2 + b3) / 27, p(2/3) = (b0 + 6 b1 + 12 b2 + 8 b3) / 27.
        const Vec3 r1 = 27.0 * p1 - 8.0 * p0 - p3, r2 = 27.0 * p2 - p0 - 8.0 * p3;
        const Vec3 b1 = (12.0 * r1 - 6.0 * r2) / 108.0, b2 = (12.0 * r2 - 6.0 * r1) / 108.0;
        if (s == 0) bez.push_back(p0);
        bez.push_back(b1);
        bez.push_back(b2);
        bez.push_back(p3);
    }
    if (closed) bez.back() = bez.front();
    out.bezier = std::move(bez);
    for (size_t i = 0; i < m; ++i) out.deviation = std::max(out.deviation, glm::length(evalAt(par[i]) - samples[i]));
    return out;
}

CurveFit fitCubicChainWithin(const std::vector<Vec3>& samples, bool closed, double tol, size_t minSegments, size_t maxSegments) {
    CurveFit best;
    for (size_t n = std::max<size_t>(minSegments, closed ? 3 : 1); n <= maxSegments; n = n < 8 ? n + 1 : n + n / 4) {
        if (samples.size() < (closed ? n : n + 3)) break;
        best = fitCubicChain(samples, closed, n);
        if (best.deviation <= tol) break;
    }
    return best;
}

}  // namespace trim
}  // namespace pw

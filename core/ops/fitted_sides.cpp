#include "core/ops/fitted_sides.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/solve/continuity_report.hpp"
#include "core/solve/sheared_joins.hpp"

namespace pw {
inline namespace ops {

bool ratiosDisagree(const std::array<double, 2>& r) { return std::abs(r[0] - r[1]) > 1e-6 * std::max({1.0, r[0], r[1]}); }

// The sides, as numbered when given, whose two ends ask for different ratios; "" when none does.
std::string ratioMismatch(const std::vector<std::optional<std::array<double, 2>>>& ratios, const std::vector<size_t>& given,
                          const std::vector<HoleSide>& sides) {
    const size_t n = ratios.size();
    auto fmt = [](double x) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.4g", x);
        return std::string(buf);
    };
    std::string out;
    for (size_t k = 0; k < n; ++k) {
        if (!ratios[k] || !ratiosDisagree(*ratios[k])) continue;
        const size_t km = (k + n - 1) % n, kp = (k + 1) % n;
        std::string label;
        for (const auto& [p, e] : sides[given[k]].edges)
            label += (label.empty() ? "" : "+") + std::to_string(p) + ":" + std::string(edgeName(e));
        out += std::string(out.empty() ? "" : "; ") + "side " + std::to_string(given[k] + 1) + " (" + label + ") needs α " +
               fmt((*ratios[k])[0]) + " at its corner with side " + std::to_string(given[km] + 1) + " and " + fmt((*ratios[k])[1]) +
               " at its corner with side " + std::to_string(given[kp] + 1);
    }
    return out;
}

std::vector<FittedSide> fitSides(const std::vector<std::array<double, 2>>& ratios) {
    const size_t n = ratios.size();
    std::vector<FittedSide> s(n);
    for (size_t k = 0; k < n; ++k) s[k] = {ratios[k][0], 0.5 * (ratios[k][0] + ratios[k][1]), ratios[k][1]};
    for (size_t k = 0; k < n; ++k) {
        const size_t km = (k + n - 1) % n, kp = (k + 1) % n;
        // β′ at each hole corner: α′/α of the fill's other seam there, each walked from the corner.
        const double g0 = (s[km].mid - s[km].end) / s[km].end, g1 = (s[kp].mid - s[kp].start) / s[kp].start;
        // At the middle the halves' β are b and −b (their walks run opposite ways) and their slopes,
        // 2b − g0 and −2b − g1, must agree.
        const double b = 0.25 * (g0 - g1);
        s[k].shearFirst = {0.0, 0.5 * g0, b};
        s[k].shearSecond = {0.0, 0.5 * g1, -b};
    }
    return s;
}

std::array<Vec3, 4> fittedRow(const std::array<Vec3, 4>& edge, const std::array<Vec3, 4>& row, double a0, double a1,
                              const std::array<double, 3>& shear) {
    // The right side's degree-4 Bernstein coefficients r_l, then the fill's differences f_k from the
    // elevation rows 0 (f0), 1 (f0/4 + 3f1/4), 3 (3f2/4 + f3/4) and 4 (f3).
    std::array<Vec3, 5> r;
    for (int l = 0; l <= 4; ++l) {
        Vec3 v(0.0);
        for (int k = 0; k < 4; ++k) v += (a0 * alphaWeight(l, k, 0) + a1 * alphaWeight(l, k, 1)) * (edge[size_t(k)] - row[size_t(k)]);
        for (int i = 0; i < 3; ++i) {
            const int j = l - i;
            if (j >= 0 && j <= 2) v += shear[size_t(i)] * shearWeight(i, j) * (edge[size_t(j + 1)] - edge[size_t(j)]);
        }
        r[size_t(l)] = v;
    }
    std::array<Vec3, 4> f;
    f[0] = r[0];
    f[3] = r[4];
    f[1] = (r[1] - 0.25 * f[0]) / 0.75;
    f[2] = (r[3] - 0.25 * f[3]) / 0.75;
    return f;
}

Join fittedJoin(const Document& doc, uint32_t patch, Edge edge, bool walkedReversed, uint32_t fill, Edge fillEdge, double a0, double a1,
                const std::array<double, 3>& shear) {
    Join jn;
    jn.patchA = patch;
    jn.edgeA = edge;
    jn.patchB = fill;
    jn.edgeB = fillEdge;
    jn.continuity = Continuity::G1;
    jn.fitted = true;
    // The join's parameter runs along A's points 0..3; β(t)·c′(t) changes sign when it is reversed.
    jn.alpha = walkedReversed ? a1 : a0;
    jn.alphaEnd = walkedReversed ? a0 : a1;
    jn.shear = walkedReversed ? std::array<double, 3>{-shear[2], -shear[1], -shear[0]} : shear;
    const Vec3 a0p = doc.points[doc.patches[patch].idx[size_t(edgeSlot(edge, 0))]];
    const Vec3 a3p = doc.points[doc.patches[patch].idx[size_t(edgeSlot(edge, 3))]];
    const Vec3 b0p = doc.points[doc.patches[fill].idx[size_t(edgeSlot(fillEdge, 0))]];
    jn.reversed = glm::length(b0p - a3p) < glm::length(b0p - a0p);
    return jn;
}

namespace {

std::vector<size_t> fittedOf(const Document& doc, const std::vector<size_t>& only) {
    std::vector<size_t> fitted;
    if (only.empty()) {
        for (size_t j = 0; j < doc.joins.size(); ++j)
            if (doc.joins[j].fitted) fitted.push_back(j);
    } else {
        for (size_t j : only)
            if (j < doc.joins.size() && doc.joins[j].fitted) fitted.push_back(j);
    }
    return fitted;
}

}  // namespace

double worstFittedAngle(const Document& doc, const std::vector<size_t>& only) {
    const std::vector<size_t> fitted = fittedOf(doc, only);
    double worst = 0.0;
    if (!fitted.empty())
        for (const JoinContinuity& c : continuityReport(doc, 32, fitted)) worst = std::max(worst, c.normalAngleDeg);
    return worst;
}

std::string fittedJoinsOutOfTolerance(const Document& doc, const std::vector<size_t>& only) {
    const std::vector<size_t> fitted = fittedOf(doc, only);
    if (fitted.empty()) return "";
    std::string out;
    for (const JoinContinuity& c : continuityReport(doc, 32, fitted)) {
        if (c.normalAngleDeg <= kFittedJoinDegrees) continue;
        const Join& jn = doc.joins[c.join];
        char buf[160];
        std::snprintf(buf, sizeof buf, "join %zu (patch %u %s – patch %u %s, fitted G1) at %.3g°", c.join, jn.patchA,
                      std::string(edgeName(jn.edgeA)).c_str(), jn.patchB, std::string(edgeName(jn.edgeB)).c_str(), c.normalAngleDeg);
        out += (out.empty() ? "" : "; ") + std::string(buf);
    }
    return out;
}

std::string fittedJoinsWorsened(const Document& before, const Document& after, const std::vector<size_t>& only, double wasWorst) {
    const std::string out = fittedJoinsOutOfTolerance(after, only);
    if (out.empty()) return "";
    const double was = wasWorst >= 0.0 ? wasWorst : worstFittedAngle(before, only);
    if (was > kFittedJoinDegrees && worstFittedAngle(after, only) <= was * (1.0 + 1e-9)) return "";
    return out;
}

}  // namespace ops
}  // namespace pw

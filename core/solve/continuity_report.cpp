// Measured continuity along each join: the seam sampled on both sides (positions, normals and the
// normal curvature across the seam) and the control-point residuals of the join's rows.
#include "core/solve/continuity_report.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/eval/rational_eval.hpp"
#include "core/gpu/curvature_math.h"
#include "core/solve/sheared_joins.hpp"
#include "core/solve/solver_constraints.hpp"
#include "core/solve/triangle_seams.hpp"

namespace pw {
inline namespace solve {

namespace {

// (u, v) of the point at parameter t along edge e (t increases with k, like edgeSlot).
void edgeParam(Edge e, double t, double& u, double& v) {
    switch (e) {
        case Edge::U0:
            u = 0, v = t;
            return;
        case Edge::U1:
            u = 1, v = t;
            return;
        case Edge::V0:
            u = t, v = 0;
            return;
        case Edge::V1:
            u = t, v = 1;
            return;
        case Edge::T0:
        case Edge::T1:
        case Edge::T2:  // triangle seams are measured by measureTriangleSeam
            u = v = 0;
            return;
    }
}

// The patch normal du × dv expressed in the edge's frame (outward direction O, along-edge
// direction T) is sign·(O × T); see Seam for how it decides orientation.
double edgeSign(Edge e) { return (e == Edge::U1 || e == Edge::V0) ? 1.0 : -1.0; }

bool usableUnit(const Vec3& n) {
    const double l = glm::length(n);
    return std::isfinite(l) && std::abs(l - 1.0) < 1e-6;
}

// Normal curvature of one side in the surface direction x (a unit tangent-plane vector): x is
// written as a·du + b·dv through the first fundamental form.
double curvatureAlong(const SurfaceJet& s, const Vec3& x) {
    const double E = glm::dot(s.du, s.du), F = glm::dot(s.du, s.dv), G = glm::dot(s.dv, s.dv);
    const double det = E * G - F * F;
    if (!(det > 1e-24 * E * G) || !(det > 0)) return 0.0;
    const double xu = glm::dot(s.du, x), xv = glm::dot(s.dv, x);
    const double a = (G * xu - F * xv) / det, b = (E * xv - F * xu) / det;
    return gpu::normalCurvature<double>(s.du, s.dv, s.duu, s.duv, s.dvv, s.n, a, b);
}

// One join's two sides, sampled together. Along the seam B's parameter runs backwards when
// reversed; its normal agrees in orientation with A's when the outward directions are opposite
// and sign(eA)·sign(eB)·(reversed ? −1 : 1) = −1, otherwise B's normal is flipped for the
// comparison (a consistently oriented surface needs no flip).
struct Seam {
    const Join& join;
    const Patch &A, &B;
    WindowNet netA, netB;
    double flip;

    Seam(const Document& doc, const Join& j)
        : join(j),
          A(doc.patches[j.patchA]),
          B(doc.patches[j.patchB]),
          netA(gatherWindow(doc, A.idx)),
          netB(gatherWindow(doc, B.idx)),
          flip(edgeSign(j.edgeA) * edgeSign(j.edgeB) * (j.reversed ? -1.0 : 1.0) > 0 ? -1.0 : 1.0) {}

    struct Sample {
        SurfaceJet a, b;  // b's normal already flipped into A's orientation
        bool normals = false;
        double kappaA = 0, kappaB = 0;
    };
    Sample at(int s, int samples) const {
        const double t = static_cast<double>(s) / samples;
        const double tb = join.reversed ? static_cast<double>(samples - s) / samples : t;
        double ua = 0, va = 0, ub = 0, vb = 0;
        edgeParam(join.edgeA, t, ua, va);
        edgeParam(join.edgeB, tb, ub, vb);
        Sample out{evaluateWindowJet(netA, A.basis, A.tension, ua, va), evaluateWindowJet(netB, B.basis, B.tension, ub, vb)};
        out.b.n *= flip;
        out.normals = usableUnit(out.a.n) && usableUnit(out.b.n);
        if (!out.normals) return out;
        // Across the seam: perpendicular to the edge's tangent, in A's tangent plane.
        const bool alongV = join.edgeA == Edge::U0 || join.edgeA == Edge::U1;
        const Vec3 tangent = alongV ? out.a.dv : out.a.du;
        Vec3 across = glm::cross(out.a.n, tangent);
        const double l = glm::length(across);
        if (!(l > 0)) return out;
        across /= l;
        out.kappaA = curvatureAlong(out.a, across);
        out.kappaB = curvatureAlong(out.b, across);
        return out;
    }
};

bool validJoin(const Document& doc, const Join& join, solver_detail::JoinPoints& jp) {
    const size_t n = doc.points.size();
    bool valid = solver_detail::joinPoints(doc, join, jp) && solver_detail::joinPointsInPool(jp, n);
    for (uint32_t p : {join.patchA, join.patchB})
        for (int s = 0; valid && s < 16; ++s) valid = doc.patches[p].idx[size_t(s)] < n;
    return valid;
}

double angleDeg(const Vec3& a, const Vec3& b) {
    // acos is ill-conditioned near 1: atan2 of |cross| and dot.
    return std::atan2(glm::length(glm::cross(a, b)), std::clamp(glm::dot(a, b), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// A join with a triangle side (C0 or G1): its rows' residuals and the seam's gap and tangent
// planes (core/solve/triangle_seams.hpp); no curvature is held across it.
JoinContinuity triangleSeamContinuity(const Document& doc, const Join& join, size_t j, int samples) {
    JoinContinuity jc;
    jc.join = j;
    std::vector<solver_detail::ConstraintRow> rows;
    appendTriangleJoinRows(doc, join, 0, rows);
    for (const auto& row : rows) {
        Vec3 r(0.0);
        for (const auto& [idx, coef] : row.terms) r += coef * doc.points[idx];
        jc.c1Residual = std::max(jc.c1Residual, glm::length(r));
    }
    for (int s = 0; s <= samples; ++s) {
        const SeamPoint q = measureTriangleSeam(doc, join, double(s) / samples);
        jc.c0Gap = std::max(jc.c0Gap, glm::length(q.a - q.b));
        if (q.planes) jc.normalAngleDeg = std::max(jc.normalAngleDeg, angleDeg(q.na, q.nb));
    }
    return jc;
}

}  // namespace

uint8_t toleranceFailures(const JoinContinuity& c, Continuity continuity, const ContinuityTolerances& tol) {
    uint8_t f = kWithinTolerance;
    if (!(c.c0Gap <= tol.position)) f |= kPositionOut;
    if (holdsTangent(continuity) && !(c.normalAngleDeg <= tol.angleDeg)) f |= kAngleOut;
    if (holdsCurvature(continuity) && !(c.curvatureDeviationPct <= tol.curvaturePct)) f |= kCurvatureOut;
    return f;
}

std::vector<JoinContinuity> continuityReport(const Document& doc, int samples, const std::vector<size_t>& only) {
    samples = std::max(samples, 1);
    std::vector<JoinContinuity> out;
    const double flatCurvature = 1e-3 / std::max(modelSize(doc), 1e-300);
    const auto& P = doc.points;
    auto report = [&](size_t j) {
        const Join& join = doc.joins[j];
        JoinContinuity jc;
        jc.join = j;
        if (joinHasTriangle(join)) {
            out.push_back(triangleSeamContinuity(doc, join, j, samples));
            return;
        }
        solver_detail::JoinPoints jp;
        if (!validJoin(doc, join, jp)) {
            out.push_back(jc);
            return;
        }
        // Control-point residuals: |B1k − B0k − α·(A0k − A1k)| and the β-constraint's.
        const double a2 = join.alpha * join.alpha, h = 0.5 * join.beta2;
        if (hasShear(join)) {  // a leaning seam: the residuals of its own (degree-4) rows
            std::vector<solver_detail::ConstraintRow> tangentRows;
            solver_detail::appendTangentRows(join, jp, 0, tangentRows);
            for (const auto& row : tangentRows) {
                Vec3 r(0.0);
                for (const auto& [idx, coef] : row.terms) r += coef * P[idx];
                jc.c1Residual = std::max(jc.c1Residual, glm::length(r));
            }
        }
        for (int k = 0; k < 4; ++k) {
            const Vec3 t = P[jp.a0[k]] - P[jp.a1[k]];
            if (!hasShear(join)) jc.c1Residual = std::max(jc.c1Residual, glm::length((P[jp.b1[k]] - P[jp.b0[k]]) - join.alpha * t));
            if (!holdsCurvature(join.continuity)) continue;
            const Vec3 r2 = (P[jp.b2[k]] - 2.0 * P[jp.b1[k]] + P[jp.b0[k]]) - a2 * (P[jp.a2[k]] - 2.0 * P[jp.a1[k]] + P[jp.a0[k]]) - h * t;
            jc.c2Residual = std::max(jc.c2Residual, glm::length(r2));
        }
        const Seam seam(doc, join);
        for (int s = 0; s <= samples; ++s) {
            const Seam::Sample q = seam.at(s, samples);
            jc.c0Gap = std::max(jc.c0Gap, glm::length(q.a.p - q.b.p));
            if (!q.normals) continue;  // no meaningful normal here
            jc.normalAngleDeg = std::max(jc.normalAngleDeg, angleDeg(q.a.n, q.b.n));
            const double big = std::max(std::abs(q.kappaA), std::abs(q.kappaB));
            jc.maxCurvature = std::max(jc.maxCurvature, big);
            jc.curvatureDeviationPct =
                std::max(jc.curvatureDeviationPct, 100.0 * std::abs(q.kappaA - q.kappaB) / std::max(big, flatCurvature));
        }
        out.push_back(jc);
    };
    if (only.empty()) {
        out.reserve(doc.joins.size());
        for (size_t j = 0; j < doc.joins.size(); ++j) report(j);
    } else {
        out.reserve(only.size());
        for (size_t j : only)
            if (j < doc.joins.size()) report(j);
    }
    return out;
}

}  // namespace solve
}  // namespace pw

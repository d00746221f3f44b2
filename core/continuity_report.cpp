// Measured continuity along each join: the seam sampled on both sides (positions and normals) and
// the control-point C1 residual.
#include "core/continuity_report.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/patch_eval.hpp"
#include "core/solver_constraints.hpp"

namespace pw {

namespace {

// (u, v) of the point at parameter t along edge e (t increases with k, like edgeSlot).
void edgeParam(Edge e, double t, double& u, double& v) {
    switch (e) {
        case Edge::U0: u = 0, v = t; return;
        case Edge::U1: u = 1, v = t; return;
        case Edge::V0: u = t, v = 0; return;
        case Edge::V1: u = t, v = 1; return;
    }
}

// The patch normal du × dv expressed in the edge's frame (outward direction O, along-edge
// direction T) is sign·(O × T); see continuityReport for how it decides orientation.
double edgeSign(Edge e) { return (e == Edge::U1 || e == Edge::V0) ? 1.0 : -1.0; }

bool usableUnit(const Vec3& n) {
    const double l = glm::length(n);
    return std::isfinite(l) && std::abs(l - 1.0) < 1e-6;
}

}  // namespace

std::vector<JoinContinuity> continuityReport(const Document& doc, int samples) {
    samples = std::max(samples, 1);
    std::vector<JoinContinuity> out;
    out.reserve(doc.joins.size());
    const size_t n = doc.points.size();
    for (size_t j = 0; j < doc.joins.size(); ++j) {
        const Join& join = doc.joins[j];
        JoinContinuity jc;
        jc.join = j;
        solver_detail::JoinPoints jp;
        bool valid = solver_detail::joinPoints(doc, join, jp);
        for (int k = 0; valid && k < 4; ++k)
            valid = jp.a0[k] < n && jp.a1[k] < n && jp.b0[k] < n && jp.b1[k] < n;
        for (uint32_t p : {join.patchA, join.patchB})
            for (int s = 0; valid && s < 16; ++s) valid = doc.patches[p].idx[s] < n;
        if (!valid) {
            out.push_back(jc);
            continue;
        }

        // Control-point residual: |B1k − B0k − α·(A0k − A1k)|.
        const auto& P = doc.points;
        for (int k = 0; k < 4; ++k) {
            const Vec3 r = (P[jp.b1[k]] - P[jp.b0[k]]) - join.alpha * (P[jp.a0[k]] - P[jp.a1[k]]);
            jc.c1Residual = std::max(jc.c1Residual, glm::length(r));
        }

        // Seam samples. Along the seam B's parameter runs backwards when reversed; its normal
        // agrees in orientation with A's when the outward directions are opposite and
        // sign(eA)·sign(eB)·(reversed ? −1 : 1) = −1, otherwise B's normal is flipped for the
        // comparison (a consistently oriented surface needs no flip).
        const Patch& A = doc.patches[join.patchA];
        const Patch& B = doc.patches[join.patchB];
        const Net16 netA = gatherNet(doc, A.idx), netB = gatherNet(doc, B.idx);
        const double flip = edgeSign(join.edgeA) * edgeSign(join.edgeB) * (join.reversed ? -1.0 : 1.0) > 0 ? -1.0 : 1.0;
        for (int s = 0; s <= samples; ++s) {
            const double t = static_cast<double>(s) / samples;
            const double tb = join.reversed ? static_cast<double>(samples - s) / samples : t;
            double ua = 0, va = 0, ub = 0, vb = 0;
            edgeParam(join.edgeA, t, ua, va);
            edgeParam(join.edgeB, tb, ub, vb);
            const SurfacePoint pa = evaluateNet(netA, A.basis, A.tension, ua, va);
            const SurfacePoint pb = evaluateNet(netB, B.basis, B.tension, ub, vb);
            jc.c0Gap = std::max(jc.c0Gap, glm::length(pa.p - pb.p));
            if (!usableUnit(pa.n) || !usableUnit(pb.n)) continue;  // no meaningful normal here
            const double c = std::clamp(glm::dot(pa.n, flip * pb.n), -1.0, 1.0);
            // acos is ill-conditioned near 1: use atan2 of |cross| and dot for small angles.
            const double angle = std::atan2(glm::length(glm::cross(pa.n, flip * pb.n)), c);
            jc.normalAngleDeg = std::max(jc.normalAngleDeg, angle * 180.0 / std::numbers::pi);
        }
        out.push_back(jc);
    }
    return out;
}

}  // namespace pw

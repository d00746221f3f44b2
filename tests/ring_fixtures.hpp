// Test fixtures for issue 40's fills: rings of patches round an n-gon hole, and what a modeller
// does with them (join every seam G1 by hand, fill the hole), shared by the corner and fill tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>

#include "core/commands/command_table.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/fold_check.hpp"
#include "core/io/bpt_format.hpp"
#include "core/model/topology.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"

namespace pw::rings {

// One bicubic patch of a .bpt whose control points are at(i/3, j/3), turned (u and v swapped) so
// that its normal points along `out`.
inline std::string bptPatch(const std::function<Vec3(double, double)>& at, const Vec3& out) {
    const Vec3 n = glm::cross(at(1, 0) - at(0, 0), at(0, 1) - at(0, 0));
    const bool swap = glm::dot(n, out) < 0.0;
    std::string text = "3 3\n";
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const Vec3 p = swap ? at(j / 3.0, i / 3.0) : at(i / 3.0, j / 3.0);
            char buf[128];
            std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
            text += buf;
        }
    return text;
}

inline Vec3 bilinear(const Vec3 (&q)[4], double u, double v) {
    return (1 - u) * (1 - v) * q[0] + u * (1 - v) * q[1] + u * v * q[2] + (1 - u) * v * q[3];
}

inline Vec3 onSphere(double polar, double azimuth) {
    return Vec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
}

// A flat ring of quads round an n-gon hole of radius 1 in z = 0: per side a side patch and per
// hole corner a corner patch whose edges continue the hole's edges, so four patches (with the
// fill) meet at each hole corner along two straight lines, as at a rounded box's face corner. The
// ring is half a side wide, so that once the sides are split at their middle every tangent ratio
// round a hole corner is 1 (fill-hole refuses surroundings whose ratios disagree there).
inline Document planarRing(int n, double bend = 0.0, double widen = 1.0) {
    std::string text = std::to_string(2 * n) + "\n";
    const double a = 2 * std::numbers::pi / n, d = std::sin(std::numbers::pi / n);
    auto V = [&](int k) { return Vec3(std::cos(((k + n) % n) * a), std::sin(((k + n) % n) * a), 0); };
    auto away = [&](int k, int from) {
        return d * (k % 2 ? widen : 1.0) * glm::normalize(V(k) - V(from));
    };  // continuing edge from→k past k
    const Vec3 up(0, 0, 1);
    // Straight edges, and each inner point the parallelogram of its corner's two edge legs (so the
    // twists agree round each hole corner, as on any surface that was smooth there).
    auto quad = [&](const Vec3(&q)[4]) {
        return [q, bend](double u, double v) {
            const int i = int(std::lround(3 * u)), j = int(std::lround(3 * v));
            const int ci = i < 2 ? 0 : 3, cj = j < 2 ? 0 : 3;
            auto edge = [&](int ii, int jj) { return bilinear(q, ii / 3.0, jj / 3.0); };
            const Vec3 p = i == 0 || i == 3 || j == 0 || j == 3 ? edge(i, j) : edge(i, cj) + edge(ci, j) - edge(ci, cj);
            return p + Vec3(0, 0, bend * glm::dot(p, p));
        };
    };
    for (int k = 0; k < n; ++k) {
        const Vec3 side[4] = {V(k), V(k + 1), V(k + 1) + away(k + 1, k + 2), V(k) + away(k, k - 1)};
        text += bptPatch(quad(side), up);
        const Vec3 corner[4] = {V(k), V(k) + away(k, k - 1), V(k) + away(k, k - 1) + away(k, k + 1), V(k) + away(k, k + 1)};
        text += bptPatch(quad(corner), up);
    }
    return parseBpt(text, "ring.bpt");
}

struct Recorder final : CommandHost {
    std::string last;
    void status(const std::string& s) override { last = s; }
    void write(const Document&, const std::string&) override {}
};

inline void runCommandLine(EditSession& s, Recorder& host, const std::string& line) { makeCommandTable().run(s, host, line); }

// Every C0 seam made G1 with `join`, one after another as a modeller would; the statuses said.
inline std::string joinAllG1(EditSession& s) {
    Recorder host;
    std::string said;
    for (int guard = 0; guard < 100; ++guard) {
        const auto c0 = std::find_if(s.doc.joins.begin(), s.doc.joins.end(), [](const Join& j) { return j.continuity == Continuity::C0; });
        if (c0 == s.doc.joins.end()) break;
        host.last.clear();
        runCommandLine(s, host,
                       "join " + std::to_string(c0->patchA) + ":" + std::string(edgeName(c0->edgeA)) + " " + std::to_string(c0->patchB) +
                           ":" + std::string(edgeName(c0->edgeB)) + " G1");
        said += host.last + "\n";
    }
    return said;
}

// Worst normal angle over the seams that hold tangents, and the worst solver residual.
inline void expectG1(const Document& d, const std::string& when) {
    double worst = 0.0;
    size_t tangent = 0;
    const auto report = continuityReport(d, 32);
    for (const JoinContinuity& c : report)
        if (holdsTangent(d.joins[c.join].continuity)) worst = std::max(worst, c.normalAngleDeg), ++tangent;
    EXPECT_GT(tangent, 0u) << when;
    EXPECT_LE(worst, 0.1) << when;
    EXPECT_LE(maxConstraintResidual(d), 1e-6 * modelSize(d)) << when;
    for (uint32_t p = 0; p < d.patches.size(); ++p) EXPECT_EQ(patchShape(d, p).invertedTriangles, 0) << when << " patch " << p;
}

// The `fill-hole` arguments for planarRing(n): each side patch's edge whose ends are hole corners.
inline std::string ringHoleSides(const Document& d, int n) {
    std::string sides;
    for (int k = 0; k < n; ++k) {
        const Patch& P = d.patches[size_t(2 * k)];
        for (Edge e : {Edge::U0, Edge::V0, Edge::U1, Edge::V1}) {
            const Vec3 a = d.points[P.idx[size_t(edgeSlot(e, 0))]], b = d.points[P.idx[size_t(edgeSlot(e, 3))]];
            auto r = [](const Vec3& x) { return std::hypot(x.x, x.y); };
            if (std::abs(r(a) - 1.0) < 1e-9 && std::abs(r(b) - 1.0) < 1e-9)
                sides += " " + std::to_string(2 * k) + ":" + std::string(edgeName(e));
        }
    }
    return sides;
}

}  // namespace pw::rings

// Rational patches (issue 21): weights per pool point, evaluated as Σ N·w·P / Σ N·w. Checked
// against a naive evaluation of that quotient and finite differences; weights 1 give the
// polynomial's bits; the exact primitives lie on their quadrics to rounding (positions, normals and
// curvatures); a rational split keeps the surface; files carry weights and refuse bad ones; the
// `weight` command, its undo, and the refusal of weights on triangles.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/model_builders.hpp"
#include "core/construct/primitives.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/gpu/curvature_math.h"
#include "core/io/patchwork_format.hpp"
#include "core/model/join_detect.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/ops/split_ops.hpp"
#include "core/solve/constraint_solver.hpp"
#include "tests/support.hpp"

using namespace pw;
using namespace pw::test;

namespace {

// Σ B_i(v) B_j(u) w_ij P_ij / Σ B_i(v) B_j(u) w_ij with Bernstein polynomials written out.
Vec3 naiveRational(const Net16& p, const Weights16& w, double u, double v) {
    const auto b = [](int i, double t) {
        static const double binom[4] = {1, 3, 3, 1};
        return binom[i] * std::pow(t, i) * std::pow(1.0 - t, 3 - i);
    };
    Vec3 num{0.0};
    double den = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const double c = b(i, v) * b(j, u) * w[size_t(i * 4 + j)];
            num += c * p[size_t(i * 4 + j)];
            den += c;
        }
    return num / den;
}

WindowNet randomWindow(std::mt19937& rng) {
    std::uniform_real_distribution<double> coord(-1.0, 1.0), weight(0.3, 3.0);
    WindowNet n;
    n.weights = Weights16{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            n.points[size_t(i * 4 + j)] = Vec3(j + 0.3 * coord(rng), i + 0.3 * coord(rng), coord(rng));
            (*n.weights)[size_t(i * 4 + j)] = weight(rng);
        }
    return n;
}

double rel(const Vec3& a, const Vec3& b) { return glm::length(a - b) / std::max(1.0, glm::length(b)); }

TEST(Rational, EvaluationMatchesTheQuotientAndItsDerivatives) {
    std::mt19937 rng(21);
    for (int trial = 0; trial < 20; ++trial) {
        const WindowNet n = randomWindow(rng);
        for (double u : {0.0, 0.17, 0.5, 0.83, 1.0})
            for (double v : {0.0, 0.31, 0.64, 1.0}) {
                const SurfaceJet j = evaluateWindowJet(n, Basis::Bezier, 0.5, u, v);
                EXPECT_LT(rel(j.p, naiveRational(n.points, *n.weights, u, v)), 1e-13);
                // Central differences of the naive quotient, inside the domain.
                const auto f = [&](double a, double b) { return naiveRational(n.points, *n.weights, a, b); };
                const double a = std::clamp(u, 1e-3, 1 - 1e-3), b = std::clamp(v, 1e-3, 1 - 1e-3), h = 1e-5, g = 1e-4;
                const SurfaceJet k = evaluateWindowJet(n, Basis::Bezier, 0.5, a, b);
                EXPECT_LT(rel(k.du, (f(a + h, b) - f(a - h, b)) / (2 * h)), 1e-6);
                EXPECT_LT(rel(k.dv, (f(a, b + h) - f(a, b - h)) / (2 * h)), 1e-6);
                EXPECT_LT(rel(k.duu, (f(a + g, b) - 2.0 * f(a, b) + f(a - g, b)) / (g * g)), 1e-5);
                EXPECT_LT(rel(k.dvv, (f(a, b + g) - 2.0 * f(a, b) + f(a, b - g)) / (g * g)), 1e-5);
                EXPECT_LT(rel(k.duv, (f(a + g, b + g) - f(a + g, b - g) - f(a - g, b + g) + f(a - g, b - g)) / (4 * g * g)), 1e-5);
                EXPECT_NEAR(glm::length(j.n), 1.0, 1e-12);
            }
    }
}

TEST(Rational, WeightsOneKeepThePolynomialsBoundaryBitsAndEqualWeightsItsSurface) {
    const Document grid = makePatchGrid(2, 2);
    const Patch& p = grid.patches[3];
    WindowNet poly{gatherNet(grid, p.idx), std::nullopt};
    WindowNet ones{poly.points, Weights16{}};
    ones.weights->fill(1.0);
    WindowNet twos{poly.points, Weights16{}};
    twos.weights->fill(2.5);
    const GridWeights gw = makeGridWeights(Basis::Bezier, 0.5, 8, 8);
    std::vector<SurfacePoint> a, b, c;
    evaluateWindowGrid(poly, p.idx, gw, a);
    evaluateWindowGrid(ones, p.idx, gw, b);  // the rational path with every weight 1
    evaluateWindowGrid(twos, p.idx, gw, c);
    ASSERT_EQ(a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k) {
        const size_t row = k / 9, col = k % 9;
        if (row == 0 || row == 8 || col == 0 || col == 8) {
            EXPECT_EQ(a[k].p, b[k].p) << k;  // the boundary bit for bit: no crack to a polynomial neighbour
        }
        EXPECT_LT(rel(b[k].p, a[k].p), 1e-15) << k;
        EXPECT_LT(rel(b[k].du, a[k].du), 1e-14) << k;
        EXPECT_LT(rel(c[k].p, a[k].p), 1e-15) << k;
        EXPECT_LT(rel(c[k].n, a[k].n), 1e-12) << k;
    }
}

// Every patch of a primitive sampled on a grid, with the jet (position, derivatives, normal).
template <class F>
void forEachSample(const Document& doc, F&& f) {
    for (size_t k = 0; k < doc.patches.size(); ++k) {
        const Patch& p = doc.patches[k];
        const WindowNet n = gatherWindow(doc, p.idx);
        for (int i = 0; i <= 12; ++i)
            for (int j = 0; j <= 12; ++j) f(evaluateWindowJet(n, p.basis, p.tension, j / 12.0, i / 12.0), i / 12.0, k);
    }
}

TEST(Rational, TheSphereIsASphere) {
    Document doc;
    const Vec3 c(1.0, -2.0, 0.5);
    const double R = 3.0;
    const PrimitiveResult made = addSphere(doc, c, R, true);
    EXPECT_EQ(made.patches.size(), 8u);
    double worstR = 0, worstN = 0, worstK = 0, worstH = 0;
    forEachSample(doc, [&](const SurfaceJet& j, double v, size_t) {
        worstR = std::max(worstR, std::abs(glm::length(j.p - c) - R));
        worstN = std::max(worstN, glm::length(j.n - (j.p - c) / R));  // outward, poles included
        if (v > 0.0 && v < 1.0) {                                     // away from the collapsed rows, where the first form is singular
            const glm::dvec2 kh = gpu::gaussMeanCurvature(j.du, j.dv, j.duu, j.duv, j.dvv, j.n);
            worstK = std::max(worstK, std::abs(kh.x * R * R - 1.0));
            worstH = std::max(worstH, std::abs(kh.y * R + 1.0));  // bends away from the outward normal
        }
    });
    // Twelve seams, all smooth: C1 joins (α = 1) that the control net already satisfies.
    ASSERT_EQ(doc.joins.size(), 8u + 4u);
    for (const Join& j : doc.joins) EXPECT_EQ(j.continuity, Continuity::C1);
    EXPECT_LT(projectConstraints(doc, {}).residual, 1e-12 * R);
    EXPECT_LT(worstR, 1e-14 * R * 8);
    EXPECT_LT(worstN, 1e-9);
    EXPECT_LT(worstK, 1e-9);
    EXPECT_LT(worstH, 1e-9);
}

TEST(Rational, CylinderConeAndTorusLieOnTheirSurfaces) {
    const double R = 2.0, H = 5.0, r = 0.5;
    for (int kind = 0; kind < 3; ++kind) {
        Document doc;
        if (kind == 0) addCylinder(doc, Vec3(0.0), R, H, true);
        if (kind == 1) addCone(doc, Vec3(0.0), R, H, true);
        if (kind == 2) addTorus(doc, Vec3(0.0), R, r, true);
        EXPECT_EQ(doc.patches.size(), kind == 0 ? 12u : kind == 1 ? 8u : 16u);
        double worst = 0.0;
        size_t outward = 0, samples = 0;
        forEachSample(doc, [&](const SurfaceJet& j, double, size_t patch) {
            const double rho = std::hypot(j.p.x, j.p.y), z = j.p.z;
            double err = 0.0;
            const bool cap = kind < 2 && (patch < 4 || (kind == 0 && patch >= 8));  // the profile: base, side(, top)
            if (kind == 2)
                err = std::abs(std::hypot(rho - R, z) - r);
            else if (cap)
                err = std::max(0.0, rho - R);
            else if (kind == 0)
                err = std::abs(rho - R);
            else
                err = std::abs(rho - R * (1.0 - z / H));
            worst = std::max(worst, err);
            // The normal points out of the solid: away from the axis on the sides, down/up on the caps.
            Vec3 out = kind == 2 ? Vec3(j.p.x - R * j.p.x / rho, j.p.y - R * j.p.y / rho, z) : Vec3(j.p.x, j.p.y, 0.0);
            if (cap) out = Vec3(0, 0, z < H / 2 ? -1.0 : 1.0);
            if (glm::length(out) > 1e-6) {
                ++samples;
                outward += glm::dot(j.n, out) > 0.0;
            }
        });
        EXPECT_LT(worst, 1e-13) << kind;
        EXPECT_EQ(outward, samples) << kind;
        // The rims are creases (C0); every other seam is smooth and held C1.
        size_t c0 = 0;
        for (const Join& j : doc.joins) c0 += j.continuity == Continuity::C0;
        EXPECT_EQ(c0, kind == 0 ? 8u : kind == 1 ? 4u : 0u) << kind;
        EXPECT_EQ(doc.joins.size(), kind == 0 ? 12u + 8u : kind == 1 ? 8u + 4u : 16u + 16u) << kind;
        EXPECT_LT(projectConstraints(doc, {}).residual, 1e-12) << kind;
    }
    Document doc;
    EXPECT_THROW(addTorus(doc, Vec3(0.0), 1.0, 1.5, true), EditError);
    EXPECT_THROW(addSphere(doc, Vec3(0.0), -1.0, true), EditError);
    EXPECT_TRUE(doc.patches.empty());
}

TEST(Rational, YUpPrimitivesStandOnTheirGroundPlane) {
    Document doc;
    addCone(doc, Vec3(0.0), 1.0, 2.0, false);
    double top = -1;
    for (const Vec3& p : doc.points) top = std::max(top, p.y);
    EXPECT_DOUBLE_EQ(top, 2.0);
    forEachSample(doc, [&](const SurfaceJet& j, double, size_t) { EXPECT_GE(j.p.y, -1e-15); });
}

TEST(Rational, SplittingARationalPatchKeepsItsSurface) {
    Document doc;
    addSphere(doc, Vec3(0.0), 1.0, true);
    const Document before = doc;
    const WindowNet whole = gatherWindow(before, before.patches[1].idx);
    const auto [a, b] = splitPatch(doc, 1, true, 0.3);
    for (double v : {0.1, 0.5, 0.9})
        for (double s : {0.0, 0.4, 1.0}) {
            const Vec3 onA = evaluateWindow(gatherWindow(doc, doc.patches[a].idx), Basis::Bezier, 0.5, s, v).p;
            const Vec3 onB = evaluateWindow(gatherWindow(doc, doc.patches[b].idx), Basis::Bezier, 0.5, s, v).p;
            EXPECT_LT(glm::length(onA - evaluateWindow(whole, Basis::Bezier, 0.5, 0.3 * s, v).p), 1e-14);
            EXPECT_LT(glm::length(onB - evaluateWindow(whole, Basis::Bezier, 0.5, 0.3 + 0.7 * s, v).p), 1e-14);
            EXPECT_NEAR(glm::length(onA), 1.0, 1e-14);
        }
}

TEST(Rational, FilesCarryWeightsAndRefuseBadOnes) {
    Document doc;
    addTorus(doc, Vec3(0.0), 2.0, 0.5, true);
    ASSERT_TRUE(isRational(doc));
    const std::string text = serializeDocument(doc);
    EXPECT_NE(text.find("\"weights\""), std::string::npos);
    EXPECT_EQ(parseDocument(text, "t.patchwork"), doc);
    EXPECT_EQ(serializeDocument(makePatchGrid(1, 1)).find("\"weights\""), std::string::npos);  // polynomial: none

    const auto refused = [&](const std::string& from, const std::string& to, const std::string& says) {
        std::string bad = text;
        const size_t at = bad.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        bad.replace(at, from.size(), to);
        try {
            (void)parseDocument(bad, "t.patchwork");
            ADD_FAILURE() << "accepted " << to;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("t.patchwork"), std::string::npos) << e.what();
        }
    };
    refused("\"weights\": [\n", "\"weights\": [\n-1.0,\n", "weights");  // a count that does not match
    refused("\"weights\": [\n    1.0", "\"weights\": [\n    0.0", "weights[0]");
    refused("\"weights\": [\n    1.0", "\"weights\": [\n    \"heavy\"", "weights[0]");
}

TEST(Rational, TheWeightCommandSetsUndoesAndRefusesTriangles) {
    EditSession s;
    s.reset(makePatchGrid(1, 1), "");
    runEditScript(s, "select point 5,6\nweight 2.5\n");
    EXPECT_EQ(pointWeight(s.doc, 5), 2.5);
    EXPECT_EQ(pointWeight(s.doc, 6), 2.5);
    EXPECT_EQ(pointWeight(s.doc, 4), 1.0);
    runEditScript(s, "undo\n");
    EXPECT_FALSE(isRational(s.doc));
    EXPECT_THROW(runEditScript(s, "select point 5\nweight 0\n"), InputError);  // a script's error names its line
    EXPECT_THROW(runEditScript(s, "select point 5\nweight -2\n"), InputError);
    EXPECT_FALSE(isRational(s.doc));

    EditSession t;
    t.reset(makeTriangleDome(), "");
    const Document before = t.doc;
    EXPECT_THROW(runEditScript(t, "select point 0\nweight 2\n"), InputError);
    EXPECT_EQ(t.doc, before);  // refused whole
}

TEST(Rational, WeldingAndMergingKeepPointsOfDifferentWeights) {
    Document doc;
    addSphere(doc, Vec3(0.0), 1.0, true);
    const size_t points = doc.points.size();
    Document twice = doc;
    EXPECT_EQ(weightedTrianglePoint(twice), std::nullopt);
    // The poles hold two points each (weights 1 and (1 + √2)/3) at one place: never merged.
    mergeCoincidentPoints(twice, 0.0);
    EXPECT_EQ(twice, doc);
    mergeCoincidentPoints(twice, 1e-6);
    EXPECT_EQ(twice.points.size(), points);
    EXPECT_EQ(twice.weights, doc.weights);
    // A copy of the same points with weight 1 everywhere welds onto nothing of the weighted ones.
    Document merged = doc;
    const size_t firstPlain = merged.points.size();
    for (size_t i = 0; i < points; ++i) merged.points.push_back(doc.points[i]);
    Patch plain = doc.patches[0];
    for (uint32_t& i : plain.idx) i += uint32_t(firstPlain);
    merged.patches.push_back(plain);
    mergeCoincidentPoints(merged, 0.0);
    for (uint32_t i : merged.patches.back().idx) EXPECT_EQ(pointWeight(merged, i), 1.0);
    for (size_t k = 0; k < 16; ++k) EXPECT_EQ(pointWeight(merged, merged.patches[0].idx[k]), pointWeight(doc, doc.patches[0].idx[k])) << k;
    EXPECT_NE(merged.patches.back().idx[5], merged.patches[0].idx[5]);  // an inner point of weight ≠ 1 stays apart from its plain twin
}

}  // namespace

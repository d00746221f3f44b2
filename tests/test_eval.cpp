// Evaluation: the three Bézier evaluators agree, derivatives match finite differences, splits
// reproduce the patch, spline windows behave as their basis promises, degenerate normals are finite.
#include <gtest/gtest.h>

#include <random>

#include "core/eval/bezier_math.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/basis.hpp"
#include "core/model/document.hpp"

using namespace pw;

namespace {

Net16 randomNet(std::mt19937& rng) {
    std::uniform_real_distribution<double> d(-2.0, 2.0);
    Net16 n;
    for (auto& p : n) p = Vec3(d(rng), d(rng), d(rng));
    return n;
}

double dist(const Vec3& a, const Vec3& b) { return glm::length(a - b); }

}  // namespace

TEST(Basis, BernsteinWeightsSumToOneAndMatchMatrixForm) {
    const Mat4 m = basisMatrix(Basis::Bezier);
    for (int k = 0; k <= 100; ++k) {
        const double t = k / 100.0;
        const BasisWeights b = bernsteinWeights(t, 1 - t), mw = matrixWeights(m, t);
        double sum = 0, dsum = 0;
        for (int j = 0; j < 4; ++j) {
            sum += b.w[j];
            dsum += b.dw[j];
            EXPECT_NEAR(b.w[j], mw.w[j], 1e-14);
            EXPECT_NEAR(b.dw[j], mw.dw[j], 1e-13);
            EXPECT_NEAR(b.ddw[j], mw.ddw[j], 1e-12);
        }
        EXPECT_NEAR(sum, 1.0, 1e-15);
        EXPECT_NEAR(dsum, 0.0, 1e-13);
    }
}

TEST(Basis, SplineWeightsArePartitionsOfUnity) {
    for (Basis b : {Basis::BSpline, Basis::CatmullRom}) {
        for (int k = 0; k <= 50; ++k) {
            const BasisWeights w = basisWeights(b, 0.5, k / 50.0);
            EXPECT_NEAR(w.w[0] + w.w[1] + w.w[2] + w.w[3], 1.0, 1e-14) << basisName(b);
        }
    }
}

TEST(Eval, BernsteinMatrixAndDeCasteljauAgree) {
    std::mt19937 rng(7);
    const Mat4 m = basisMatrix(Basis::Bezier);
    for (int trial = 0; trial < 200; ++trial) {
        const Net16 net = randomNet(rng);
        std::uniform_real_distribution<double> t(0, 1);
        const double u = t(rng), v = t(rng);
        const Vec3 a = evaluateBezierBernsteinSum(net, u, v);
        const Vec3 b = evaluateMatrixForm(net, m, u, v);
        const Vec3 c = evaluateBezierDeCasteljau(net, u, v);
        const Vec3 d = evaluateNet(net, Basis::Bezier, 0.5, u, v).p;
        EXPECT_LE(dist(a, b), 1e-12);
        EXPECT_LE(dist(a, c), 1e-12);
        EXPECT_LE(dist(a, d), 1e-12);
    }
}

TEST(Eval, DerivativesMatchFiniteDifferences) {
    std::mt19937 rng(11);
    for (Basis basis : {Basis::Bezier, Basis::BSpline, Basis::CatmullRom}) {
        for (int trial = 0; trial < 50; ++trial) {
            const Net16 net = randomNet(rng);
            std::uniform_real_distribution<double> t(0.05, 0.95);
            const double u = t(rng), v = t(rng), h = 1e-6;
            const SurfacePoint sp = evaluateNet(net, basis, 0.5, u, v);
            const Vec3 fu = (evaluateNet(net, basis, 0.5, u + h, v).p - evaluateNet(net, basis, 0.5, u - h, v).p) / (2 * h);
            const Vec3 fv = (evaluateNet(net, basis, 0.5, u, v + h).p - evaluateNet(net, basis, 0.5, u, v - h).p) / (2 * h);
            EXPECT_LE(dist(sp.du, fu), 1e-6) << basisName(basis);
            EXPECT_LE(dist(sp.dv, fv), 1e-6) << basisName(basis);
            EXPECT_NEAR(glm::length(sp.n), 1.0, 1e-12);
            EXPECT_NEAR(glm::dot(sp.n, sp.du), 0.0, 1e-9 * glm::length(sp.du));
        }
    }
}

TEST(Eval, SplitHalvesReproduceThePatch) {
    std::mt19937 rng(3);
    for (int trial = 0; trial < 50; ++trial) {
        const Net16 net = randomNet(rng);
        const double s = 0.1 + 0.8 * (trial / 50.0);
        const auto [left, right] = splitBezierU(net, s);
        const auto [low, high] = splitBezierV(net, s);
        for (int k = 0; k <= 10; ++k) {
            for (int l = 0; l <= 10; ++l) {
                const double a = k / 10.0, b = l / 10.0;
                EXPECT_LE(dist(evaluateBezierDeCasteljau(left, a, b), evaluateBezierDeCasteljau(net, a * s, b)), 1e-12);
                EXPECT_LE(dist(evaluateBezierDeCasteljau(right, a, b), evaluateBezierDeCasteljau(net, s + a * (1 - s), b)), 1e-12);
                EXPECT_LE(dist(evaluateBezierDeCasteljau(low, a, b), evaluateBezierDeCasteljau(net, a, b * s)), 1e-12);
                EXPECT_LE(dist(evaluateBezierDeCasteljau(high, a, b), evaluateBezierDeCasteljau(net, a, s + b * (1 - s))), 1e-12);
            }
        }
    }
}

TEST(Eval, CatmullRomInterpolatesInnerPoints) {
    std::mt19937 rng(5);
    for (double tension : {0.5, 0.3, 0.8}) {
        const Net16 net = randomNet(rng);
        EXPECT_LE(dist(evaluateNet(net, Basis::CatmullRom, tension, 0, 0).p, net[5]), 1e-14);
        EXPECT_LE(dist(evaluateNet(net, Basis::CatmullRom, tension, 1, 0).p, net[6]), 1e-14);
        EXPECT_LE(dist(evaluateNet(net, Basis::CatmullRom, tension, 0, 1).p, net[9]), 1e-14);
        EXPECT_LE(dist(evaluateNet(net, Basis::CatmullRom, tension, 1, 1).p, net[10]), 1e-14);
    }
}

TEST(Eval, BSplineWindowsMeetC2) {
    // A 4x5 net: the two windows side by side share three columns and must meet with equal
    // position, first and second u-derivatives.
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> d(-2.0, 2.0);
    Vec3 big[4][5];
    for (auto& row : big)
        for (auto& p : row) p = Vec3(d(rng), d(rng), d(rng));
    Net16 a, b;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            a[i * 4 + j] = big[i][j];
            b[i * 4 + j] = big[i][j + 1];
        }
    const Mat4 m = basisMatrix(Basis::BSpline);
    for (int k = 0; k <= 10; ++k) {
        const double v = k / 10.0;
        EXPECT_LE(dist(evaluateNet(a, Basis::BSpline, 0.5, 1, v).p, evaluateNet(b, Basis::BSpline, 0.5, 0, v).p), 1e-13);
        EXPECT_LE(dist(evaluateNet(a, Basis::BSpline, 0.5, 1, v).du, evaluateNet(b, Basis::BSpline, 0.5, 0, v).du), 1e-12);
        // second derivative in u from the matrix form
        const BasisWeights wa = matrixWeights(m, 1.0), wb = matrixWeights(m, 0.0), wv = matrixWeights(m, v);
        Vec3 dda{0.0}, ddb{0.0};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                dda += wv.w[i] * wa.ddw[j] * a[i * 4 + j];
                ddb += wv.w[i] * wb.ddw[j] * b[i * 4 + j];
            }
        EXPECT_LE(dist(dda, ddb), 1e-12);
    }
}

TEST(Eval, DegenerateEdgeNormalsAreFiniteUnitAndContinuous) {
    // A cone-like patch: row v=0 collapsed to the apex, like the teapot's lid top.
    Net16 net;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const double r = i / 3.0, a = j / 3.0 * 1.5707963;
            net[i * 4 + j] = Vec3(r * std::cos(a), r * std::sin(a), 1.0 - r);
        }
    for (int k = 0; k <= 8; ++k) {
        const double u = k / 8.0;
        const SurfacePoint apex = evaluateNet(net, Basis::Bezier, 0.5, u, 0.0);
        const SurfacePoint near = evaluateNet(net, Basis::Bezier, 0.5, u, 1e-4);
        ASSERT_TRUE(std::isfinite(apex.n.x) && std::isfinite(apex.n.y) && std::isfinite(apex.n.z));
        EXPECT_NEAR(glm::length(apex.n), 1.0, 1e-12);
        EXPECT_GT(glm::dot(apex.n, near.n), 0.99) << "u=" << u;
    }
}

TEST(Eval, GridMatchesPointEvaluationAndSharedEdgesAreBitIdentical) {
    std::mt19937 rng(21);
    Net16 a = randomNet(rng), b = randomNet(rng);
    // B's column j=0 is A's column j=3 reversed (a seam traversed the other way round).
    std::array<uint32_t, 16> ia{}, ib{};
    for (int k = 0; k < 16; ++k) ia[k] = k;
    for (int k = 0; k < 16; ++k) ib[k] = 100 + k;
    for (int i = 0; i < 4; ++i) {
        b[i * 4] = a[(3 - i) * 4 + 3];
        ib[i * 4] = ia[(3 - i) * 4 + 3];
    }
    const GridWeights gw = makeGridWeights(Basis::Bezier, 0.5, 7, 7);
    std::vector<SurfacePoint> ga, gb;
    evaluateGrid(a, ia, gw, ga);
    evaluateGrid(b, ib, gw, gb);
    for (int r = 0; r <= 7; ++r) {
        // bit-identical seam: A's u=1 column at v=r/7 equals B's u=0 column at v=(7-r)/7
        EXPECT_EQ(ga[r * 8 + 7].p, gb[(7 - r) * 8 + 0].p) << "row " << r;
        for (int c = 0; c <= 7; ++c) EXPECT_LE(dist(ga[r * 8 + c].p, evaluateNet(a, Basis::Bezier, 0.5, c / 7.0, r / 7.0).p), 1e-12);
    }
}

// The Bézier math overlay's numbers (core/eval/bezier_math): the 16 weights are the products of the
// 4 + 4 Bernstein factors and sum to 1, Σ weight·P is the point, the de Casteljau column ends on
// it, its last segment is the v tangent over 3, and the rows' points are the column's control
// polygon; a rational patch the same with w·B / Σ w·B.
TEST(BezierMath, WeightsConstructionAndPointAgree) {
    std::mt19937 rng(41);
    for (int trial = 0; trial < 20; ++trial) {
        const Net16 net = randomNet(rng);
        const double u = std::uniform_real_distribution<double>(0, 1)(rng), v = std::uniform_real_distribution<double>(0, 1)(rng);
        const BezierMath m = bezierMath(net, std::nullopt, u, v);
        double sum = 0.0;
        Vec3 weighted(0.0);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const double w = m.weights[size_t(i * 4 + j)];
                EXPECT_NEAR(w, m.bv[size_t(i)] * m.bu[size_t(j)], 1e-15);
                sum += w;
                weighted += w * net[size_t(i * 4 + j)];
            }
        EXPECT_NEAR(sum, 1.0, 1e-14);
        const Vec3 ref = evaluateBezierBernsteinSum(net, u, v);
        EXPECT_LT(glm::length(weighted - ref), 1e-12);
        EXPECT_LT(glm::length(m.column.point - ref), 1e-12);
        EXPECT_LT(glm::length(m.point - ref), 1e-12);
        EXPECT_LT(glm::length(3.0 * (m.column.second[1] - m.column.second[0]) - m.dv), 1e-10);
        for (int i = 0; i < 4; ++i) {
            Vec3 row(0.0);
            for (int j = 0; j < 4; ++j) row += m.bu[size_t(j)] * net[size_t(i * 4 + j)];
            EXPECT_LT(glm::length(m.rows[size_t(i)].point - row), 1e-12);
        }
        EXPECT_NEAR(glm::length(m.normal), 1.0, 1e-12);
    }
    // Rational: a patch with uneven weights.
    const Net16 net = randomNet(rng);
    Weights16 w;
    for (size_t k = 0; k < 16; ++k) w[k] = 0.5 + 0.1 * double(k);
    const BezierMath m = bezierMath(net, w, 0.3, 0.7);
    double sum = 0.0;
    Vec3 weighted(0.0);
    for (size_t k = 0; k < 16; ++k) {
        sum += m.weights[k];
        weighted += m.weights[k] * net[k];
    }
    const Vec3 ref = evaluateWindow(WindowNet{net, w}, Basis::Bezier, 0.5, 0.3, 0.7).p;
    EXPECT_NEAR(sum, 1.0, 1e-14);
    EXPECT_LT(glm::length(weighted - ref), 1e-12);
    EXPECT_LT(glm::length(m.column.point - ref), 1e-12);
}

// The diagram: the net (24 lines) with every point labelled by its weight, each row's pyramid (3
// strokes), the column polygon (3) and its pyramid (3), three arrows; the side box's seven lines.
TEST(BezierMath, DiagramLabelsEveryControlPoint) {
    std::mt19937 rng(7);
    const Net16 net = randomNet(rng);
    const BezierMath m = bezierMath(net, std::nullopt, 0.25, 0.5);
    const MathDiagram d = bezierMathDiagram(net, m);
    EXPECT_EQ(d.strokes.size(), 24u + 4u * 3u + 3u + 3u + 3u);
    size_t labelled = 0;
    for (const auto& dot : d.dots)
        if (dot.role == MathDiagram::Role::Net) {
            ++labelled;
            EXPECT_FALSE(dot.label.empty());
        }
    EXPECT_EQ(labelled, 16u);
    // B_1(0.25) = 3 * 0.25 * 0.75^2 = 0.421875, B_2(0.5) = 0.375: point (2, 1) weighs 0.158.
    EXPECT_EQ(d.dots[2 * 4 + 1].label, "0.158");
    ASSERT_EQ(d.legend.size(), 7u);
    EXPECT_EQ(d.legend[1], "B(u) = 0.422  0.422  0.141  0.016");
}

// Cubic Bézier triangles: evaluation against an independent formula (de Casteljau on the triangle
// net), partition of unity, corner interpolation, edges as cubic curves of their 4 points, flat and
// degenerate normals, finite-difference derivatives, bit-identical shared edges.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/eval/bezier_triangle.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/model/basis.hpp"
#include "core/model/document.hpp"

using namespace pw;

namespace {

Net10 randomNet(std::mt19937& rng) {
    std::uniform_real_distribution<double> d(-2.0, 2.0);
    Net10 n;
    for (auto& p : n) p = Vec3(d(rng), d(rng), d(rng));
    return n;
}

// Independent formula: de Casteljau on the triangular net. Level r holds the points b^r_{ijk},
// i + j + k = 3 - r, keyed by (i, j); b^{r+1}_{ijk} = u b^r_{i+1,j,k} + v b^r_{i,j+1,k} + w b^r_{i,j,k+1}.
// The net is read by its (i, j, k) meaning, written out here rather than through triSlot.
Vec3 deCasteljauTriangle(const Net10& net, double u, double v, double w) {
    // b[i][j] at the current level (k = deg - i - j).
    Vec3 b[4][4];
    const int order[10][3] = {{3, 0, 0}, {2, 1, 0}, {2, 0, 1}, {1, 2, 0}, {1, 1, 1}, {1, 0, 2}, {0, 3, 0}, {0, 2, 1}, {0, 1, 2}, {0, 0, 3}};
    for (int s = 0; s < 10; ++s) b[order[s][0]][order[s][1]] = net[s];
    for (int deg = 3; deg > 0; --deg) {
        Vec3 nb[4][4];
        for (int i = 0; i < deg; ++i)
            for (int j = 0; j < deg - i; ++j) nb[i][j] = u * b[i + 1][j] + v * b[i][j + 1] + w * b[i][j];
        for (int i = 0; i < deg; ++i)
            for (int j = 0; j < deg - i; ++j) b[i][j] = nb[i][j];
    }
    return b[0][0];
}

double dist(const Vec3& a, const Vec3& b) { return glm::length(a - b); }

Vec3 cubic(const std::array<Vec3, 4>& p, double t) {
    const double s = 1 - t;
    return s * s * s * p[0] + 3 * s * s * t * p[1] + 3 * s * t * t * p[2] + t * t * t * p[3];
}

}  // namespace

TEST(BezierTriangle, SlotsFollowTheDocumentedOrder) {
    EXPECT_EQ(triSlot(3, 0, 0), 0);
    EXPECT_EQ(triSlot(2, 1, 0), 1);
    EXPECT_EQ(triSlot(2, 0, 1), 2);
    EXPECT_EQ(triSlot(1, 2, 0), 3);
    EXPECT_EQ(triSlot(1, 1, 1), 4);
    EXPECT_EQ(triSlot(1, 0, 2), 5);
    EXPECT_EQ(triSlot(0, 3, 0), 6);
    EXPECT_EQ(triSlot(0, 2, 1), 7);
    EXPECT_EQ(triSlot(0, 1, 2), 8);
    EXPECT_EQ(triSlot(0, 0, 3), 9);
    // Edges run corner to corner: 0 = v→w, 1 = w→u, 2 = u→v.
    EXPECT_EQ(triEdgeSlot(0, 0), 6);
    EXPECT_EQ(triEdgeSlot(0, 3), 9);
    EXPECT_EQ(triEdgeSlot(1, 0), 9);
    EXPECT_EQ(triEdgeSlot(1, 3), 0);
    EXPECT_EQ(triEdgeSlot(2, 0), 0);
    EXPECT_EQ(triEdgeSlot(2, 3), 6);
}

TEST(BezierTriangle, MatchesDeCasteljauOnTheNet) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> d(0.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        const Net10 net = randomNet(rng);
        for (int s = 0; s < 20; ++s) {
            double u = d(rng), v = d(rng);
            if (u + v > 1) {
                u = 1 - u;
                v = 1 - v;
            }
            const double w = 1 - u - v;
            const Vec3 ref = deCasteljauTriangle(net, u, v, w);
            EXPECT_LT(dist(evaluateTriangle(net, u, v).p, ref), 1e-12);
            EXPECT_LT(dist(evaluateTriangleBernsteinSum(net, u, v, w), ref), 1e-12);
        }
    }
}

TEST(BezierTriangle, PartitionOfUnityReproducesConstantsAndLinearFunctions) {
    // All control points equal → that point everywhere; a linear net (b_ijk = (iA + jB + kC)/3) →
    // the linear map u A + v B + w C (linear precision).
    const Vec3 A(1, 2, 3), B(-4, 0.5, 2), C(0.25, -1, 7);
    Net10 same, linear;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3 - i; ++j) {
            const int k = 3 - i - j;
            same[triSlot(i, j, k)] = A;
            linear[triSlot(i, j, k)] = (double(i) * A + double(j) * B + double(k) * C) / 3.0;
        }
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10 - i; ++j) {
            const double u = i / 10.0, v = j / 10.0, w = 1 - u - v;
            EXPECT_LT(dist(evaluateTriangle(same, u, v).p, A), 1e-13);
            EXPECT_LT(dist(evaluateTriangle(linear, u, v).p, u * A + v * B + w * C), 1e-13);
        }
}

TEST(BezierTriangle, InterpolatesCornersAndEdgesAreCubicCurvesOfTheirFourPoints) {
    std::mt19937 rng(11);
    const Net10 net = randomNet(rng);
    EXPECT_EQ(evaluateTriangle(net, 1, 0, 0).p, net[0]);
    EXPECT_EQ(evaluateTriangle(net, 0, 1, 0).p, net[6]);
    EXPECT_EQ(evaluateTriangle(net, 0, 0, 1).p, net[9]);
    for (int e = 0; e < 3; ++e) {
        std::array<Vec3, 4> pts;
        for (int k = 0; k < 4; ++k) pts[k] = net[triEdgeSlot(e, k)];
        for (int s = 0; s <= 16; ++s) {
            const double t = s / 16.0;
            // Edge 0: (0, 1-t, t); edge 1: (t, 0, 1-t); edge 2: (1-t, t, 0).
            const double u = e == 0 ? 0 : e == 1 ? t : 1 - t;
            const double v = e == 0 ? 1 - t : e == 1 ? 0 : t;
            EXPECT_LT(dist(evaluateTriangle(net, u, v).p, cubic(pts, t)), 1e-13) << "edge " << e << " t " << t;
        }
    }
}

TEST(BezierTriangle, DerivativesMatchFiniteDifferences) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> d(0.05, 0.45);
    const double h = 1e-6;
    for (int trial = 0; trial < 30; ++trial) {
        const Net10 net = randomNet(rng);
        const double u = d(rng), v = d(rng);
        const TriPoint tp = evaluateTriangle(net, u, v);
        const Vec3 fdU = (evaluateTriangle(net, u + h, v).p - evaluateTriangle(net, u - h, v).p) / (2 * h);
        const Vec3 fdV = (evaluateTriangle(net, u, v + h).p - evaluateTriangle(net, u, v - h).p) / (2 * h);
        EXPECT_LT(dist(tp.du, fdU), 1e-6);
        EXPECT_LT(dist(tp.dv, fdV), 1e-6);
        EXPECT_NEAR(glm::length(tp.n), 1.0, 1e-12);
        EXPECT_LT(dist(tp.n, glm::normalize(glm::cross(fdU, fdV))), 1e-5);
    }
}

TEST(BezierTriangle, FlatTriangleNormalsEqualThePlaneNormal) {
    // A curved parametrisation of a planar triangle: control points scattered in the plane.
    const Vec3 o(1, 2, 3), a = glm::normalize(Vec3(1, 1, 0)), b = glm::normalize(Vec3(-1, 1, 1));
    const Vec3 planeNormal = glm::normalize(glm::cross(a, b));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    Net10 net;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3 - i; ++j) {
            const double x = i / 3.0 + jitter(rng) * (i > 0 && i < 3), y = j / 3.0 + jitter(rng) * (j > 0 && j < 3);
            net[triSlot(i, j, 3 - i - j)] = o + 2.0 * x * a + 2.0 * y * b;
        }
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8 - i; ++j) {
            const TriPoint tp = evaluateTriangle(net, i / 8.0, j / 8.0);
            EXPECT_LT(dist(tp.n, planeNormal), 1e-9) << i << "," << j;
        }
}

TEST(BezierTriangle, DegenerateNetsGiveFiniteUnitNormals) {
    std::mt19937 rng(9);
    std::vector<Net10> nets;
    // Edge 2 (w = 0) collapsed to one point: every point on it has du × dv = 0.
    Net10 a = randomNet(rng);
    for (int k = 1; k < 4; ++k) a[triEdgeSlot(2, k)] = a[triEdgeSlot(2, 0)];
    nets.push_back(a);
    // A corner whose first tangent point coincides with it.
    Net10 b = randomNet(rng);
    b[1] = b[0];
    nets.push_back(b);
    // Two edges collapsed (a triangle pinched to a lens).
    Net10 c = randomNet(rng);
    for (int k = 1; k < 4; ++k) c[triEdgeSlot(0, k)] = c[triEdgeSlot(0, 0)];
    for (int k = 1; k < 4; ++k) c[triEdgeSlot(1, k)] = c[triEdgeSlot(1, 0)];
    nets.push_back(c);
    // Everything on one line: no tangent plane anywhere, still a finite unit normal.
    Net10 line;
    for (int s = 0; s < 10; ++s) line[s] = Vec3(s, 2 * s, 0);
    nets.push_back(line);
    for (const Net10& net : nets)
        for (int i = 0; i <= 6; ++i)
            for (int j = 0; j <= 6 - i; ++j) {
                const TriPoint tp = evaluateTriangle(net, i / 6.0, j / 6.0);
                ASSERT_TRUE(std::isfinite(tp.n.x) && std::isfinite(tp.n.y) && std::isfinite(tp.n.z));
                EXPECT_NEAR(glm::length(tp.n), 1.0, 1e-12);
            }
    // At the collapsed edge the fallback keeps the orientation of the interior.
    const Vec3 inside = evaluateTriangle(a, 0.3, 0.3).n;
    EXPECT_GT(glm::dot(evaluateTriangle(a, 0.5, 0.5).n, inside), 0.0);
}

TEST(BezierTriangle, GridMatchesPointwiseEvaluationAndCounts) {
    std::mt19937 rng(13);
    const Net10 net = randomNet(rng);
    std::array<uint32_t, 10> ids;
    for (uint32_t k = 0; k < 10; ++k) ids[k] = k;
    for (int n : {1, 2, 5, 16}) {
        std::vector<TriPoint> grid;
        evaluateTriangleGrid(net, ids, n, grid);
        ASSERT_EQ(grid.size(), size_t(n + 1) * (n + 2) / 2);
        EXPECT_EQ(triGridIndex(n, 0, n) + 1, triGridIndex(0, 1, n));
        EXPECT_EQ(triGridIndex(0, n, n) + 1, grid.size());
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n - j; ++i)
                EXPECT_LT(dist(grid[triGridIndex(i, j, n)].p, evaluateTriangle(net, double(i) / n, double(j) / n).p), 1e-12);
    }
}

TEST(BezierTriangle, SharedEdgesAreBitIdenticalWithTrianglesAndQuads) {
    // Triangle A and triangle B share A's edge 2 (pool 0,1,3,6) as B's edge 0 reversed; a quad
    // shares A's edge 1 as its v = 0 row.
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> d(-2.0, 2.0);
    std::vector<Vec3> pool(40);
    for (auto& p : pool) p = Vec3(d(rng), d(rng), d(rng));
    const std::array<uint32_t, 10> A{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    // B's edge 0 (slots 6,7,8,9) = pool 6,3,1,0 (A's edge 2 reversed).
    const std::array<uint32_t, 10> B{20, 21, 22, 23, 24, 25, 6, 3, 1, 0};
    Net10 na, nb;
    for (int k = 0; k < 10; ++k) {
        na[k] = pool[A[k]];
        nb[k] = pool[B[k]];
    }
    // Quad: row i = 0 is A's edge 1 (pool 9, 5, 2, 0).
    std::array<uint32_t, 16> Q{9, 5, 2, 0, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 10, 11};
    Net16 nq;
    for (int k = 0; k < 16; ++k) nq[k] = pool[Q[k]];
    for (int n : {3, 7, 16}) {
        std::vector<TriPoint> ga, gb;
        evaluateTriangleGrid(na, A, n, ga);
        evaluateTriangleGrid(nb, B, n, gb);
        std::vector<SurfacePoint> gq;
        evaluateGrid(nq, Q, makeGridWeights(Basis::Bezier, 0.5, n, n), gq);
        for (int k = 0; k <= n; ++k) {
            const auto [ia, ja] = triGridEdgePoint(2, k, n);
            const auto [ib, jb] = triGridEdgePoint(0, n - k, n);
            EXPECT_EQ(ga[triGridIndex(ia, ja, n)].p, gb[triGridIndex(ib, jb, n)].p) << "n " << n << " k " << k;
            const auto [i1, j1] = triGridEdgePoint(1, k, n);
            EXPECT_EQ(ga[triGridIndex(i1, j1, n)].p, gq[size_t(k)].p) << "quad n " << n << " k " << k;
        }
    }
}

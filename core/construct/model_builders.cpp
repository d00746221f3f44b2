// Procedural documents for tests and benchmarks: a grid of bicubic Bézier patches on one shared
// control lattice, joined across every interior edge.
#include "core/construct/model_builders.hpp"

#include <array>
#include <cmath>
#include <glm/vec2.hpp>
#include <map>
#include <stdexcept>
#include <string>

namespace pw {
inline namespace construct {

namespace {

// Samples f at lattice indices 0..3n and replaces every patch-boundary sample 3m (0 < m < n) by
// the average of its two neighbours, so that a net built from these values is exactly C1 across
// the boundaries (uniform spacing: boundary = midpoint of the two tangent points).
std::vector<double> c1Samples(int n, double step, double (*f)(double)) {
    std::vector<double> s(static_cast<size_t>(3 * n + 1));
    for (size_t i = 0; i < s.size(); ++i) s[i] = f(static_cast<double>(i) * step);
    for (int m = 1; m < n; ++m) s[3 * m] = 0.5 * (s[3 * m - 1] + s[3 * m + 1]);
    return s;
}

// The Bézier form of a uniform cubic B-spline whose de Boor values are f at −1, 0, ..., n + 1
// (Böhm's conversion): interior points at the thirds of each de Boor leg, boundary points midway
// between their neighbours, so a net built from these values is C2 across every boundary.
std::vector<double> c2Samples(int n, double (*f)(double)) {
    std::vector<double> d(static_cast<size_t>(n + 3)), s(static_cast<size_t>(3 * n + 1));
    for (size_t i = 0; i < d.size(); ++i) d[i] = f(static_cast<double>(i) - 1.0);
    for (int m = 0; m < n; ++m) {
        s[size_t(3 * m + 1)] = (2.0 * d[size_t(m + 1)] + d[size_t(m + 2)]) / 3.0;
        s[size_t(3 * m + 2)] = (d[size_t(m + 1)] + 2.0 * d[size_t(m + 2)]) / 3.0;
    }
    for (int m = 1; m < n; ++m) s[size_t(3 * m)] = 0.5 * (s[size_t(3 * m - 1)] + s[size_t(3 * m + 1)]);
    s[0] = (d[0] + 4.0 * d[1] + d[2]) / 6.0;
    s[size_t(3 * n)] = (d[size_t(n)] + 4.0 * d[size_t(n + 1)] + d[size_t(n + 2)]) / 6.0;
    return s;
}

double waveX(double x) { return std::sin(x); }
double waveY(double y) { return std::cos(0.7 * y); }

// Slot of b_ijk in TrianglePatch::idx (bezier_triangle.hpp's triSlot, repeated to keep this file
// free of the evaluator).
int triangleSlot(int i, int k) { return (3 - i) * (4 - i) / 2 + k; }

}  // namespace

Document makePatchGrid(int rows, int cols, Continuity continuity) {
    if (rows < 1 || cols < 1) throw std::invalid_argument("makePatchGrid: rows and cols must be >= 1");

    Document doc;
    doc.name = "grid " + std::to_string(rows) + "x" + std::to_string(cols);

    // Lattice (3*rows+1) x (3*cols+1): x = c/3, y = r/3 and z = 0.3·X(c)·Y(r) with X, Y sampled so
    // that every boundary value is the mean of its neighbours. The product of two such sequences
    // keeps the property in both directions, so the net satisfies C1 (up to rounding) everywhere.
    const int latticeCols = 3 * cols + 1, latticeRows = 3 * rows + 1;
    const double step = 1.0 / 3.0;
    // C2/G2 grids use the Bézier form of a cubic B-spline instead (C2 in both directions).
    const bool c2 = holdsCurvature(continuity);
    const std::vector<double> zx = c2 ? c2Samples(cols, waveX) : c1Samples(cols, step, waveX);
    const std::vector<double> zy = c2 ? c2Samples(rows, waveY) : c1Samples(rows, step, waveY);
    auto poolIndex = [&](int r, int c) { return static_cast<uint32_t>(r * latticeCols + c); };

    doc.points.resize(static_cast<size_t>(latticeRows) * latticeCols);
    for (int r = 0; r < latticeRows; ++r) {
        for (int c = 0; c < latticeCols; ++c) {
            const double x = c == 3 * (c / 3) ? c / 3 : c * step;  // exact integers on boundaries
            const double y = r == 3 * (r / 3) ? r / 3 : r * step;
            doc.points[poolIndex(r, c)] = Vec3(x, y, 0.3 * zx[c] * zy[r]);
        }
    }

    // Patches: patch i*cols+j covers lattice rows 3i..3i+3 and columns 3j..3j+3.
    doc.patches.reserve(static_cast<size_t>(rows) * cols);
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < cols; ++j) {
            Patch p;
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b) p.idx[a * 4 + b] = poolIndex(3 * i + a, 3 * j + b);
            p.basis = Basis::Bezier;
            p.name = "grid_" + std::to_string(i) + "_" + std::to_string(j);
            doc.patches.push_back(std::move(p));
        }
    }

    // Joins across interior edges: u1 of (i,j) meets u0 of (i,j+1); v1 of (i,j) meets v0 of (i+1,j).
    // In both cases point k runs the same way on both sides (not reversed).
    auto patchIndex = [&](int i, int j) { return static_cast<uint32_t>(i * cols + j); };
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < cols; ++j) {
            if (j + 1 < cols) doc.joins.push_back(Join{patchIndex(i, j), Edge::U1, patchIndex(i, j + 1), Edge::U0, false, continuity, 1.0});
            if (i + 1 < rows) doc.joins.push_back(Join{patchIndex(i, j), Edge::V1, patchIndex(i + 1, j), Edge::V0, false, continuity, 1.0});
        }
    }
    return doc;
}

Document makeTriangleDome(double radius, double height) {
    if (!(radius > 0.0)) throw std::invalid_argument("makeTriangleDome: radius must be > 0");
    Document doc;
    doc.name = "triangle dome";
    const double a = height / (radius * radius);
    // The blossom of f(p) = height - a |p|^2 (a polynomial of degree 2 written as degree 3).
    auto blossom = [&](const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& r) {
        return height - a * (glm::dot(p, q) + glm::dot(p, r) + glm::dot(q, r)) / 3.0;
    };
    // Pool entries keyed by their lattice position (multiples of radius/3 in the hexagon's frame).
    std::map<std::array<int, 8>, uint32_t> pool;
    auto pointFor = [&](const std::array<int, 8>& key, const Vec3& p) {
        auto [it, inserted] = pool.try_emplace(key, static_cast<uint32_t>(doc.points.size()));
        if (inserted) doc.points.push_back(p);
        return it->second;
    };
    const double kPi = 3.14159265358979323846;
    glm::dvec2 corner[6];
    for (int m = 0; m < 6; ++m) corner[m] = radius * glm::dvec2(std::cos(m * kPi / 3.0), std::sin(m * kPi / 3.0));
    const glm::dvec2 centre(0.0);
    for (int m = 0; m < 6; ++m) {
        // u corner = hexagon vertex m, v corner = vertex m+1, w corner = the centre: counter-clockwise
        // seen from above, so du × dv points up.
        const int m1 = (m + 1) % 6;
        const glm::dvec2 P[3] = {corner[m], corner[m1], centre};
        TrianglePatch tri;
        tri.name = "dome " + std::to_string(m);
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; j <= 3 - i; ++j) {
                const int k = 3 - i - j;
                glm::dvec2 args[3];
                int n = 0;
                for (int c = 0; c < i; ++c) args[n++] = P[0];
                for (int c = 0; c < j; ++c) args[n++] = P[1];
                for (int c = 0; c < k; ++c) args[n++] = P[2];
                const glm::dvec2 xy = (double(i) * P[0] + double(j) * P[1] + double(k) * P[2]) / 3.0;
                // Key: how much of each hexagon vertex (0..5) and the centre (6) the point mixes,
                // which is the same for both triangles along a shared edge; the interior point
                // b111 also carries its triangle.
                std::array<int, 8> key{};
                key[size_t(m)] += i;
                key[size_t(m1)] += j;
                key[6] += k;
                if (i > 0 && j > 0 && k > 0) key[7] = m + 1;
                tri.idx[static_cast<size_t>(triangleSlot(i, k))] = pointFor(key, Vec3(xy.x, xy.y, blossom(args[0], args[1], args[2])));
            }
        doc.triangles.push_back(tri);
    }
    doc.tess.outer = {8, 8, 8, 8};
    doc.tess.inner = {8, 8};
    doc.camera.target = {0.0, 0.0, 0.5 * height};
    doc.camera.distance = 4.0 * radius;
    return doc;
}

}  // namespace construct
}  // namespace pw

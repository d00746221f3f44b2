// Procedural documents for tests and benchmarks: a grid of bicubic Bézier patches on one shared
// control lattice, joined across every interior edge.
#include "model_builders.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pw {

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

double waveX(double x) { return std::sin(x); }
double waveY(double y) { return std::cos(0.7 * y); }

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
    const std::vector<double> zx = c1Samples(cols, step, waveX);
    const std::vector<double> zy = c1Samples(rows, step, waveY);
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
            if (j + 1 < cols)
                doc.joins.push_back(Join{patchIndex(i, j), Edge::U1, patchIndex(i, j + 1), Edge::U0, false, continuity, 1.0});
            if (i + 1 < rows)
                doc.joins.push_back(Join{patchIndex(i, j), Edge::V1, patchIndex(i + 1, j), Edge::V0, false, continuity, 1.0});
        }
    }
    return doc;
}

}  // namespace pw

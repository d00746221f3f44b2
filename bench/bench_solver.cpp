// Drag solver on a 32x32 patch grid (1 024 patches, 9 409 points): the factorisation done once
// when a drag starts, and the per-frame projection while the dragged points move.
#include <benchmark/benchmark.h>

#include <stdexcept>

#include "core/construct/model_builders.hpp"
#include "core/solve/constraint_solver.hpp"

namespace {

constexpr int kGrid = 32;

// Lattice (r, c) of makePatchGrid(kGrid, kGrid).
uint32_t lat(int r, int c) { return static_cast<uint32_t>(r * (3 * kGrid + 1) + c); }

// An interior boundary point (on a u seam and a v seam: a four-patch corner) and a tangent point.
const std::vector<uint32_t>& dragged() {
    static const std::vector<uint32_t> sel{lat(48, 48), lat(40, 44)};
    return sel;
}

void BM_DragFactorize_Grid32(benchmark::State& state) {
    const pw::Document doc = pw::makePatchGrid(kGrid, kGrid);
    size_t rows = 0;
    for (auto _ : state) {
        pw::DragSolver solver(doc, dragged());
        rows = solver.constraintCount();
        benchmark::DoNotOptimize(rows);
    }
    state.counters["constraints"] = static_cast<double>(rows);
    state.counters["points"] = static_cast<double>(doc.points.size());
}
BENCHMARK(BM_DragFactorize_Grid32)->Unit(benchmark::kMicrosecond);

void BM_DragSolve_Grid32(benchmark::State& state) {
    pw::Document doc = pw::makePatchGrid(kGrid, kGrid);
    const pw::DragSolver solver(doc, dragged());
    const double size = pw::modelSize(doc);
    int step = 0;
    for (auto _ : state) {
        // Move both dragged points a little, back and forth, and project.
        const double d = (step++ % 20 < 10) ? 0.01 : -0.01;
        doc.points[dragged()[0]] += pw::Vec3(d, 0.5 * d, 2 * d);
        doc.points[dragged()[1]] += pw::Vec3(-d, d, d);
        solver.project(doc.points);
        benchmark::DoNotOptimize(doc.points.data());
    }
    const double residual = pw::maxConstraintResidual(doc);
    if (residual > 1e-6 * size) state.SkipWithError("constraint residual too large");
    state.counters["constraints"] = static_cast<double>(solver.constraintCount());
    state.counters["residual_rel"] = residual / size;
}
BENCHMARK(BM_DragSolve_Grid32)->Unit(benchmark::kMicrosecond);

}  // namespace

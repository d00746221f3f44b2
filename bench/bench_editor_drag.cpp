// One mouse move of an editor drag on makePatchGrid(32, 32) (1 024 patches, 9 409 points), as the
// editor does it: restore the pool to the drag-start positions, move the dragged points, project
// onto the joins (DragSolver factorised at drag start), find the points that changed since the last
// upload and write only those into the mapped float3 pool buffer. Budget: <= 1 ms CPU.
#include <benchmark/benchmark.h>

#include <vector>

#include "core/constraint_solver.hpp"
#include "core/model_builders.hpp"
#include "core/point_upload.hpp"

namespace {

constexpr int kGrid = 32;
uint32_t lat(int r, int c) { return static_cast<uint32_t>(r * (3 * kGrid + 1) + c); }

void runDrag(benchmark::State& state, const std::vector<uint32_t>& dragged) {
    pw::Document doc = pw::makePatchGrid(kGrid, kGrid);
    const std::vector<pw::Vec3> start = doc.points;
    const pw::DragSolver solver(doc, dragged);  // drag start (not timed here; see bench_solver)
    std::vector<float> gpuPool(3 * doc.points.size());  // stands in for the mapped vertex buffer
    std::vector<pw::Vec3> uploaded = start;
    std::vector<uint32_t> changed;
    size_t totalChanged = 0;
    int step = 0;
    for (auto _ : state) {
        const double d = 0.002 * (step++ % 50);  // the mouse keeps moving
        doc.points = start;
        for (uint32_t p : dragged) doc.points[p] = start[p] + pw::Vec3(d, 0.5 * d, 2.0 * d);
        solver.project(doc.points);
        pw::takeChangedPoints(uploaded, doc.points, changed);
        pw::writeFloat3(doc.points, changed, gpuPool.data());
        totalChanged += changed.size();
        benchmark::DoNotOptimize(gpuPool.data());
    }
    if (pw::maxConstraintResidual(doc) > 1e-6 * pw::modelSize(doc)) state.SkipWithError("constraint residual too large");
    state.counters["points"] = double(doc.points.size());
    state.counters["uploaded/move"] = double(totalChanged) / double(std::max<int64_t>(state.iterations(), 1));
}

// A four-patch corner (boundary point: carries its tangent neighbours).
void BM_EditorDragMove_Grid32_Corner(benchmark::State& state) { runDrag(state, {lat(48, 48)}); }
BENCHMARK(BM_EditorDragMove_Grid32_Corner)->Unit(benchmark::kMicrosecond);

// A tangent point next to a seam (mirrors its partner).
void BM_EditorDragMove_Grid32_Tangent(benchmark::State& state) { runDrag(state, {lat(40, 44)}); }
BENCHMARK(BM_EditorDragMove_Grid32_Tangent)->Unit(benchmark::kMicrosecond);

// A box selection of 16 points around a corner.
void BM_EditorDragMove_Grid32_Box16(benchmark::State& state) {
    std::vector<uint32_t> sel;
    for (int r = 47; r <= 50; ++r)
        for (int c = 47; c <= 50; ++c) sel.push_back(lat(r, c));
    runDrag(state, sel);
}
BENCHMARK(BM_EditorDragMove_Grid32_Box16)->Unit(benchmark::kMicrosecond);

}  // namespace

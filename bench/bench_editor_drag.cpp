// One mouse move of an editor drag (or R rotation) on makePatchGrid(32, 32) (1 024 patches, 9 409 points), or on
// data/rounded_box.patchwork (corners held by leaning seams), through
// the editor's own DragController (core/edit/drag_controller.hpp): the dragged points follow the mouse
// on the view plane, the solver (factorised at drag start) holds the joins, and only the points that
// changed since the last move are written into the mapped float3 pool buffer. Budget: <= 1 ms CPU.
#include <benchmark/benchmark.h>

#include <vector>

#include "core/base/point_upload.hpp"
#include "core/construct/model_builders.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/io/document_io.hpp"
#include "core/model/camera_math.hpp"

namespace {

constexpr int kGrid = 32;
uint32_t lat(int r, int c) { return static_cast<uint32_t>(r * (3 * kGrid + 1) + c); }

void runDragOn(benchmark::State& state, pw::Document doc, const std::vector<uint32_t>& dragged, pw::TransformKind kind,
               pw::SoftSelection soft) {
    pw::DragView view;
    view.width = 1280;
    view.height = 720;
    view.camera = pw::frameBounds(view.camera, pw::computeBounds(doc.points), double(view.width) / view.height);
    pw::Selection sel;
    sel.points = dragged;
    pw::DragController drag;
    const double x0 = 640, y0 = 360;
    const pw::Vec3 pivot = pw::transformPivot(doc, sel, dragged, pw::PivotMode::Median, pw::Vec3(0.0));
    pw::TransformStart start{dragged, pivot, kind, true};
    start.soft = soft;
    if (!drag.begin(doc, start, view, x0 + 40.0, y0)) return state.SkipWithError("the drag did not start");
    std::vector<float> gpuPool(4 * doc.points.size());  // stands in for the mapped vertex buffer
    size_t totalChanged = 0;
    int step = 0;
    for (auto _ : state) {
        const double d = 2.0 * (step++ % 50);  // the mouse keeps moving
        if (!drag.update(doc, view, x0 + d, y0 - 0.5 * d, false)) return state.SkipWithError("the mouse ray missed the drag plane");
        pw::writePoolPositions(doc.points, drag.changed(), gpuPool.data());
        totalChanged += drag.changed().size();
        benchmark::DoNotOptimize(gpuPool.data());
    }
    if (pw::maxConstraintResidual(doc) > 1e-6 * pw::modelSize(doc)) state.SkipWithError("constraint residual too large");
    if (!drag.projection().ok()) state.SkipWithError("the joins conflicted");
    state.counters["points"] = double(doc.points.size());
    state.counters["soft points"] = double(drag.softCount());
    state.counters["uploaded/move"] = double(totalChanged) / double(std::max<int64_t>(state.iterations(), 1));
}

void runDrag(benchmark::State& state, const std::vector<uint32_t>& dragged, pw::TransformKind kind = pw::TransformKind::Move,
             pw::Continuity joins = pw::Continuity::C1, pw::SoftSelection soft = {}) {
    runDragOn(state, pw::makePatchGrid(kGrid, kGrid, joins), dragged, kind, soft);
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

// A whole lattice row (97 points across 32 patches, boundary row of a seam): the case.
std::vector<uint32_t> wholeRow(int r) {
    std::vector<uint32_t> sel;
    for (int c = 0; c <= 3 * kGrid; ++c) sel.push_back(lat(r, c));
    return sel;
}
void BM_EditorDragMove_Grid32_Row(benchmark::State& state) { runDrag(state, wholeRow(48)); }
BENCHMARK(BM_EditorDragMove_Grid32_Row)->Unit(benchmark::kMicrosecond);
// The same row rotated (R) about its median.
void BM_EditorDragRotate_Grid32_Row(benchmark::State& state) { runDrag(state, wholeRow(48), pw::TransformKind::Rotate); }
BENCHMARK(BM_EditorDragRotate_Grid32_Row)->Unit(benchmark::kMicrosecond);

// C2 joins everywhere (issue 21): the β-constraints couple three rows on each side of every seam,
// so the whole grid is one component of the solve. Budget: <= 1 ms per mouse event.
void BM_EditorDragMove_Grid32C2_Corner(benchmark::State& state) {
    runDrag(state, {lat(48, 48)}, pw::TransformKind::Move, pw::Continuity::C2);
}
BENCHMARK(BM_EditorDragMove_Grid32C2_Corner)->Unit(benchmark::kMicrosecond);
void BM_EditorDragMove_Grid32C2_Tangent(benchmark::State& state) {
    runDrag(state, {lat(40, 44)}, pw::TransformKind::Move, pw::Continuity::C2);
}
BENCHMARK(BM_EditorDragMove_Grid32C2_Tangent)->Unit(benchmark::kMicrosecond);
void BM_EditorDragMove_Grid32C2_Row(benchmark::State& state) { runDrag(state, wholeRow(48), pw::TransformKind::Move, pw::Continuity::C2); }
BENCHMARK(BM_EditorDragMove_Grid32C2_Row)->Unit(benchmark::kMicrosecond);

// Soft selection (issue 40): the four-patch corner with the points around it within 1 and 3 model
// units along the nets (a patch is 1 unit), smooth falloff, the joins around them held too.
// Budget: <= 1 ms per mouse event.
void BM_EditorDragMove_Grid32_SoftCorner_R1(benchmark::State& state) {
    runDrag(state, {lat(48, 48)}, pw::TransformKind::Move, pw::Continuity::C1, pw::SoftSelection{true, 1.0, pw::Falloff::Smooth});
}
BENCHMARK(BM_EditorDragMove_Grid32_SoftCorner_R1)->Unit(benchmark::kMicrosecond);
void BM_EditorDragMove_Grid32_SoftCorner_R3(benchmark::State& state) {
    runDrag(state, {lat(48, 48)}, pw::TransformKind::Move, pw::Continuity::C1, pw::SoftSelection{true, 3.0, pw::Falloff::Smooth});
}
BENCHMARK(BM_EditorDragMove_Grid32_SoftCorner_R3)->Unit(benchmark::kMicrosecond);

}  // namespace

// Corners of three patches held G1 by leaning seams (issue 40): data/rounded_box.patchwork, 54
// patches, 108 G1/C1 joins (24 leaning). The centre of a filled corner, a face corner (three
// corners' seams in the solver's region), and the centre with soft selection reaching the corner's
// neighbours.
pw::Document roundedBox() { return pw::loadDocument(PATCHWORK_DATA_DIR "/rounded_box.patchwork"); }
uint32_t cornerCentre(const pw::Document& d) { return d.patches[30].idx[15]; }
void BM_EditorDragMove_RoundedBox_CornerCentre(benchmark::State& state) {
    const pw::Document doc = roundedBox();
    runDragOn(state, doc, {cornerCentre(doc)}, pw::TransformKind::Move, {});
}
BENCHMARK(BM_EditorDragMove_RoundedBox_CornerCentre)->Unit(benchmark::kMicrosecond);
void BM_EditorDragMove_RoundedBox_FaceCorner(benchmark::State& state) {
    const pw::Document doc = roundedBox();
    runDragOn(state, doc, {doc.patches[0].idx[0]}, pw::TransformKind::Move, {});
}
BENCHMARK(BM_EditorDragMove_RoundedBox_FaceCorner)->Unit(benchmark::kMicrosecond);
void BM_EditorDragMove_RoundedBox_SoftCentre(benchmark::State& state) {
    const pw::Document doc = roundedBox();
    runDragOn(state, doc, {cornerCentre(doc)}, pw::TransformKind::Move, pw::SoftSelection{true, 0.4, pw::Falloff::Smooth});
}
BENCHMARK(BM_EditorDragMove_RoundedBox_SoftCentre)->Unit(benchmark::kMicrosecond);

// A 4-sided fill whose sides' tangent ratios disagree (issue 40): data/fitted_fill.patchwork, a
// bent ring of uneven widths filled with fitted joins, which a drag measures by angle as well as
// holding their rows (only those whose patches the drag moved). A hole corner and the fill's centre.
void BM_EditorDragMove_FittedFill_HoleCorner(benchmark::State& state) {
    const pw::Document doc = pw::loadDocument(PATCHWORK_DATA_DIR "/fitted_fill.patchwork");
    runDragOn(state, doc, {doc.patches[14].idx[0]}, pw::TransformKind::Move, {});
}
BENCHMARK(BM_EditorDragMove_FittedFill_HoleCorner)->Unit(benchmark::kMicrosecond);
void BM_EditorDragMove_FittedFill_Centre(benchmark::State& state) {
    const pw::Document doc = pw::loadDocument(PATCHWORK_DATA_DIR "/fitted_fill.patchwork");
    runDragOn(state, doc, {doc.patches[12].idx[15]}, pw::TransformKind::Move, {});
}
BENCHMARK(BM_EditorDragMove_FittedFill_Centre)->Unit(benchmark::kMicrosecond);

// One mouse move of a drag of an input curve of a live construction (issue 39) with a 100-patch
// result, through the editor's DragController: the curve point follows the mouse, the surface is
// made again from the curve (core/construct/constructions.hpp), the solver holds the joins, and the
// changed points are written into the mapped pool buffer. Target: <= 2 ms per mouse event.
// The same drag of a baked copy (no construction to re-run) is the floor it is compared against;
// BM_Rerun_* time the re-run alone.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "core/base/point_upload.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/constructions.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/edit/edit_session.hpp"
#include "core/model/camera_math.hpp"

namespace {

class NoHost final : public pw::CommandHost {
public:
    void write(const pw::Document&, const std::string&) override {}
};

enum class Kind { Revolve, Loft, Network };

// A vase: a 25-segment profile through 26 points revolved 360° (25 × 4 = 100 patches), a loft
// through 26 circles (25 spans × 4 quarters = 100 patches), or a shell through an 11 × 11 curve
// network (10 × 10 cells = 100 patches).
pw::Document build(Kind kind) {
    pw::EditSession s;
    NoHost host;
    const pw::CommandTable table = pw::makeCommandTable();
    std::string script;
    const auto height = [](int x, int y) { return std::to_string(0.5 * std::sin(0.6 * x) * std::cos(0.4 * y)); };
    if (kind == Kind::Network) {
        for (int y = 0; y <= 10; ++y) {
            script += "curve-through";
            for (int x = 0; x <= 10; ++x) script += " " + std::to_string(x) + "," + std::to_string(y) + "," + height(x, y);
            script += "; ";
        }
        for (int x = 0; x <= 10; ++x) {
            script += "curve-through";
            for (int y = 0; y <= 10; ++y) script += " " + std::to_string(x) + "," + std::to_string(y) + "," + height(x, y);
            script += "; ";
        }
        script += "network";
        for (int c = 0; c <= 10; ++c) script += " c" + std::to_string(c);
        script += " /";
        for (int c = 11; c <= 21; ++c) script += " c" + std::to_string(c);
    } else if (kind == Kind::Loft) {
        std::string sections;
        for (int i = 0; i <= 25; ++i) {
            script += "cursor 0 0 " + std::to_string(0.2 * i) + "; add-circle " + std::to_string(1.0 + 0.3 * std::sin(0.5 * i)) + "; ";
            sections += " c" + std::to_string(i);
        }
        script += "loft" + sections;
    } else {
        script = "curve-through";
        for (int i = 0; i <= 25; ++i) script += " " + std::to_string(1.0 + 0.3 * std::sin(0.5 * i)) + ",0," + std::to_string(0.2 * i);
        script += "; cursor 0 0 0; revolve c0 Z";
    }
    table.runScript(s, host, script, "bench");
    return s.doc;
}

void runDrag(benchmark::State& state, Kind kind, bool baked) {
    pw::Document doc = build(kind);
    if (doc.patches.size() != 100) return state.SkipWithError("expected 100 patches");
    const bool loft = kind == Kind::Loft;
    // Mid-height: a profile point, a whole section, or the network's middle crossing (both curves' point).
    const uint32_t dragged = loft ? doc.curves[12].idx[0] : kind == Kind::Network ? doc.curves[5].idx[15] : doc.curves[0].idx[37];
    if (baked) doc.constructions.clear();
    pw::DragView view;
    view.width = 1280;
    view.height = 720;
    view.camera = pw::frameBounds(view.camera, pw::computeBounds(doc.points), double(view.width) / view.height);
    pw::DragController drag;
    const double x0 = 640, y0 = 360;
    const std::vector<uint32_t> moved = loft ? doc.curves[12].idx : std::vector<uint32_t>{dragged};
    if (!drag.begin(doc, pw::TransformStart{moved, doc.points[dragged], pw::TransformKind::Move, true}, view, x0, y0))
        return state.SkipWithError(("the drag did not start: " + drag.refusal()).c_str());
    std::vector<float> gpuPool(4 * doc.points.size());
    size_t totalChanged = 0;
    int step = 0;
    for (auto _ : state) {
        const double d = 2.0 * (step++ % 50);
        if (!drag.update(doc, view, x0 + d, y0 - 0.5 * d, false)) return state.SkipWithError("the mouse ray missed the drag plane");
        pw::writePoolPositions(doc.points, drag.changed(), gpuPool.data());
        totalChanged += drag.changed().size();
        benchmark::DoNotOptimize(gpuPool.data());
    }
    if (pw::maxConstraintResidual(doc) > 1e-6 * pw::modelSize(doc)) state.SkipWithError("constraint residual too large");
    state.counters["patches"] = double(doc.patches.size());
    state.counters["uploaded/move"] = double(totalChanged) / double(std::max<int64_t>(state.iterations(), 1));
}

void BM_DragProfile_Revolve100(benchmark::State& state) { runDrag(state, Kind::Revolve, false); }
BENCHMARK(BM_DragProfile_Revolve100)->Unit(benchmark::kMicrosecond);
void BM_DragProfile_Revolve100_BakedFloor(benchmark::State& state) { runDrag(state, Kind::Revolve, true); }
BENCHMARK(BM_DragProfile_Revolve100_BakedFloor)->Unit(benchmark::kMicrosecond);
void BM_DragSection_Loft100(benchmark::State& state) { runDrag(state, Kind::Loft, false); }
BENCHMARK(BM_DragSection_Loft100)->Unit(benchmark::kMicrosecond);
void BM_DragSection_Loft100_BakedFloor(benchmark::State& state) { runDrag(state, Kind::Loft, true); }
BENCHMARK(BM_DragSection_Loft100_BakedFloor)->Unit(benchmark::kMicrosecond);
void BM_DragCrossing_Network100(benchmark::State& state) { runDrag(state, Kind::Network, false); }
BENCHMARK(BM_DragCrossing_Network100)->Unit(benchmark::kMicrosecond);
void BM_DragCrossing_Network100_BakedFloor(benchmark::State& state) { runDrag(state, Kind::Network, true); }
BENCHMARK(BM_DragCrossing_Network100_BakedFloor)->Unit(benchmark::kMicrosecond);

void runRerun(benchmark::State& state, Kind kind) {
    pw::Document doc = build(kind);
    for (auto _ : state) {
        const pw::RerunReport r = pw::rerunConstructions(doc);
        benchmark::DoNotOptimize(r.moved.data());
    }
}
void BM_Rerun_Revolve100(benchmark::State& state) { runRerun(state, Kind::Revolve); }
BENCHMARK(BM_Rerun_Revolve100)->Unit(benchmark::kMicrosecond);
void BM_Rerun_Loft100(benchmark::State& state) { runRerun(state, Kind::Loft); }
BENCHMARK(BM_Rerun_Loft100)->Unit(benchmark::kMicrosecond);
void BM_Rerun_Network100(benchmark::State& state) { runRerun(state, Kind::Network); }
BENCHMARK(BM_Rerun_Network100)->Unit(benchmark::kMicrosecond);

}  // namespace

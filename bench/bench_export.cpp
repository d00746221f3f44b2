// glTF export of a C1-joined 32×32 patch grid at level 32 (1 024 windows, ~2.1 M triangles) to .glb:
// time per export and peak memory; the teapot at level 64 in each format (glb, gltf, OBJ, STEP),
// in memory, against its bare CPU tessellation (the floor every mesh format pays); and CPU
// evaluation throughput (grid points with normals, single random points). Targets: export ≤ 1.5 s,
// ≥ 20 M grid points with normals per second per core.
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <vector>

#include "core/construct/model_builders.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/io/document_io.hpp"
#include "core/io/gltf_export.hpp"
#include "core/io/obj_export.hpp"
#include "core/io/step_export.hpp"
#include "core/mesh/mesh_tessellate.hpp"

namespace {

double peakRssMiB() {
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    return static_cast<double>(ru.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

// The resident set now (not the peak), so that the baseline stays right when the benchmark is
// repeated in one process.
double currentRssMiB() {
    long pages = 0, resident = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Registered first so that the baseline is the process before any other benchmark grew it.
void BM_ExportGlbGrid32x32Level32(benchmark::State& state) {
    const pw::Document doc = pw::makePatchGrid(32, 32);
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("patchwork-bench-export-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path out = dir / "grid32.glb";
    pw::ExportOptions options;
    options.level = 32;
    const double baseline = currentRssMiB();
    pw::GltfExportStats stats;
    double firstPeak = 0;
    for (auto _ : state) {
        stats = pw::exportGltfWithStats(doc, out, options);
        benchmark::ClobberMemory();
        if (firstPeak == 0) firstPeak = peakRssMiB();
    }
    const double peak = peakRssMiB();
    // One export's own peak: later ones start from what the allocator kept of the earlier ones.
    state.counters["first_rss_increase_MiB"] = firstPeak - baseline;
    state.counters["peak_rss_MiB"] = peak;
    state.counters["rss_increase_MiB"] = peak - baseline;  // peak during the exports over the RSS before them
    state.counters["baseline_rss_MiB"] = baseline;
    state.counters["triangles"] = static_cast<double>(stats.triangles);
    state.counters["vertices"] = static_cast<double>(stats.vertices);
    state.counters["file_MiB"] = static_cast<double>(stats.bytes) / (1024.0 * 1024.0);
    std::filesystem::remove_all(dir);
}
BENCHMARK(BM_ExportGlbGrid32x32Level32)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);

struct TeapotNets {
    std::vector<pw::Net16> nets;
    std::vector<std::array<uint32_t, 16>> idx;
};

TeapotNets teapotNets() {
    const pw::Document doc = pw::builtinTeapot();
    TeapotNets t;
    for (const pw::PatchInstance& inst : pw::expandPatches(doc)) {
        t.nets.push_back(pw::gatherNet(doc, inst.idx));
        t.idx.push_back(inst.idx);
    }
    return t;
}

// The teapot at level 64 (32 windows, 261 632 triangles), in memory (no disk).
enum class Format { Tessellate, Glb, Gltf, Obj, Step };
void BM_TeapotLevel64(benchmark::State& state) {
    const pw::Document doc = pw::builtinTeapot();
    const auto format = static_cast<Format>(state.range(0));
    size_t bytes = 0;
    for (auto _ : state) {
        switch (format) {
            case Format::Tessellate:
                bytes = pw::tessellateDocument(doc, 64).indices.size() * 4;
                break;
            case Format::Glb:
                bytes = pw::exportGltfBytes(doc, true, {64, pw::MeshGrouping::Surfaces, false}).size();
                break;
            case Format::Gltf:
                bytes = pw::exportGltfBytes(doc, false, {64, pw::MeshGrouping::Surfaces, false}).size();
                break;
            case Format::Obj:
                bytes = pw::exportObjText(doc, 64, "teapot.mtl").obj.size();
                break;
            case Format::Step:
                bytes = pw::exportStepText(doc, {}).size();
                break;
        }
        benchmark::DoNotOptimize(bytes);
    }
    static const char* names[] = {"tessellate only (floor)", "glb", "gltf", "obj", "step (exact, no level)"};
    state.SetLabel(names[state.range(0)]);
    state.counters["output_MiB"] = static_cast<double>(bytes) / (1024.0 * 1024.0);
}
BENCHMARK(BM_TeapotLevel64)->DenseRange(0, 4)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

// evaluateGrid on the 32 teapot patches at level 64: 65 × 65 points with derivatives and normals each.
void BM_EvaluateGrid(benchmark::State& state) {
    const TeapotNets t = teapotNets();
    const int level = static_cast<int>(state.range(0));
    const pw::GridWeights weights = pw::makeGridWeights(pw::Basis::Bezier, 0.5, level, level);
    std::vector<pw::SurfacePoint> out;
    size_t points = 0;
    for (auto _ : state) {
        for (size_t p = 0; p < t.nets.size(); ++p) {
            pw::evaluateGrid(t.nets[p], t.idx[p], weights, out);
            benchmark::DoNotOptimize(out.data());
            points += out.size();
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<int64_t>(points));
}
BENCHMARK(BM_EvaluateGrid)->Arg(64)->Unit(benchmark::kMicrosecond);

// evaluateNet at random (u, v) on random teapot patches: one point with derivatives and normal.
void BM_EvaluateNet(benchmark::State& state) {
    const TeapotNets t = teapotNets();
    struct Sample {
        uint32_t patch;
        double u, v;
    };
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Sample> samples(4096);
    for (Sample& s : samples) s = {static_cast<uint32_t>(rng() % t.nets.size()), unit(rng), unit(rng)};
    size_t i = 0;
    for (auto _ : state) {
        const Sample& s = samples[i++ & 4095];
        const pw::SurfacePoint sp = pw::evaluateNet(t.nets[s.patch], pw::Basis::Bezier, 0.5, s.u, s.v);
        benchmark::DoNotOptimize(sp);
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_EvaluateNet);

}  // namespace

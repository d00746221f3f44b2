// Loading a document of independent patches (issue 43): a .bpt of n×n patches on a grid, each with
// its own copies of its corner and edge points, parsed in memory — points merged, joins detected
// (every shared edge C1), orientation checked. Reports the time against the patch count with
// Google Benchmark's complexity fit: it must stay near n log n (it was quadratic: findJoin per
// edge and the model's size per join candidate).
#include <benchmark/benchmark.h>

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/base/errors.hpp"
#include "core/io/bpt_format.hpp"

namespace {

// n × n unit patches on a slightly waved grid, as text.
std::string gridBpt(int n) {
    std::string text = std::to_string(n * n) + "\n";
    char buf[96];
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            text += "3 3\n";
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) {
                    const double x = b + j / 3.0, y = a + i / 3.0;
                    std::snprintf(buf, sizeof buf, "%.6f %.6f %.6f\n", x, y, 0.05 * (x - 2.0 * int(x / 2.0)));
                    text += buf;
                }
        }
    return text;
}

void BM_LoadBptGrid(benchmark::State& state) {
    const int n = int(state.range(0));
    const std::string text = gridBpt(n);
    size_t joins = 0;
    for (auto _ : state) {
        const pw::Document doc = pw::parseBpt(text, "grid.bpt");
        joins = doc.joins.size();
        benchmark::DoNotOptimize(joins);
    }
    state.SetComplexityN(int64_t(n) * n);
    state.counters["patches"] = double(n) * n;
    state.counters["joins"] = double(joins);
    state.counters["patches_per_s"] = benchmark::Counter(double(n) * n, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_LoadBptGrid)->Arg(32)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->Complexity(benchmark::oNLogN);

// Refusing a file of a million patches (issue 44: it took 30 s and 2.4 GB, then failed with
// bad_alloc when the patches were identical): the count on its first line already lists more points
// than the limit, so loadBpt refuses after reading the file's first 4 KiB. Arg 1: identical patches,
// 0: distinct ones on a grid — the same cost, whatever follows the header.
void BM_RefuseMillionPatchBpt(benchmark::State& state) {
    const bool identical = state.range(0) == 1;
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("patchwork_bench_" + std::to_string(getpid()) + (identical ? "_same" : "_grid") + ".bpt");
    {
        std::ofstream out(path, std::ios::binary);
        constexpr int kPatches = 1'000'000;
        out << kPatches << "\n";
        std::string patch;
        char buf[96];
        for (int k = 0; k < kPatches; ++k) {
            const int ox = identical ? 0 : 3 * (k % 1000), oy = identical ? 0 : 3 * (k / 1000);
            patch = "3 3\n";
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) {
                    std::snprintf(buf, sizeof buf, "%d %d 0\n", ox + i, oy + j);
                    patch += buf;
                }
            out << patch;
        }
    }
    const double megabytes = double(std::filesystem::file_size(path)) / 1e6;
    bool refused = false;
    for (auto _ : state) {
        try {
            (void)pw::loadBpt(path);
        } catch (const pw::InputError&) {
            refused = true;
        }
    }
    std::filesystem::remove(path);
    if (!refused) state.SkipWithError("a million-patch .bpt was not refused");
    state.counters["file_MB"] = megabytes;
}
BENCHMARK(BM_RefuseMillionPatchBpt)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

}  // namespace

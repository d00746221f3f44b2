// Loading a document of independent patches (issue 43): a .bpt of n×n patches on a grid, each with
// its own copies of its corner and edge points, parsed in memory — points merged, joins detected
// (every shared edge C1), orientation checked. Reports the time against the patch count with
// Google Benchmark's complexity fit: it must stay near n log n (it was quadratic: findJoin per
// edge and the model's size per join candidate).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

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

}  // namespace

// Whole `patchwork` commands as a person runs them, timed from launch to exit (loading the program,
// the Vulkan driver and the document included): the teapot at level 64 exported to .glb plainly
// (CPU tessellation) and as displayed (lavapipe's tessellator, read back and welded), the two
// alternating in each iteration so that a drift of the machine falls on both (issue 43: as
// displayed ≤ 3× plain). Run e.g.
//   build/bench/bench_commands --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;

// Runs the patchwork binary with `args` (output to /dev/null); its wall time in seconds. Throws
// when it does not exit 0.
double run(const std::vector<std::string>& args) {
    std::vector<std::string> all{PATCHWORK_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", 1 /*O_WRONLY*/, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", 1, 0);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid = 0;
    const int err = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (err != 0) throw std::runtime_error("cannot start " + all[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw std::runtime_error(all[0] + " " + all[1] + " failed");
    return s;
}

// A folder of its own under the temporary directory, removed at exit.
struct Scratch {
    fs::path dir;
    Scratch() {
        std::string tmpl = (fs::temp_directory_path() / "patchwork-bench-XXXXXX").string();
        if (!mkdtemp(tmpl.data())) throw std::runtime_error("cannot make a temporary folder");
        dir = tmpl;
    }
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

void BM_ExportTeapot64AsDisplayedOverPlain(benchmark::State& state) {
    const Scratch scratch;
    const std::string doc = (scratch.dir / "teapot64.patchwork").string(), plain = (scratch.dir / "plain.glb").string(),
                      shown = (scratch.dir / "shown.glb").string();
    run({"edit", PATCHWORK_DATA_DIR "/teapot.bpt", "-o", doc, "-q", "-c", "tess 64"});
    run({"export", doc, "-o", shown, "--as-displayed"});  // warm: the driver's shader caches, the page cache
    double plainSum = 0, shownSum = 0;
    for (auto _ : state) {
        plainSum += run({"export", doc, "-o", plain, "--no-as-displayed"});
        shownSum += run({"export", doc, "-o", shown, "--as-displayed"});
    }
    const double n = double(state.iterations());
    state.counters["plain_s"] = plainSum / n;
    state.counters["displayed_s"] = shownSum / n;
    state.counters["ratio"] = shownSum / plainSum;
}
BENCHMARK(BM_ExportTeapot64AsDisplayedOverPlain)->Iterations(5)->Unit(benchmark::kMillisecond);

}  // namespace

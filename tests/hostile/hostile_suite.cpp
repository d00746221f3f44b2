// `hostile_suite`: the hostile-input suite (issue 44, item 4). Generates the files of
// hostile_files.hpp and runs each through the command line — `info`, `convert` to .patchwork and
// `export` to .glb — every run in its own process under a wall-clock and an address-space limit.
// Reports, per reader, what the runs did and every problem: a crash (a signal, or an exit other
// than 0 and 2), a hang (past the time limit), a silent success (exit 0 on a file built to be
// invalid), an unclear refusal (not one line naming the file), a partial output (exit 2 with
// something left in the output folder) and an output that does not reopen. Exits 1 when there is
// any problem. scripts/hostile.sh runs all of it; ctest runs a fixed sample (--stride).
//
//   hostile_suite --bin build/app/patchwork --repo . [--stride N] [--seconds 10] [--megabytes 1024]
//                 [--mutations 120] [--large] [--keep DIR]
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/io/document_io.hpp"
#include "hostile/hostile_files.hpp"

namespace fs = std::filesystem;
using pw::hostile::HostileFile;

namespace {

struct Options {
    fs::path bin, repo, keep;
    size_t stride = 1;
    double seconds = 10.0;
    size_t megabytes = 1024;
    int mutations = 120;
    bool large = false;
};

struct Run {
    int exitCode = -1;  // -1: killed by a signal
    int signal = 0;
    bool timedOut = false;
    double seconds = 0.0;
    long maxRssKb = 0;
    std::string output;  // stdout and stderr
};

// The resident memory of a running process (VmRSS, kB; 0 once it has exited, or before it runs
// `bin`), sampled while it runs (the largest sample is reported): wait4's ru_maxrss and VmHWM would
// also count this process's memory, which the fork copies until the exec.
long peakKb(pid_t pid, const fs::path& canonicalBin) {
    std::error_code ec;
    if (fs::read_symlink("/proc/" + std::to_string(pid) + "/exe", ec) != canonicalBin) return 0;
    std::FILE* f = std::fopen(("/proc/" + std::to_string(pid) + "/status").c_str(), "r");
    if (!f) return 0;
    long kb = 0;
    char line[256];
    while (std::fgets(line, sizeof line, f))
        if (std::sscanf(line, "VmRSS: %ld kB", &kb) == 1) break;
    std::fclose(f);
    return kb;
}

// Runs argv with stdout and stderr into `log`, under the limits; waits at most `seconds`.
Run runLimited(const std::vector<std::string>& argv, const fs::path& log, const Options& opt) {
    Run r;
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        const rlimit as{opt.megabytes << 20, opt.megabytes << 20};
        ::setrlimit(RLIMIT_AS, &as);
        std::vector<char*> args;
        for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        ::execv(args[0], args.data());
        ::_exit(127);
    }
    int status = 0;
    for (;;) {
        // Before reaping, while /proc still shows the process (a zombie shows no memory).
        r.maxRssKb = std::max(r.maxRssKb, peakKb(pid, opt.bin));
        siginfo_t info{};
        if (::waitid(P_PID, id_t(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid) {
            ::waitpid(pid, &status, 0);
            break;
        }
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > opt.seconds && !r.timedOut) {
            r.timedOut = true;
            ::kill(pid, SIGKILL);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    try {
        r.output = pw::readFileLimited(log);
    } catch (const std::exception&) {
    }
    return r;
}

struct Tally {
    int files = 0, runs = 0, exit0 = 0, exit2 = 0;
    std::map<std::string, int> problems;
    double slowest = 0.0;
    long largestKb = 0;
};

std::string oneLine(std::string s) {
    std::replace(s.begin(), s.end(), '\n', '|');
    return s.size() > 300 ? s.substr(0, 300) + "..." : s;
}

int usage(const char* why) {
    std::fprintf(stderr,
                 "hostile_suite: %s\nusage: hostile_suite --bin PATCHWORK --repo SOURCE_TREE [--stride N] [--seconds S] "
                 "[--megabytes MB] [--mutations N] [--large] [--keep DIR]\n",
                 why);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
        if (a == "--bin")
            opt.bin = value();
        else if (a == "--repo")
            opt.repo = value();
        else if (a == "--keep")
            opt.keep = value();
        else if (a == "--stride")
            opt.stride = std::max<size_t>(1, std::strtoul(value().c_str(), nullptr, 10));
        else if (a == "--seconds")
            opt.seconds = std::strtod(value().c_str(), nullptr);
        else if (a == "--megabytes")
            opt.megabytes = std::strtoul(value().c_str(), nullptr, 10);
        else if (a == "--mutations")
            opt.mutations = std::atoi(value().c_str());
        else if (a == "--large")
            opt.large = true;
        else
            return usage(("unknown argument " + a).c_str());
    }
    if (opt.bin.empty() || opt.repo.empty()) return usage("--bin and --repo are required");
    std::error_code binError;
    opt.bin = fs::canonical(opt.bin, binError);  // once: the runs' memory is sampled by comparing /proc/PID/exe with it
    if (binError) return usage(("--bin: " + binError.message()).c_str());
    if (!(opt.seconds > 0) || opt.megabytes == 0 || opt.mutations < 0) return usage("limits must be positive");

    const fs::path root = opt.keep.empty() ? fs::temp_directory_path() / ("patchwork-hostile-" + std::to_string(::getpid())) : opt.keep;
    const fs::path in = root / "in", out = root / "out";
    fs::create_directories(in);
    fs::create_directories(out);
    const std::vector<HostileFile> all =
        pw::hostile::generateHostileFiles(in, {.repository = opt.repo, .mutationsPerSeed = opt.mutations, .cad = true, .large = opt.large});

    std::map<std::string, Tally> byReader;
    int problems = 0;
    size_t chosen = 0;
    for (size_t i = 0; i < all.size(); ++i) {
        const HostileFile& h = all[i];
        // A fixed sample: every stride-th file, and every file built to be refused (cheap, and the
        // cases the issue names).
        if (i % opt.stride != 0 && !h.mustRefuse) continue;
        ++chosen;
        std::string reader = h.file.extension().string();
        if (h.large) reader += " (large)";
        Tally& t = byReader[reader];
        ++t.files;
        for (const std::string verb : {"info", "convert", "export"}) {
            const fs::path target = out / (verb == std::string("export") ? "out.glb" : "out.patchwork");
            std::vector<std::string> args = {opt.bin.string(), verb, h.file.string()};
            if (verb == std::string("convert")) args.push_back(target.string());
            if (verb == std::string("export")) args.insert(args.end(), {"--tess", "2", "-o", target.string()});
            const Run r = runLimited(args, root / "log.txt", opt);
            ++t.runs;
            t.slowest = std::max(t.slowest, r.seconds);
            t.largestKb = std::max(t.largestKb, r.maxRssKb);
            std::string problem;
            if (r.timedOut) {
                problem = "hang";
            } else if (r.signal != 0) {
                problem = "crash";
            } else if (r.exitCode != 0 && r.exitCode != 2) {
                problem = "crash";
            } else if (r.exitCode == 0) {
                ++t.exit0;
                if (h.mustRefuse) {
                    problem = "silent success";
                } else if (verb != std::string("info")) {
                    try {
                        (void)pw::loadDocument(target);
                    } catch (const std::exception& e) {
                        problem = "output does not reopen";
                    }
                }
            } else {
                ++t.exit2;
                const size_t lines = size_t(std::count(r.output.begin(), r.output.end(), '\n'));
                // info prints its report to stdout before nothing: a refusal is the one line.
                if (lines != 1 || r.output.find(h.file.filename().string()) == std::string::npos) problem = "unclear refusal";
                std::error_code ec;
                for (const auto& e : fs::directory_iterator(out, ec)) {
                    (void)e;
                    problem = "partial output";
                }
            }
            if (!problem.empty()) {
                ++t.problems[problem];
                ++problems;
                std::printf("%s: %s %s: exit %d signal %d %.1f s %ld MB: %s\n", problem.c_str(), verb.c_str(), h.file.filename().c_str(),
                            r.exitCode, r.signal, r.seconds, r.maxRssKb / 1024, oneLine(r.output).c_str());
            }
            std::error_code ec;
            for (const auto& e : fs::directory_iterator(out, ec)) fs::remove_all(e.path(), ec);
        }
    }
    std::printf("\nhostile suite: %zu of %zu files, each through info, convert and export (limits %.0f s, %zu MB)\n", chosen, all.size(),
                opt.seconds, opt.megabytes);
    std::printf("%-18s %6s %6s %7s %7s %9s %8s  %s\n", "reader", "files", "runs", "exit 0", "exit 2", "slowest", "peak", "problems");
    for (const auto& [reader, t] : byReader) {
        std::string list;
        for (const auto& [what, count] : t.problems) list += (list.empty() ? "" : ", ") + std::to_string(count) + " " + what;
        std::printf("%-18s %6d %6d %7d %7d %7.2f s %5ld MB  %s\n", reader.c_str(), t.files, t.runs, t.exit0, t.exit2, t.slowest,
                    t.largestKb / 1024, list.empty() ? "none" : list.c_str());
    }
    std::printf("problems: %d (crashes, hangs, silent successes, unclear refusals, partial outputs, outputs that do not reopen)\n",
                problems);
    if (opt.keep.empty()) fs::remove_all(root);
    return problems == 0 ? 0 : 1;
}

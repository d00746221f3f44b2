#include "core/io/bounded_child.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>

namespace pw {
inline namespace io {

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kLimitAddressSpace = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kLimitAddressSpace = false;
#else
constexpr bool kLimitAddressSpace = true;
#endif
#else
constexpr bool kLimitAddressSpace = true;
#endif

// The process's address space now, in bytes (/proc/self/statm's first field, in pages).
std::size_t addressSpaceNow() {
    long pages = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
        std::fclose(f);
    }
    return std::size_t(pages) * std::size_t(::sysconf(_SC_PAGESIZE));
}

bool writeAll(int fd, const std::string& s) {
    size_t done = 0;
    while (done < s.size()) {
        const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += size_t(n);
    }
    return true;
}

// The processor time a child has used so far, in seconds (/proc/PID/stat's utime + stime, all its
// threads); -1 when it cannot be read.
double cpuSecondsOf(pid_t pid) {
    char path[64];
    std::snprintf(path, sizeof path, "/proc/%d/stat", int(pid));
    std::FILE* f = std::fopen(path, "r");
    if (!f) return -1.0;
    char line[1024];
    const size_t n = std::fread(line, 1, sizeof line - 1, f);
    std::fclose(f);
    line[n] = 0;
    const char* rest = std::strrchr(line, ')');  // the command name may hold spaces and parentheses
    if (!rest) return -1.0;
    unsigned long long ticks[2] = {0, 0};
    // After ") ": state (field 3) … utime (field 14), stime (field 15).
    if (std::sscanf(rest + 1, " %*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu", &ticks[0], &ticks[1]) != 2) return -1.0;
    return double(ticks[0] + ticks[1]) / double(::sysconf(_SC_CLK_TCK));
}

}  // namespace

std::string cadChildFailure(const BoundedResult& r, const std::string& doing, double seconds, std::size_t memoryBytes) {
    char text[300];
    switch (r.kind) {
        case BoundedResult::Kind::TimedOut:
            std::snprintf(text, sizeof text,
                          "OpenCASCADE did not finish %s within %g s of processor time (PATCHWORK_CAD_SECONDS sets the limit; a damaged "
                          "file can make it loop)",
                          doing.c_str(), seconds);
            return text;
        case BoundedResult::Kind::OutOfMemory:
            std::snprintf(text, sizeof text, "OpenCASCADE needed more than %zu MiB %s (the limit for a STEP or IGES file)",
                          memoryBytes >> 20, doing.c_str());
            return text;
        case BoundedResult::Kind::Crashed:
            if (r.signal)
                std::snprintf(text, sizeof text, "OpenCASCADE crashed %s (signal %d, %s)", doing.c_str(), r.signal,
                              r.signal == SIGKILL || r.signal == SIGSEGV ? "perhaps its memory limit" : "a fault in it");
            else
                std::snprintf(text, sizeof text, "OpenCASCADE failed %s", doing.c_str());
            return text;
        case BoundedResult::Kind::Done:
            break;
    }
    return {};
}

BoundedResult runBounded(const std::function<std::string()>& work, double seconds, std::size_t memoryBytes) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("cannot create a pipe for a bounded reader");
    const std::size_t base = addressSpaceNow();
    std::fflush(nullptr);  // nothing buffered twice
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]), ::close(fds[1]);
        throw std::runtime_error("cannot start a bounded reader (fork failed)");
    }
    if (pid == 0) {
        ::close(fds[0]);
        if (kLimitAddressSpace && memoryBytes > 0) {
            const rlimit lim{rlim_t(base + memoryBytes), rlim_t(base + memoryBytes)};
            ::setrlimit(RLIMIT_AS, &lim);
        }
        std::string out;
        try {
            out = "D" + work();
        } catch (const std::bad_alloc&) {
            out = "M";
        } catch (...) {
            out = "X";
        }
        _exit(writeAll(fds[1], out) ? 0 : 1);
    }
    ::close(fds[1]);
    BoundedResult result;
    std::string got;
    // The budget is the child's processor time, read every 50 ms, so that a loaded machine does not
    // refuse a file an idle one reads (issue 66); wall time past three budgets (a child that waits
    // on nothing) ends it too.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(3.0 * seconds);
    bool timedOut = false;
    char buf[65536];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0 || cpuSecondsOf(pid) >= seconds) {
            timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int r = ::poll(&p, 1, int(std::clamp<long long>(left, 1, 50)));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) continue;
        const ssize_t n = ::read(fds[0], buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // the child closed its end: finished
        got.append(buf, size_t(n));
    }
    ::close(fds[0]);
    if (timedOut) ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timedOut) {
        result.kind = BoundedResult::Kind::TimedOut;
    } else if (WIFSIGNALED(status)) {
        result.kind = BoundedResult::Kind::Crashed;
        result.signal = WTERMSIG(status);
    } else if (got.empty() || got[0] == 'X') {
        result.kind = BoundedResult::Kind::Crashed;
    } else if (got[0] == 'M') {
        result.kind = BoundedResult::Kind::OutOfMemory;
    } else {
        result.output = got.substr(1);
    }
    return result;
}

}  // namespace io
}  // namespace pw

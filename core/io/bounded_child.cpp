#include "core/io/bounded_child.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
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

}  // namespace

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
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    bool timedOut = false;
    char buf[65536];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int r = ::poll(&p, 1, int(std::min<long long>(left, 1000)));
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

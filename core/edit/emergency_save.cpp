#include "core/edit/emergency_save.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <atomic>
#include <csignal>
#include <cstring>
#include <stdexcept>

#include "core/edit/autosave.hpp"
#include "core/io/patchwork_format.hpp"

namespace pw {
inline namespace edit {

namespace {

// What the handler reads: fixed paths (set before the handlers are installed, never changed while
// they are) and two alternating buffers of bytes.
struct Slot {
    std::string document, note;
    uint64_t serial = 0;
    bool empty = true;  // nothing to save: unmodified
};
constexpr int kSignals[] = {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL};
constexpr int kSignalCount = int(sizeof(kSignals) / sizeof(kSignals[0]));
struct State {
    std::string documentPath, documentTemp, notePath, noteTemp;
    Slot slots[2];
    std::atomic<int> current{-1};     // the slot the handler writes; -1 = none yet
    std::atomic<bool> frozen{false};  // the handler has begun: the worker writes no slot again
    std::atomic<bool> installed{false};
    struct sigaction previous[kSignalCount];
    std::string altStack;
};
State g;

// open + write + rename: all async-signal-safe.
void writeFile(const std::string& temp, const std::string& path, const std::string& bytes) {
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) return;
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n <= 0) break;
        done += size_t(n);
    }
    const bool whole = done == bytes.size() && ::fsync(fd) == 0;
    ::close(fd);
    if (whole)
        ::rename(temp.c_str(), path.c_str());
    else
        ::unlink(temp.c_str());
}

void say(const char* text) {
    const ssize_t n = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)n;
}

void onFatal(int sig) {
    EmergencySave::writeNow();
    // Ends as it would have without us: the previous handler (ASan's, or the default), raised again.
    for (int i = 0; i < kSignalCount; ++i)
        if (kSignals[i] == sig) ::sigaction(sig, &g.previous[i], nullptr);
    ::raise(sig);
}

}  // namespace

void EmergencySave::writeNow() {
    g.frozen.store(true);
    const int c = g.current.load();
    if (c < 0 || g.slots[c].empty) return;
    say("patchwork: a fatal error; writing the last committed document for recovery: ");
    say(g.documentPath.c_str());
    say("\n");
    writeFile(g.documentTemp, g.documentPath, g.slots[c].document);
    writeFile(g.noteTemp, g.notePath, g.slots[c].note);
}

EmergencySave::EmergencySave(const std::filesystem::path& document, const std::filesystem::path& note) {
    if (g.installed.exchange(true)) throw std::logic_error("EmergencySave: installed twice");
    g.documentPath = document.string();
    g.documentTemp = document.string() + ".emergency";
    g.notePath = note.string();
    g.noteTemp = note.string() + ".emergency";
    g.current.store(-1);
    g.frozen.store(false);
    // Its own stack, so that a stack overflow's SIGSEGV can still be handled.
    g.altStack.assign(size_t(64) * 1024, '\0');
    stack_t ss{};
    ss.ss_sp = g.altStack.data();
    ss.ss_size = g.altStack.size();
    ::sigaltstack(&ss, nullptr);
    struct sigaction sa {};
    sa.sa_handler = onFatal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_ONSTACK | SA_RESETHAND;
    for (int i = 0; i < kSignalCount; ++i) ::sigaction(kSignals[i], &sa, &g.previous[i]);
    worker_ = std::thread([this] { work(); });
}

EmergencySave::~EmergencySave() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    worker_.join();
    for (int i = 0; i < kSignalCount; ++i) ::sigaction(kSignals[i], &g.previous[i], nullptr);
    g.current.store(-1);
    g.installed.store(false);
}

void EmergencySave::submit(const Document& doc, const std::string& originalPath, uint64_t serial) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        job_ = Job{doc, originalPath, serial};
    }
    wake_.notify_one();
}

void EmergencySave::clear(uint64_t serial) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        job_ = Job{std::nullopt, {}, serial};
    }
    wake_.notify_one();
}

uint64_t EmergencySave::published() const {
    const int c = g.current.load();
    return c < 0 ? 0 : g.slots[c].serial;
}

void EmergencySave::waitIdle() {
    std::unique_lock<std::mutex> lock(mutex_);
    idle_.wait(lock, [this] { return !job_ && !busy_; });
}

void EmergencySave::work() {
    for (;;) {
        Job job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return stop_ || job_; });
            if (stop_) return;
            job = std::move(*job_);
            job_.reset();
            busy_ = true;
        }
        Slot next;
        next.serial = job.serial;
        if (job.doc) {
            try {
                next.document = serializeDocument(*job.doc);
                next.note = autosaveNote(job.original, int(::getpid()), job.doc->name, true);
                next.empty = false;
            } catch (...) {
                next.empty = true;  // not serialisable: the previous autosave stays the recovery
            }
        }
        // The handler reads slot `current`; the worker writes only the other one, and none once
        // the handler has begun (frozen is set before it reads `current`).
        if (!g.frozen.load()) {
            const int target = g.current.load() == 0 ? 1 : 0;
            g.slots[target] = std::move(next);
            g.current.store(target);
        }
        {
            std::lock_guard<std::mutex> lock(mutex_);
            busy_ = false;
        }
        idle_.notify_all();
    }
}

}  // namespace edit
}  // namespace pw

// The emergency save (issue 72): a fatal signal (SIGABRT from a failed assertion or
// std::terminate, SIGSEGV, SIGBUS, SIGFPE, SIGILL) writes the last committed document to the
// process's autosave file and its note before the process ends, so that the next start offers it
// for recovery (core/edit/autosave.hpp) with nothing lost since the last committed edit.
//
// A signal handler may not allocate or take locks, so the document is written to bytes ahead of
// time: the editor hands each committed state to submit(), a worker thread serialises it (off the
// frame), and the handler only open()s, write()s and rename()s those bytes. Two buffers alternate;
// once the handler has begun, the worker never writes again, so the buffer it reads stays whole.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/model/document.hpp"

namespace pw {
inline namespace edit {

class EmergencySave {
public:
    // Installs the handlers (once per process: a second EmergencySave is refused with logic_error),
    // writing to `document` and `note` (the autosave's two paths).
    EmergencySave(const std::filesystem::path& document, const std::filesystem::path& note);
    // Restores the previous handlers and stops the worker.
    ~EmergencySave();
    EmergencySave(const EmergencySave&) = delete;
    EmergencySave& operator=(const EmergencySave&) = delete;

    // The document as committed (modified since its last save), for the worker to serialise; the
    // latest one wins. `serial` identifies it (published() says when it is ready).
    void submit(const Document& doc, const std::string& originalPath, uint64_t serial);
    // Nothing to save: the document is unmodified (saved, or just opened).
    void clear(uint64_t serial);
    // The serial of the state the handler would write now.
    uint64_t published() const;
    // Waits until every submitted state is published (tests).
    void waitIdle();

    // What the handler writes, written now the same way (tests; the handler calls it).
    static void writeNow();

private:
    struct Job {
        std::optional<Document> doc;
        std::string original;
        uint64_t serial = 0;
    };
    std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::optional<Job> job_;
    bool stop_ = false, busy_ = false;
    std::thread worker_;
    void work();
};

}  // namespace edit
}  // namespace pw

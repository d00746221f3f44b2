// Long writes off the editor's thread: exports are queued here and written one after another on a
// worker thread, so the window keeps drawing and taking keys (a Ctrl+S pressed during a long export
// was lost while the export held the frame). Each write goes through saveDocument (all or nothing).
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/io/gltf_export.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace edit {

class BackgroundWriter {
public:
    struct Result {
        std::string path;
        std::string error;  // empty: written
    };

    BackgroundWriter();
    ~BackgroundWriter();  // finishes every queued write first: nothing is abandoned half-way
    BackgroundWriter(const BackgroundWriter&) = delete;
    BackgroundWriter& operator=(const BackgroundWriter&) = delete;

    // Queues `doc` (a copy) for `path`; returns how many writes are ahead of it. `displayed`: the
    // surface mesh of an export as displayed (options.asDisplayed), captured on the render thread.
    size_t enqueue(Document doc, std::string path, ExportOptions options, std::optional<TriangleMesh> displayed = std::nullopt);
    // The writes finished since the last call, in order.
    std::vector<Result> takeFinished();
    // The path being written or waiting, first in line ("" when idle), and how many are pending.
    std::string current() const;
    size_t pending() const;
    // Blocks until every queued write has finished.
    void waitIdle();

private:
    struct Job {
        Document doc;
        std::string path;
        ExportOptions options;
        std::optional<TriangleMesh> displayed;
    };
    void work();

    mutable std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::deque<Job> queue_;  // the front is the one being written
    bool stop_ = false;
    std::vector<Result> finished_;
    std::thread worker_;
};

}  // namespace edit
}  // namespace pw

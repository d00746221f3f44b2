#include "core/edit/background_writer.hpp"

#include <exception>
#include <utility>

#include "core/io/document_io.hpp"

namespace pw {
inline namespace edit {

BackgroundWriter::BackgroundWriter() : worker_([this] { work(); }) {}

BackgroundWriter::~BackgroundWriter() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    worker_.join();
}

size_t BackgroundWriter::enqueue(Document doc, std::string path, ExportOptions options, std::optional<TriangleMesh> displayed) {
    size_t ahead = 0;
    {
        const std::lock_guard lock(mutex_);
        ahead = queue_.size();
        queue_.push_back({std::move(doc), std::move(path), options, std::move(displayed)});
    }
    wake_.notify_all();
    return ahead;
}

std::vector<BackgroundWriter::Result> BackgroundWriter::takeFinished() {
    const std::lock_guard lock(mutex_);
    return std::exchange(finished_, {});
}

std::string BackgroundWriter::current() const {
    const std::lock_guard lock(mutex_);
    return queue_.empty() ? std::string() : queue_.front().path;
}

size_t BackgroundWriter::pending() const {
    const std::lock_guard lock(mutex_);
    return queue_.size();
}

void BackgroundWriter::waitIdle() {
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [this] { return queue_.empty(); });
}

void BackgroundWriter::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stop_ with nothing left to write
        Job& job = queue_.front();   // stays put: only this thread pops
        lock.unlock();
        Result r{job.path, {}};
        try {
            saveDocument(job.doc, job.path, job.options, job.displayed ? &*job.displayed : nullptr);
        } catch (const std::exception& e) {
            r.error = e.what();
        }
        lock.lock();
        queue_.pop_front();
        finished_.push_back(std::move(r));
        if (queue_.empty()) idle_.notify_all();
    }
}

}  // namespace edit
}  // namespace pw

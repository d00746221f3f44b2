// Reading whole files with a size limit, and writing outputs safely: checked before the work
// (never onto a device node, FIFO or read-only file; through symlinks), written completely beside
// the target and moved into place (temporary file, fsync, rename), several outputs all or nothing,
// so that a failed or interrupted save never leaves a partial file or destroys the old one.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/limits.hpp"

namespace pw {
inline namespace base {

// Reads the file; throws InputError naming it when it is missing, unreadable, not a regular file (a
// directory, device, FIFO or socket: refused before any read, so a FIFO cannot hang it), a file of
// /proc or /sys, or larger than `maxBytes` (default limits::kMaxFileBytes).
std::string readFileLimited(const std::filesystem::path& path, size_t maxBytes = limits::kMaxFileBytes);
// The first `bytes` of a file (fewer when it is shorter), with the same checks: a header read before
// the whole file.
std::string readFileHead(const std::filesystem::path& path, size_t bytes);

// Where an output really goes, checked before anything is written: through a symlink to the file
// it names; refused (OutputError naming the path) onto a device, FIFO, socket or directory, onto a
// read-only file, into a missing or unwritable directory. Call early, before long work.
struct OutputTarget {
    std::filesystem::path requested, path;  // as given; after symlinks
    bool exists = false;
    unsigned mode = 0, uid = 0, gid = 0;  // of the existing file, kept by the new one
};
OutputTarget checkOutputPath(const std::filesystem::path& path);

// Outputs that appear together or not at all: stage() writes each one completely into a
// temporary file beside its target (full disk, permissions found here); commit() moves them all
// into place. A batch destroyed before commit() leaves every target as it was and no temporary
// file. Existing files keep their permissions and owner; a file with other hard links is replaced
// like any other (the other names keep the old file: a rewrite in place could leave them all empty).
class OutputBatch {
public:
    OutputBatch() = default;
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;
    ~OutputBatch();
    void stage(const std::filesystem::path& path, std::string_view data);
    void stage(const std::filesystem::path& path, const std::vector<std::string_view>& pieces);  // written one after another
    // The temporary file the last stage() wrote (to read it back before commit()).
    const std::filesystem::path& lastStaged() const { return staged_.back().temp; }
    void commit();

private:
    struct Staged {
        OutputTarget target;
        std::filesystem::path temp;
    };
    std::vector<Staged> staged_;
};

// One output through an OutputBatch: whatever was at `path` stays untouched on failure.
// `readBack`, when given, reads the staged file (complete, synced, not yet in place) back through
// the format's own reader before it replaces anything: an InputError from it becomes an OutputError
// ("written, but it does not read back: …") and nothing is replaced, so a document the program
// writes always reopens (issue 44).
void writeFileAtomic(const std::filesystem::path& path, std::string_view data,
                     const std::function<void(const std::filesystem::path& staged)>& readBack = {});
// The same with the data in pieces, written one after another (a large file with no copy of it in
// one string). `written`, when given, is called once they are all in the staged file and before
// the read-back, so that the caller can release what they point to first.
void writeFileAtomic(const std::filesystem::path& path, const std::vector<std::string_view>& pieces,
                     const std::function<void(const std::filesystem::path& staged)>& readBack, const std::function<void()>& written = {});

// What identifies a file's contents on disk without reading them: its modification time, size and
// inode. A document remembers its file's stamp when it is opened or saved; a different stamp at the
// next save means another program (a second editor) wrote it in between (issue 73).
struct FileStamp {
    bool exists = false;
    long long mtimeNs = 0, size = 0;
    unsigned long long inode = 0, device = 0;
    bool operator==(const FileStamp&) const = default;
};
FileStamp fileStamp(const std::filesystem::path& path);

// Lower-case extension with the dot, e.g. ".glb".
std::string lowerExtension(const std::filesystem::path& path);

}  // namespace base
}  // namespace pw

// Reading whole files with a size limit, and atomic writes (temporary file, flush, fsync, rename)
// so that a failed or interrupted save never leaves a partial file or destroys the old one.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace pw {

// Reads the file; throws InputError naming it when it is missing, unreadable, a directory or
// larger than limits::kMaxFileBytes.
std::string readFileLimited(const std::filesystem::path& path);

// Writes `data` to `path` atomically; throws OutputError naming the path on any failure, leaving
// whatever was at `path` before untouched and no temporary file behind.
void writeFileAtomic(const std::filesystem::path& path, std::string_view data);

// Lower-case extension with the dot, e.g. ".glb".
std::string lowerExtension(const std::filesystem::path& path);

}  // namespace pw

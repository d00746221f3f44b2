// Helpers shared by the tests: paths to the data set and the binary, temporary directories, and
// running the patchwork executable.
#pragma once

#include <filesystem>
#include <string>

#include "core/document.hpp"

namespace pw::test {

std::filesystem::path dataDir();           // the repository's data/ (tea set)
std::filesystem::path testsDir();          // the repository's tests/
std::filesystem::path patchworkBinary();   // the built `patchwork`
std::filesystem::path freshTempDir(const std::string& tag);  // empty, unique per call
std::string readBytes(const std::filesystem::path& file);      // the whole file ("" when missing)
size_t entryCount(const std::filesystem::path& dir);           // files, folders and links in dir

struct RunResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};
RunResult runCommand(const std::string& shellCommand);

}  // namespace pw::test

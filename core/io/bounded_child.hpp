// Running a reader that may not be trusted to finish (OpenCASCADE on a damaged or hostile STEP or
// IGES file, issue 44) in a child process with a deadline and a memory budget: the child computes a
// string, the parent reads it through a pipe, and a child past its deadline is killed. A hang or an
// exhausted budget then costs the caller seconds and an error, never a frozen program.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace pw {
inline namespace io {

struct BoundedResult {
    enum class Kind { Done, TimedOut, OutOfMemory, Crashed } kind = Kind::Done;
    std::string output;  // what `work` returned (Done only)
    int signal = 0;      // Crashed: the signal that ended the child
};

// Runs `work` in a forked child limited to `seconds` of processor time (and three times that of
// wall time) and `memoryBytes` more address space than the parent has now (not applied under
// AddressSanitizer, whose shadow memory needs the whole address space). std::bad_alloc in the child
// counts as OutOfMemory.
BoundedResult runBounded(const std::function<std::string()>& work, double seconds, std::size_t memoryBytes);

// What an OpenCASCADE child that ended without an answer did, in words, for imports and exports
// alike: "OpenCASCADE did not finish reading it within 8 s of processor time (PATCHWORK_CAD_SECONDS
// sets the limit; …)". `doing`: "reading it", "writing it", "reading it back".
std::string cadChildFailure(const BoundedResult& r, const std::string& doing, double seconds, std::size_t memoryBytes);

}  // namespace io
}  // namespace pw

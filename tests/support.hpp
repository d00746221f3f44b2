// Helpers shared by the tests: paths to the data set and the binary, temporary directories, and
// running the patchwork executable.
#pragma once

#include <filesystem>
#include <string>

#include "core/commands/command_table.hpp"
#include "core/edit/edit_session.hpp"
#include "core/model/document.hpp"

namespace pw::test {

// True in the AddressSanitizer build (scripts/sanitize.sh). Sweeps whose time goes to lavapipe take
// a sample there: the Release pass checks every value, the sanitizer pass looks for memory errors.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

std::filesystem::path dataDir();                             // the repository's data/ (tea set)
std::filesystem::path testsDir();                            // the repository's tests/
std::filesystem::path patchworkBinary();                     // the built `patchwork`
std::filesystem::path freshTempDir(const std::string& tag);  // empty, unique per call; removed at the end when every test passed
std::string readBytes(const std::filesystem::path& file);    // the whole file ("" when missing)
size_t entryCount(const std::filesystem::path& dir);         // files, folders and links in dir

// A PNG read with stb_image as RGBA8 (w = h = 0 when it cannot be read).
struct Png {
    int w = 0, h = 0;
    std::vector<uint8_t> rgba;
    const uint8_t* at(int x, int y) const { return &rgba[(size_t(y) * size_t(w) + size_t(x)) * 4]; }
};
Png loadPng(const std::filesystem::path& file);

// The area of the document's surfaces as they are kept: each patch's and net's trimmed area
// (Green's theorem over its loops, ~1e-9 relative), and its Bézier triangles' tessellated at level 64.
double surfaceArea(const Document& doc);

struct RunResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};
RunResult runCommand(const std::string& shellCommand);

// A command host that writes nothing (scripts whose saves are not the point).
class NoWritesHost final : public CommandHost {
public:
    void write(const Document&, const std::string&) override {}
};
// Runs `script` (';'-separated commands) on the session through the command table, as `patchwork edit` does.
void runEditScript(EditSession& session, const std::string& script);
// Runs "a; b; …" one command after another through `table` with `host`, letting each command's own
// EditError out (runEditScript wraps failures in the script's InputError); the first refusal stops
// the rest.
void runCommands(const CommandTable& table, EditSession& session, CommandHost& host, const std::string& line);

// The point of Bézier patch p at (u, v), and of curve c at parameter t of segment `seg`, both
// rational where weighted (tests of surfaces built from curves compare the two).
Vec3 patchPointAt(const Document& doc, uint32_t p, double u, double v);
Vec3 curvePointAt(const Document& doc, const BezierCurve& c, size_t seg, double t);

// Three patches round the pole of the unit sphere (polar angle 0.35 to 0.9, a third of the way round
// each), neighbours sharing their radial edges and joined C0: a triangular hole at the top, edges
// 0:v0, 1:v0 and 2:v0, which one Bézier triangle fills G1 (issue 40).
Document poleRing();

// Runs the Khronos glTF validator (PATCHWORK_GLTF_VALIDATOR, one node process) on the files and
// expects 0 errors and 0 warnings each; a missing validator or node is a failure, never a skip.
void expectValidGltf(const std::vector<std::filesystem::path>& files);
// The validator script, or an empty path after a failure saying how to install it.
std::filesystem::path gltfValidatorScript();

}  // namespace pw::test

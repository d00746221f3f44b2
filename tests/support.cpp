#include "support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace pw::test {

namespace {

// The paths compiled in by tests/CMakeLists.txt become environment variables (unless already set),
// so the test and every `patchwork` it starts see the same ones. Render tests also turn the Vulkan
// validation layer on, failing on any message.
struct ExportCompiledDefaults {
    ExportCompiledDefaults() {
        ::setenv("PATCHWORK_DATA_DIR", PATCHWORK_DATA_DIR, 0);
        ::setenv("PATCHWORK_TESTS_DIR", PATCHWORK_TESTS_DIR, 0);
        ::setenv("PATCHWORK_BIN", PATCHWORK_BIN, 0);
        ::setenv("PATCHWORK_GLTF_VALIDATOR", PATCHWORK_GLTF_VALIDATOR, 0);
#ifdef PATCHWORK_RENDER_TESTS
        ::setenv("PATCHWORK_VALIDATION", "1", 1);
        ::setenv("XDG_CACHE_HOME", PATCHWORK_TEST_CACHE_DIR, 0);
#endif
    }
} const exportCompiledDefaults;

std::filesystem::path envPath(const char* name) {
    const char* v = std::getenv(name);
    if (!v || !*v) throw std::runtime_error(std::string("environment variable ") + name + " is not set (run through ctest)");
    return v;
}
}  // namespace

std::filesystem::path dataDir() { return envPath("PATCHWORK_DATA_DIR"); }
std::filesystem::path testsDir() { return envPath("PATCHWORK_TESTS_DIR"); }
std::filesystem::path patchworkBinary() { return envPath("PATCHWORK_BIN"); }

std::filesystem::path freshTempDir(const std::string& tag) {
    static std::atomic<int> counter{0};
    auto dir = std::filesystem::temp_directory_path() /
               ("patchwork-test-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

size_t entryCount(const std::filesystem::path& dir) {
    size_t n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
    return n;
}

RunResult runCommand(const std::string& shellCommand) {
    RunResult r;
    FILE* pipe = ::popen((shellCommand + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    const int status = ::pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

void runEditScript(EditSession& session, const std::string& script) {
    NoWritesHost host;
    makeCommandTable().runScript(session, host, script, "test");
}

}  // namespace pw::test

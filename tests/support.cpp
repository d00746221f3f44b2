#include "support.hpp"

#include "core/eval/bezier_curve.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"
#include "core/trim/trim_mesh.hpp"

#include <gtest/gtest.h>

#include <stb_image.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <mutex>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace pw::test {

Document poleRing() {
    Document d;
    auto pool = [](int i, int g) { return uint32_t(i * 9 + g % 9); };
    for (int i = 0; i < 4; ++i)
        for (int g = 0; g < 9; ++g) {
            const double polar = 0.35 + 0.55 * i / 3.0, azimuth = g * 2.0 * std::acos(-1.0) / 9.0;
            d.points.emplace_back(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
        }
    for (int k = 0; k < 3; ++k) {
        Patch p;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) p.idx[size_t(i * 4 + j)] = pool(i, 3 * k + j);
        d.patches.push_back(p);
    }
    for (uint32_t k = 0; k < 3; ++k) d.joins.push_back(Join{k, Edge::U1, (k + 1) % 3, Edge::U0, false, Continuity::C0, 1.0});
    return d;
}

Vec3 patchPointAt(const Document& doc, uint32_t p, double u, double v) {
    return evaluateWindow(gatherWindow(doc, doc.patches.at(p).idx), Basis::Bezier, 0.5, u, v).p;
}

Vec3 curvePointAt(const Document& doc, const BezierCurve& c, size_t seg, double t) {
    const std::array<uint32_t, 4> i = curveSegment(c, seg);
    const std::array<double, 4> w{pointWeight(doc, i[0]), pointWeight(doc, i[1]), pointWeight(doc, i[2]), pointWeight(doc, i[3])};
    return evaluateRationalCurve(curvePoints(doc, c, seg), w, t).p;
}

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

namespace {

// The folders freshTempDir made in this process: removed when every test of the process passed,
// kept (and named) for a look when one failed. Before, every run left its folders behind (8 000
// of them in /tmp after a hundred suites).
class TempDirs : public ::testing::Environment {
public:
    void add(const std::filesystem::path& dir) {
        const std::lock_guard<std::mutex> lock(mutex_);
        dirs_.push_back(dir);
    }
    void TearDown() override {
        const std::lock_guard<std::mutex> lock(mutex_);
        const bool keep = !::testing::UnitTest::GetInstance()->Passed() || std::getenv("PATCHWORK_KEEP_TEST_DIRS");
        for (const std::filesystem::path& dir : dirs_) {
            std::error_code ec;
            if (keep)
                std::cerr << "kept for a look: " << dir.string() << "\n";
            else
                std::filesystem::remove_all(dir, ec);
        }
        dirs_.clear();
    }

private:
    std::mutex mutex_;
    std::vector<std::filesystem::path> dirs_;
};
TempDirs* const tempDirs = static_cast<TempDirs*>(::testing::AddGlobalTestEnvironment(new TempDirs));

}  // namespace

std::filesystem::path freshTempDir(const std::string& tag) {
    static std::atomic<int> counter{0};
    auto dir = std::filesystem::temp_directory_path() /
               ("patchwork-test-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    tempDirs->add(dir);
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

void runCommands(const CommandTable& table, EditSession& session, CommandHost& host, const std::string& line) {
    for (size_t start = 0; start < line.size();) {
        const size_t end = std::min(line.find("; ", start), line.size());
        table.run(session, host, std::string_view(line).substr(start, end - start));
        start = end + 2;
    }
}

namespace {
std::string shellQuote(const std::filesystem::path& p) { return "'" + p.string() + "'"; }
}  // namespace

// The validator script, or an empty path after reporting a failure that says how to install it.
// Never skips: a missing validator is a failure of the test set-up.
std::filesystem::path gltfValidatorScript() {
    const char* env = std::getenv("PATCHWORK_GLTF_VALIDATOR");
    if (!env || !*env) {
        ADD_FAILURE() << "PATCHWORK_GLTF_VALIDATOR is not set: run the tests through ctest (scripts/test.sh)";
        return {};
    }
    const std::filesystem::path script = env;
    if (!std::filesystem::exists(script)) {
        ADD_FAILURE() << script << " does not exist";
        return {};
    }
    const auto node = runCommand("node --version");
    if (node.exitCode != 0) {
        ADD_FAILURE() << "node is not available (" << node.output
                      << "): run scripts/test.sh, which installs the glTF "
                         "validator (npm install --prefix tests/gltf)";
        return {};
    }
    if (!std::filesystem::exists(script.parent_path() / "node_modules" / "gltf-validator" / "package.json")) {
        ADD_FAILURE() << "the npm package gltf-validator is not installed in " << script.parent_path()
                      << ": run scripts/test.sh (it runs npm install --prefix tests/gltf)";
        return {};
    }
    return script;
}

// Runs the validator on the files (one node process for all); expects 0 errors and 0 warnings each.
void expectValidGltf(const std::vector<std::filesystem::path>& files) {
    const std::filesystem::path script = gltfValidatorScript();
    if (script.empty()) return;
    std::string cmd = "node " + shellQuote(script);
    for (const std::filesystem::path& f : files) cmd += " " + shellQuote(f);
    const auto r = runCommand(cmd);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    size_t okErrors = 0, okWarnings = 0;
    for (size_t pos = 0; (pos = r.output.find("numErrors: 0\n", pos)) != std::string::npos; ++pos) ++okErrors;
    for (size_t pos = 0; (pos = r.output.find("numWarnings: 0\n", pos)) != std::string::npos; ++pos) ++okWarnings;
    EXPECT_EQ(okErrors, files.size()) << r.output;
    EXPECT_EQ(okWarnings, files.size()) << r.output;
}

Png loadPng(const std::filesystem::path& file) {
    Png img;
    int n = 0;
    unsigned char* data = stbi_load(file.c_str(), &img.w, &img.h, &n, 4);
    if (data)
        img.rgba.assign(data, data + size_t(img.w) * size_t(img.h) * 4);
    else
        img.w = img.h = 0;
    stbi_image_free(data);
    return img;
}

double surfaceArea(const Document& doc) {
    double a = 0.0;
    for (uint32_t p = 0; p < doc.patches.size(); ++p) a += trimmedArea(DomainSurface(doc, {false, p}), doc.patches[p].trims);
    for (uint32_t s = 0; s < doc.surfaces.size(); ++s) a += trimmedArea(DomainSurface(doc, {true, s}), doc.surfaces[s].trims);
    if (!doc.triangles.empty()) {
        Document triangles;
        triangles.points = doc.points;
        triangles.weights = doc.weights;
        triangles.triangles = doc.triangles;
        const TriangleMesh m = tessellateTrimmed(triangles, 64);
        for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            const auto& p = m.positions[m.indices[t]];
            const auto& q = m.positions[m.indices[t + 1]];
            const auto& r = m.positions[m.indices[t + 2]];
            const Vec3 a0(p[0], p[1], p[2]), a1(q[0], q[1], q[2]), a2(r[0], r[1], r[2]);
            a += 0.5 * glm::length(glm::cross(a1 - a0, a2 - a0));
        }
    }
    return a;
}

}  // namespace pw::test

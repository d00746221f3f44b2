// The layers depend one way (README): core includes no Vulkan, ImGui or GLFW and no header of
// render/, ui/ or app/; render includes no ImGui or GLFW and no header of ui/ or app/. Every quoted
// include names its layer ("core/document.hpp"). Read from the sources, so a new include that
// breaks a rule fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>

#include "support.hpp"

namespace fs = std::filesystem;

namespace {

fs::path repo() { return pw::test::testsDir().parent_path(); }

std::set<std::string> headersOf(const std::string& layer) {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(repo() / layer))
        if (e.path().extension() == ".hpp" || e.path().extension() == ".h") out.insert(e.path().filename().string());
    return out;
}

// "file:line: #include ..." for every include of `layer` that names a forbidden system prefix or a
// header of a forbidden layer.
std::vector<std::string> violations(const std::string& layer, const std::vector<std::string>& systemPrefixes,
                                    const std::vector<std::string>& layers) {
    std::set<std::string> forbidden;
    for (const std::string& l : layers)
        for (const std::string& h : headersOf(l)) forbidden.insert(l + "/" + h);
    const std::regex include(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
    std::vector<std::string> out;
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(repo() / layer)) {
        const std::string ext = e.path().extension().string();
        if (ext != ".cpp" && ext != ".hpp") continue;
        ++files;
        std::ifstream in(e.path());
        int n = 0;
        for (std::string line; std::getline(in, line);) {
            ++n;
            std::smatch m;
            if (!std::regex_search(line, m, include)) continue;
            const std::string name = m[2];
            bool bad = false;
            for (const std::string& p : systemPrefixes) bad = bad || name.rfind(p, 0) == 0;
            if (m[1] == "\"" && forbidden.count(name)) bad = true;
            if (bad) out.push_back(layer + "/" + e.path().filename().string() + ":" + std::to_string(n) + ": " + line);
        }
    }
    EXPECT_GT(files, 10u) << "no sources found under " << (repo() / layer);
    return out;
}

// Quoted includes of `dir`'s sources that do not start with a layer folder.
std::vector<std::string> unnamedLayer(const std::string& dir) {
    const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
    const std::regex named(R"(^(core|render|ui|app|shaders)/[a-z0-9_]+\.(hpp|h)$)");
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(repo() / dir)) {
        const std::string ext = e.path().extension().string();
        if (ext != ".cpp" && ext != ".hpp" && ext != ".h") continue;
        std::ifstream in(e.path());
        int n = 0;
        for (std::string line; std::getline(in, line);) {
            ++n;
            std::smatch m;
            if (std::regex_search(line, m, include) && !std::regex_match(std::string(m[1]), named))
                out.push_back(dir + "/" + e.path().filename().string() + ":" + std::to_string(n) + ": " + line);
        }
    }
    return out;
}

}  // namespace

TEST(Layering, IncludesNameTheirLayer) {
    for (const char* dir : {"core", "render", "ui", "app"}) {
        const auto v = unnamedLayer(dir);
        EXPECT_TRUE(v.empty()) << ::testing::PrintToString(v);
    }
}

TEST(Layering, CoreIncludesNoGpuNoWindowNoUpperLayer) {
    const auto v = violations("core", {"vulkan/", "imgui", "GLFW/", "X11/"}, {"render", "ui", "app"});
    EXPECT_TRUE(v.empty()) << ::testing::PrintToString(v);
}

TEST(Layering, RenderIncludesNoImGuiNoGlfwNoUi) {
    const auto v = violations("render", {"imgui", "GLFW/", "X11/"}, {"ui", "app"});
    EXPECT_TRUE(v.empty()) << ::testing::PrintToString(v);
}

TEST(Layering, UiIncludesNoAppHeader) {
    const auto v = violations("ui", {}, {"app"});
    EXPECT_TRUE(v.empty()) << ::testing::PrintToString(v);
}

// Issue 24: every JSON Patchwork reads goes through core/json_guard's size and nesting guard. A
// parser call anywhere else fails here (the listed files are the guard and what runs behind it).
TEST(Layering, EveryJsonParserIsGuarded) {
    const std::regex parserCall(R"(json::parse\s*\(|LoadASCIIFrom|LoadBinaryFrom|json::from_)");
    const std::set<std::string> allowed = {
        "core/json_guard.cpp",   // the guard itself
        "core/gltf_import.cpp",  // tinygltf runs after parseJsonGuarded of the same JSON text
    };
    std::vector<std::string> bad;
    for (const char* dir : {"core", "render", "ui", "app"})
        for (const auto& e : fs::directory_iterator(repo() / dir)) {
            const std::string rel = std::string(dir) + "/" + e.path().filename().string();
            if (allowed.count(rel)) continue;
            std::ifstream in(e.path());
            std::string line;
            for (int n = 1; std::getline(in, line); ++n)
                if (std::regex_search(line, parserCall)) bad.push_back(rel + ":" + std::to_string(n) + ": " + line);
        }
    EXPECT_TRUE(bad.empty()) << ::testing::PrintToString(bad);
}

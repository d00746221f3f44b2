// The folder tree is the architecture (docs/DESIGN.md §8). Every source folder (core/*, render/*,
// ui/*, app, shaders) holds a LAYER file naming the folders it may use, one `uses FOLDER` a line;
// the build links exactly those (cmake/PatchworkLayers.cmake) and this test reads the same files:
// they form no cycle, every quoted include of a folder's sources (.h and shaders included) names
// its own folder or one it declares, system headers stay in their layers (no Vulkan in core, no
// ImGui or GLFW in render, OpenCASCADE only in core/io, Eigen only in core/solve), and each
// folder's README names every header in it. Checked from the sources, so a new include that
// crosses a boundary upward fails here; LayeringCheck.FindsAPlantedUpwardInclude shows it does.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>

#include "support.hpp"

namespace fs = std::filesystem;

namespace {

fs::path repo() { return pw::test::testsDir().parent_path(); }

using LayerMap = std::map<std::string, std::set<std::string>>;  // folder -> the folders it declares

bool isSource(const fs::path& p) {
    static const std::set<std::string> exts = {".cpp", ".hpp", ".h", ".glsl", ".vert", ".tesc", ".tese", ".frag", ".comp"};
    return exts.count(p.extension().string()) > 0;
}

std::string relPath(const fs::path& root, const fs::path& p) { return fs::relative(p, root).generic_string(); }

// Every LAYER file under root (build and node folders skipped), and what each declares. Lines that
// are neither comments nor `uses FOLDER` are reported as problems.
LayerMap readLayers(const fs::path& root, std::vector<std::string>& problems) {
    LayerMap layers;
    const std::regex usesLine(R"(^uses\s+([a-z0-9_/]+)\s*$)");
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        const std::string name = it->path().filename().string();
        if (it->is_directory() && (name.rfind("build", 0) == 0 || name == "node_modules" || name[0] == '.')) {
            it.disable_recursion_pending();
            continue;
        }
        if (name != "LAYER") continue;
        const std::string dir = relPath(root, it->path().parent_path());
        std::set<std::string>& uses = layers[dir];
        std::ifstream in(it->path());
        int n = 0;
        for (std::string line; std::getline(in, line);) {
            ++n;
            std::smatch m;
            if (std::regex_match(line, m, usesLine))
                uses.insert(m[1]);
            else if (!line.empty() && line[0] != '#')
                problems.push_back(dir + "/LAYER:" + std::to_string(n) + ": not 'uses FOLDER': " + line);
        }
    }
    return layers;
}

// Declared folders that have no LAYER, and cycles among the declarations.
void checkGraph(const LayerMap& layers, std::vector<std::string>& problems) {
    for (const auto& [dir, uses] : layers)
        for (const std::string& u : uses)
            if (!layers.count(u)) problems.push_back(dir + "/LAYER: uses " + u + ", which is no layer");
    std::map<std::string, int> state;  // 1 on the path, 2 done
    std::vector<std::string> path;
    std::function<void(const std::string&)> visit = [&](const std::string& d) {
        state[d] = 1;
        path.push_back(d);
        if (auto it = layers.find(d); it != layers.end())
            for (const std::string& u : it->second) {
                if (state[u] == 1) {
                    std::string cycle;
                    for (auto p = std::find(path.begin(), path.end(), u); p != path.end(); ++p) cycle += *p + " -> ";
                    problems.push_back("cycle: " + cycle + u);
                } else if (state[u] == 0) {
                    visit(u);
                }
            }
        path.pop_back();
        state[d] = 2;
    };
    for (const auto& [dir, uses] : layers)
        if (state[dir] == 0) visit(dir);
}

struct SystemRule {
    std::string folderPrefix;  // the folders it applies to ("core/", "render/")
    std::regex include;        // a forbidden <...> include
    std::string why;
};

// Includes that cross a declared boundary, and system headers outside the layers that own them.
void checkIncludes(const fs::path& root, const LayerMap& layers, std::vector<std::string>& problems) {
    const std::regex include(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
    const std::vector<SystemRule> rules = {
        {"core/", std::regex(R"(^(vulkan/|imgui|GLFW/|X11/))"), "core is pure C++ (no Vulkan, ImGui, GLFW or X11)"},
        {"render/", std::regex(R"(^(imgui|GLFW/|X11/))"), "render draws without a window (no ImGui, GLFW or X11)"},
    };
    // Libraries that belong to one layer: the folders that may include them.
    const std::vector<std::pair<std::regex, std::set<std::string>>> owned = {
        {std::regex(R"(\.hxx$)"), {"core/io"}},                                       // OpenCASCADE
        {std::regex(R"(^(Eigen/|unsupported/Eigen))"), {"core/solve", "core/trim"}},  // the solver; trim curves' least-squares fits
        {std::regex(R"(^tiny_gltf)"), {"core/io"}},
        {std::regex(R"(^CGAL/)"), {"core/trim"}},  // constrained triangulation of trimmed windows
    };
    for (const auto& [dir, uses] : layers) {
        for (const auto& e : fs::directory_iterator(root / dir)) {
            if (!e.is_regular_file() || !isSource(e.path())) continue;
            const std::string file = dir + "/" + e.path().filename().string();
            std::ifstream in(e.path());
            int n = 0;
            for (std::string line; std::getline(in, line);) {
                ++n;
                std::smatch m;
                if (!std::regex_search(line, m, include)) continue;
                const std::string name = m[2];
                const std::string where = file + ":" + std::to_string(n) + ": " + line;
                if (m[1] == "<") {
                    for (const SystemRule& r : rules)
                        if (dir.rfind(r.folderPrefix, 0) == 0 && std::regex_search(name, r.include))
                            problems.push_back(where + " (" + r.why + ")");
                    for (const auto& [re, owners] : owned)
                        if (std::regex_search(name, re) && !owners.count(dir))
                            problems.push_back(where + " (belongs to " + *owners.begin() + ")");
                    continue;
                }
                const std::string target = fs::path(name).parent_path().generic_string();
                if (target.empty()) {  // a file beside this one (shaders' own .glsl)
                    if (!fs::exists(e.path().parent_path() / name)) problems.push_back(where + " (no such file beside it)");
                    continue;
                }
                if (target != dir && !uses.count(target)) {
                    problems.push_back(where + " (" + dir + "/LAYER does not declare " + target + ")");
                    continue;
                }
                // Generated headers (shaders/spirv.hpp, shaders/glsl_sources.hpp) live in the build tree.
                if (target != "shaders" && !fs::exists(root / name)) problems.push_back(where + " (no such file)");
            }
        }
    }
}

// Source files in a top folder that belongs to no layer (core/x.hpp beside the layer folders).
void checkNoStraySources(const fs::path& root, const LayerMap& layers, std::vector<std::string>& problems) {
    std::set<std::string> tops;
    for (const auto& [dir, uses] : layers) tops.insert(fs::path(dir).begin()->string());
    for (const std::string& top : tops)
        for (auto it = fs::recursive_directory_iterator(root / top); it != fs::recursive_directory_iterator(); ++it)
            if (it->is_regular_file() && isSource(it->path()) && !layers.count(relPath(root, it->path().parent_path())))
                problems.push_back(relPath(root, it->path()) + " is in no layer (its folder has no LAYER file)");
}

std::vector<std::string> layeringProblems(const fs::path& root) {
    std::vector<std::string> problems;
    const LayerMap layers = readLayers(root, problems);
    checkGraph(layers, problems);
    checkIncludes(root, layers, problems);
    checkNoStraySources(root, layers, problems);
    return problems;
}

struct TempTree {
    fs::path root = fs::temp_directory_path() / ("pw_layering_" + std::to_string(::getpid()));
    TempTree() { fs::create_directories(root); }
    ~TempTree() { fs::remove_all(root); }
    void write(const std::string& rel, const std::string& text) const {
        fs::create_directories((root / rel).parent_path());
        std::ofstream(root / rel) << text;
    }
};

}  // namespace

TEST(Layering, TheRepositoryKeepsItsLayers) {
    std::vector<std::string> problems;
    const LayerMap layers = readLayers(repo(), problems);
    // The tree the README and docs/DESIGN.md describe: core, render and ui split into folders.
    for (const char* d : {"core/gpu", "core/base", "core/model", "core/eval", "core/solve", "core/ops", "core/io", "core/edit",
                          "core/commands", "render/vk", "render/scene", "ui/platform", "ui/panels", "ui/editor", "app", "shaders"})
        EXPECT_TRUE(layers.count(d)) << d << " has no LAYER file";
    EXPECT_GE(layers.size(), 20u);
    const auto all = layeringProblems(repo());
    EXPECT_TRUE(all.empty()) << ::testing::PrintToString(all);
}

TEST(LayeringCheck, FindsAPlantedUpwardInclude) {
    TempTree t;
    t.write("core/low/LAYER", "# the bottom\n");
    t.write("core/low/a.hpp", "#pragma once\n");
    t.write("core/high/LAYER", "uses core/low\n");
    t.write("core/high/b.hpp", "#pragma once\n#include \"core/low/a.hpp\"\n");
    EXPECT_TRUE(layeringProblems(t.root).empty()) << ::testing::PrintToString(layeringProblems(t.root));
    t.write("core/low/c.h", "#pragma once\n#include \"core/high/b.hpp\"  // upward\n");
    const auto problems = layeringProblems(t.root);
    ASSERT_EQ(problems.size(), 1u) << ::testing::PrintToString(problems);
    EXPECT_NE(problems[0].find("core/low/c.h:2"), std::string::npos) << problems[0];
    EXPECT_NE(problems[0].find("does not declare core/high"), std::string::npos) << problems[0];
}

TEST(LayeringCheck, FindsCyclesStrayFilesAndForbiddenHeaders) {
    TempTree t;
    t.write("core/a/LAYER", "uses core/b\n");
    t.write("core/b/LAYER", "uses core/a\nnonsense\n");
    t.write("core/stray.hpp", "#pragma once\n");
    t.write("core/a/x.cpp", "#include <vulkan/vulkan.h>\n#include <BRep_Tool.hxx>\n#include \"core/a/missing.hpp\"\n");
    const auto problems = layeringProblems(t.root);
    const std::string all = ::testing::PrintToString(problems);
    EXPECT_NE(all.find("cycle: "), std::string::npos) << all;
    EXPECT_NE(all.find("core/b/LAYER:2: not 'uses FOLDER'"), std::string::npos) << all;
    EXPECT_NE(all.find("core/stray.hpp is in no layer"), std::string::npos) << all;
    EXPECT_NE(all.find("core is pure C++"), std::string::npos) << all;
    EXPECT_NE(all.find("belongs to core/io"), std::string::npos) << all;
    EXPECT_NE(all.find("(no such file)"), std::string::npos) << all;
}

// Each library is its namespace part: every source of core/X, render/X and ui/X that opens
// namespace pw puts its code in `inline namespace X` (pw::model::Document, pw::render::scene::Renderer),
// so a symbol names its layer while code within pw still writes Document. core/gpu, shared with
// GLSL, is pw::gpu.
TEST(Layering, EveryLibraryIsItsNamespacePart) {
    std::vector<std::string> problems;
    const LayerMap layers = readLayers(repo(), problems);
    std::vector<std::string> wrong;
    size_t checked = 0;
    for (const auto& [dir, uses] : layers) {
        const fs::path d(dir);
        const std::string top = d.begin()->string(), part = d.filename().string();
        if ((top != "core" && top != "render" && top != "ui") || dir == "core/gpu") continue;
        const std::regex opens(R"(^namespace pw[\w:]* \{)");
        const std::regex inlinePart("^inline namespace " + part + R"( \{)");
        for (const auto& e : fs::directory_iterator(repo() / dir)) {
            const std::string ext = e.path().extension().string();
            if (ext != ".hpp" && ext != ".h" && ext != ".cpp") continue;
            std::ifstream in(e.path());
            bool opened = false, ownPart = false;
            for (std::string line; std::getline(in, line);) {
                if (std::regex_search(line, opens)) opened = true;
                if (std::regex_search(line, inlinePart)) ownPart = true;
            }
            if (!opened) continue;
            ++checked;
            if (!ownPart) wrong.push_back(relPath(repo(), e.path()) + " has no `inline namespace " + part + "`");
        }
    }
    EXPECT_GT(checked, 300u);
    EXPECT_TRUE(wrong.empty()) << ::testing::PrintToString(wrong);
}

// Each layer's README names every header in the folder (as name.hpp, name.h or name.*).
TEST(Layering, EveryHeaderIsNamedInItsFoldersReadme) {
    std::vector<std::string> problems;
    const LayerMap layers = readLayers(repo(), problems);
    std::vector<std::string> missing;
    for (const auto& [dir, uses] : layers) {
        std::ifstream in(repo() / dir / "README.md");
        if (!in) {
            missing.push_back(dir + "/README.md does not exist");
            continue;
        }
        const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        for (const auto& e : fs::directory_iterator(repo() / dir)) {
            const std::string ext = e.path().extension().string(), stem = e.path().stem().string();
            if (ext != ".hpp" && ext != ".h") continue;
            const std::regex named("`" + stem + R"((\.hpp|\.h|\.\*|\.hpp/\.cpp|\.hpp, \.cpp)?`)");
            if (!std::regex_search(readme, named)) missing.push_back(dir + "/README.md does not name " + e.path().filename().string());
        }
    }
    EXPECT_TRUE(missing.empty()) << ::testing::PrintToString(missing);
}

// Every "DESIGN §n" the code and docs cite is a section of the repository's own docs/DESIGN.md.
TEST(Layering, EveryDesignReferenceResolvesInTheRepository) {
    std::ifstream in(repo() / "docs" / "DESIGN.md");
    ASSERT_TRUE(in) << "docs/DESIGN.md is missing";
    std::set<std::string> sections;
    const std::regex heading(R"(^## ([0-9]+)\. )");
    for (std::string line; std::getline(in, line);) {
        std::smatch m;
        if (std::regex_search(line, m, heading)) sections.insert(m[1]);
    }
    const std::regex cite(R"(DESIGN(?:\.md)? ?§ ?([0-9]+))");
    std::vector<std::string> dangling;
    size_t cites = 0;
    for (const char* dir : {"core", "render", "ui", "app", "shaders", "tests", "bench", "docs"})
        for (const auto& e : fs::recursive_directory_iterator(repo() / dir)) {
            if (!e.is_regular_file() || (!isSource(e.path()) && e.path().extension() != ".md")) continue;
            if (e.path().generic_string().find("/node_modules/") != std::string::npos) continue;
            std::ifstream f(e.path());
            std::string line;
            for (int n = 1; std::getline(f, line); ++n)
                for (auto it = std::sregex_iterator(line.begin(), line.end(), cite); it != std::sregex_iterator(); ++it) {
                    ++cites;
                    if (!sections.count((*it)[1]))
                        dangling.push_back(relPath(repo(), e.path()) + ":" + std::to_string(n) + ": §" + (*it)[1].str());
                }
        }
    EXPECT_GT(cites, 40u);
    EXPECT_TRUE(dangling.empty()) << ::testing::PrintToString(dangling);
}

// Issue 24: every JSON Patchwork reads goes through core/base/json_guard's size and nesting guard. A
// parser call anywhere else fails here (the listed files are the guard and what runs behind it).
TEST(Layering, EveryJsonParserIsGuarded) {
    const std::regex parserCall(R"(json::parse\s*\(|LoadASCIIFrom|LoadBinaryFrom|json::from_)");
    const std::set<std::string> allowed = {
        "core/base/json_guard.cpp",  // the guard itself
        "core/io/gltf_import.cpp",   // tinygltf runs after parseJsonGuarded of the same JSON text
    };
    std::vector<std::string> bad;
    size_t files = 0;
    for (const char* dir : {"core", "render", "ui", "app"})
        for (const auto& e : fs::recursive_directory_iterator(repo() / dir)) {
            if (!e.is_regular_file() || !isSource(e.path())) continue;
            ++files;
            const std::string rel = relPath(repo(), e.path());
            if (allowed.count(rel)) continue;
            std::ifstream in(e.path());
            std::string line;
            for (int n = 1; std::getline(in, line); ++n)
                if (std::regex_search(line, parserCall)) bad.push_back(rel + ":" + std::to_string(n) + ": " + line);
        }
    EXPECT_GT(files, 200u);
    EXPECT_TRUE(bad.empty()) << ::testing::PrintToString(bad);
}

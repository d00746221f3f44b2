// Bad input: every file of tests/corpus/bad/ is refused with an InputError naming the file and the
// line or JSON field of the problem; the CLI reports it in one line with exit status 2 and leaves
// no output (and no temporary) file behind, nor touches an existing output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/document_io.hpp"
#include "support.hpp"

using namespace pw;
namespace fs = std::filesystem;

namespace {

// Where each corpus file's problem is: a line number, or a JSON field path.
struct Where {
    int line = 0;
    std::string field;
};

const std::map<std::string, Where>& expectedLocations() {
    static const std::map<std::string, Where> table = {
        // .bpt
        {"bad_degree.bpt", {2, ""}},
        {"bad_degree_line.bpt", {2, ""}},
        {"beyond_limit.bpt", {5, ""}},
        {"binary.bpt", {1, ""}},
        {"blank_point_line.bpt", {13, ""}},
        {"count_above_limit.bpt", {1, ""}},
        {"count_huge.bpt", {1, ""}},
        {"count_text.bpt", {1, ""}},
        {"count_too_high.bpt", {36, ""}},
        {"count_too_low.bpt", {19, ""}},
        {"crlf_truncated.bpt", {16, ""}},
        {"degree_text.bpt", {2, ""}},
        {"empty.bpt", {1, ""}},
        {"extra_number.bpt", {13, ""}},
        {"huge.bpt", {5, ""}},
        {"inf.bpt", {12, ""}},
        {"letters.bpt", {6, ""}},
        {"missing_number.bpt", {13, ""}},
        {"nan.bpt", {8, ""}},
        {"negative_count.bpt", {1, ""}},
        {"number_suffix.bpt", {6, ""}},
        {"overflow.bpt", {18, ""}},
        {"trailing_garbage.bpt", {20, ""}},
        {"truncated.bpt", {27, ""}},
        {"truncated_mid_line.bpt", {7, ""}},
        {"whitespace_only.bpt", {1, ""}},
        // .patchwork: syntax errors by line
        {"deep_nesting.patchwork", {2, ""}},
        {"empty.patchwork", {1, ""}},
        {"malformed.patchwork", {4, ""}},
        {"malformed_missing_comma.patchwork", {3, ""}},
        {"nan.patchwork", {3, ""}},
        {"not_json.patchwork", {2, ""}},
        {"not_object.patchwork", {1, ""}},
        {"overflow.patchwork", {3, ""}},
        {"truncated.patchwork", {33, ""}},
        // .patchwork: validation errors by field
        {"camera_wrong_type.patchwork", {0, "camera.distance"}},
        {"camera_zero_distance.patchwork", {0, "camera.distance"}},
        {"display_wrong_type.patchwork", {0, "display.lightDir"}},
        {"fractional_index.patchwork", {0, "patches[0].idx[7]"}},
        {"huge_coordinate.patchwork", {0, "points[1][2]"}},
        {"idx_count.patchwork", {0, "patches[0].idx"}},
        {"idx_missing.patchwork", {0, "patches[0].idx"}},
        {"index_out_of_range.patchwork", {0, "patches[0].idx[15]"}},
        {"join_bad_alpha.patchwork", {0, "joins[0].alpha"}},
        {"join_bad_continuity.patchwork", {0, "joins[0].continuity"}},
        {"join_bad_edge.patchwork", {0, "joins[0].edgeA"}},
        {"join_missing_edge.patchwork", {0, "joins[0].edgeA"}},
        {"join_negative_patch.patchwork", {0, "joins[0].a"}},
        {"join_out_of_range.patchwork", {0, "joins[0].b"}},
        {"joins_not_array.patchwork", {0, "joins"}},
        {"missing_format.patchwork", {0, "format"}},
        {"missing_points.patchwork", {0, "points"}},
        {"missing_version.patchwork", {0, "version"}},
        {"name_number.patchwork", {0, "name"}},
        {"negative_index.patchwork", {0, "patches[0].idx[7]"}},
        {"newer_version.patchwork", {0, "version"}},
        {"patch_not_object.patchwork", {0, "patches[0]"}},
        {"patches_wrong_type.patchwork", {0, "patches"}},
        {"point_string_coord.patchwork", {0, "points[1][1]"}},
        {"point_two_coords.patchwork", {0, "points[1]"}},
        {"points_not_array.patchwork", {0, "points"}},
        {"surface_idx_count.patchwork", {0, "surfaces[0].idx"}},
        {"surface_index_out_of_range.patchwork", {0, "surfaces[0].idx[3]"}},
        {"surface_rows_zero.patchwork", {0, "surfaces[0].rows"}},
        {"surface_too_big.patchwork", {0, "surfaces[0].rows"}},
        {"tension_string.patchwork", {0, "patches[0].tension"}},
        {"tess_level_too_high.patchwork", {0, "tess.outer[3]"}},
        {"tess_override_level.patchwork", {0, "patches[0].tess[5]"}},
        {"tess_unknown_spacing.patchwork", {0, "tess.spacing"}},
        {"tess_wrong_type.patchwork", {0, "tess.linked"}},
        {"unknown_basis.patchwork", {0, "patches[0].basis"}},
        {"version_string.patchwork", {0, "version"}},
        {"version_zero.patchwork", {0, "version"}},
        {"wrong_format.patchwork", {0, "format"}},
        // .patchwork: cubic Bézier triangles
        {"triangle_fractional_index.patchwork", {0, "triangles[0].idx[2]"}},
        {"triangle_idx_count.patchwork", {0, "triangles[0].idx"}},
        {"triangle_idx_missing.patchwork", {0, "triangles[0].idx"}},
        {"triangle_index_out_of_range.patchwork", {0, "triangles[0].idx[9]"}},
        {"triangle_name_number.patchwork", {0, "triangles[1].name"}},
        {"triangle_nan.patchwork", {5, ""}},
        {"triangle_negative_index.patchwork", {0, "triangles[0].idx[4]"}},
        {"triangle_not_object.patchwork", {0, "triangles[0]"}},
        {"triangle_tess_count.patchwork", {0, "triangles[0].tess"}},
        {"triangle_tess_level.patchwork", {0, "triangles[0].tess[3]"}},
        {"triangles_not_array.patchwork", {0, "triangles"}},
        // .patchwork: cubic Bézier curves and the isoline levels
        {"curve_fractional_index.patchwork", {0, "curves[0].idx[1]"}},
        {"curve_idx_count.patchwork", {0, "curves[0].idx"}},
        {"curve_idx_missing.patchwork", {0, "curves[0].idx"}},
        {"curve_index_out_of_range.patchwork", {0, "curves[0].idx[2]"}},
        {"curves_not_array.patchwork", {0, "curves"}},
        {"tess_isoline_level.patchwork", {0, "tess.isoline[1]"}},
    };
    return table;
}

// tests/CMakeLists.txt passes a list to gtest_discover_tests' ENVIRONMENT, of which CMake 3.25
// keeps only the first entry (PATCHWORK_DATA_DIR): fall back on paths derived from it and from
// this executable (<build>/tests/test_bad_input → <build>/app/patchwork) when the others are unset.
fs::path testsDir() {
    if (std::getenv("PATCHWORK_TESTS_DIR")) return test::testsDir();
    return test::dataDir().parent_path() / "tests";
}

fs::path patchworkBinary() {
    if (std::getenv("PATCHWORK_BIN")) return test::patchworkBinary();
    return fs::read_symlink("/proc/self/exe").parent_path().parent_path() / "app" / "patchwork";
}

fs::path corpusDir() { return testsDir() / "corpus" / "bad"; }

std::vector<fs::path> corpusFiles() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(corpusDir()))
        if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string quote(const fs::path& p) {
    std::string s = "'";
    for (char c : p.string()) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return s + "'";
}

std::string bin() { return quote(patchworkBinary()); }

std::vector<std::string> listDir(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// "patchwork: <file>...: reason" on exactly one line.
void expectOneLineError(const test::RunResult& r, const std::string& file) {
    EXPECT_EQ(r.exitCode, 2) << r.output;
    std::string out = r.output;
    while (!out.empty() && out.back() == '\n') out.pop_back();
    EXPECT_EQ(out.find('\n'), std::string::npos) << r.output;
    EXPECT_EQ(out.rfind("patchwork: ", 0), 0u) << r.output;
    EXPECT_NE(out.find(file), std::string::npos) << r.output;
}

}  // namespace

TEST(BadInput, CorpusAndTableAgree) {
    const auto files = corpusFiles();
    ASSERT_GE(files.size(), 60u);
    for (const fs::path& f : files) EXPECT_TRUE(expectedLocations().count(f.filename().string())) << f << " has no expected location";
    for (const auto& [name, where] : expectedLocations()) EXPECT_TRUE(fs::exists(corpusDir() / name)) << name << " missing from the corpus";
}

TEST(BadInput, EveryCorpusFileIsRefusedWithItsLocation) {
    for (const fs::path& f : corpusFiles()) {
        const std::string name = f.filename().string();
        SCOPED_TRACE(name);
        try {
            loadDocument(f);
            ADD_FAILURE() << "no error for " << name;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(f.string()), std::string::npos) << what;
            EXPECT_EQ(e.file(), f.string());
            EXPECT_TRUE(e.line() > 0 || !e.field().empty()) << what;
            EXPECT_FALSE(e.reason().empty());
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
            auto it = expectedLocations().find(name);
            if (it != expectedLocations().end()) {
                EXPECT_EQ(e.line(), it->second.line) << what;
                EXPECT_EQ(e.field(), it->second.field) << what;
                if (e.line() > 0) {
                    EXPECT_NE(what.find(f.string() + ":" + std::to_string(e.line()) + ": "), std::string::npos) << what;
                }
                if (!e.field().empty()) {
                    EXPECT_NE(what.find("'" + e.field() + "'"), std::string::npos) << what;
                }
            }
        } catch (const std::exception& e) {
            ADD_FAILURE() << name << ": not an InputError: " << e.what();
        }
    }
}

TEST(BadInput, SpecificMessages) {
    auto message = [](const std::string& name) {
        try {
            loadDocument(corpusDir() / name);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("<no error>");
    };
    EXPECT_NE(message("bad_degree.bpt").find("degree 2 3"), std::string::npos);
    EXPECT_NE(message("nan.bpt").find("not finite"), std::string::npos);
    EXPECT_NE(message("huge.bpt").find("too large"), std::string::npos);
    EXPECT_NE(message("missing_number.bpt").find("expected 3 numbers"), std::string::npos);
    EXPECT_NE(message("truncated.bpt").find("ends early"), std::string::npos);
    EXPECT_NE(message("trailing_garbage.bpt").find("after the last"), std::string::npos);
    EXPECT_NE(message("count_above_limit.bpt").find("limit"), std::string::npos);
    EXPECT_NE(message("newer_version.patchwork").find("was written by a newer Patchwork (format version 2); this build reads version 1"),
              std::string::npos);
    EXPECT_NE(message("malformed.patchwork").find("JSON syntax error"), std::string::npos);
    EXPECT_NE(message("index_out_of_range.patchwork").find("out of range"), std::string::npos);
}

TEST(BadInput, DirectoryMissingFileAndUnknownExtension) {
    const fs::path dir = test::freshTempDir("badfs");
    fs::create_directories(dir / "x.patchwork");
    fs::create_directories(dir / "y.bpt");
    for (const fs::path& p :
         {dir / "x.patchwork", dir / "y.bpt", dir / "missing.patchwork", dir / "missing.bpt", dir / "missing.glb", dir / "model.obj"}) {
        SCOPED_TRACE(p.string());
        try {
            loadDocument(p);
            ADD_FAILURE() << "no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
        }
    }
}

TEST(BadInput, HugeClaimedCountOnAShortFileIsCheap) {
    // A count within the limit but far beyond the data must fail at the end of the file, not
    // allocate for the claim.
    std::string text = "200000\n3 3\n";
    for (int k = 0; k < 16; ++k) text += "0 0 0\n";
    try {
        parseBpt(text, "claim.bpt");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 19);
    }
}

// A count whose points exceed the limit (each .bpt patch lists its own 16) is refused at line 1,
// from the file's first bytes, whatever follows (issue 44: a million identical patches ran 30 s
// into bad_alloc).
TEST(BadInput, BptCountBeyondThePointLimitIsRefusedAtLineOne) {
    const auto dir = test::freshTempDir("bpt-count");
    std::string text = "300000\n3 3\n";
    for (int k = 0; k < 16; ++k) text += "0 0 0\n";
    std::ofstream(dir / "many.bpt", std::ios::binary) << text;
    try {
        loadBpt(dir / "many.bpt");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 1);
        EXPECT_NE(e.reason().find("4800000 control points; the limit is 4000000"), std::string::npos) << e.reason();
    }
    std::filesystem::remove_all(dir);
}

// Stacked copies of one patch share every edge: no pair is joined (n copies would give n² joins)
// and the reader says so.
TEST(BadInput, EdgesSharedByMoreThanTwoPatchesAreLeftUnjoinedWithANote) {
    std::string text = "300\n";
    for (int p = 0; p < 300; ++p) {
        text += "3 3\n";
        for (int k = 0; k < 16; ++k) text += std::to_string(k % 4) + " " + std::to_string(k / 4) + " 0\n";
    }
    std::vector<std::string> notes;
    const Document doc = parseBpt(text, "stack.bpt", &notes);
    EXPECT_EQ(doc.patches.size(), 300u);
    EXPECT_TRUE(doc.joins.empty());
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("4 edges are shared by more than two patches"), std::string::npos) << notes[0];
}

// ---------------------------------------------------------------------------------------------
// Command line

TEST(BadInputCli, HelpWorksForEachCommand) {
    for (const char* cmd : {"info", "convert"}) {
        const auto r = test::runCommand(bin() + " " + cmd + " --help");
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find(cmd), std::string::npos) << r.output;
    }
    const auto r = test::runCommand(bin() + " info --help");
    EXPECT_NE(r.output.find("--json"), std::string::npos) << r.output;
}

TEST(BadInputCli, InfoOnBadFilesExitsTwoWithOneLine) {
    for (const char* name :
         {"truncated.bpt", "nan.bpt", "malformed.patchwork", "index_out_of_range.patchwork", "newer_version.patchwork", "empty.bpt"}) {
        const fs::path f = corpusDir() / name;
        const auto r = test::runCommand(bin() + " info " + quote(f));
        SCOPED_TRACE(name);
        expectOneLineError(r, f.string());
    }
    const auto r = test::runCommand(bin() + " info " + quote(corpusDir() / "truncated.bpt"));
    EXPECT_NE(r.output.find("truncated.bpt:27: "), std::string::npos) << r.output;
    const auto missing = test::runCommand(bin() + " info /nonexistent/nothing.patchwork");
    expectOneLineError(missing, "/nonexistent/nothing.patchwork");
}

TEST(BadInputCli, ConvertFromBadFileLeavesNothing) {
    const fs::path dir = test::freshTempDir("convbad");
    for (const char* out : {"out.patchwork", "out.bpt", "out.gltf", "out.glb"}) {
        const fs::path in = corpusDir() / "letters.bpt";
        const auto r = test::runCommand(bin() + " convert " + quote(in) + " " + quote(dir / out));
        SCOPED_TRACE(out);
        expectOneLineError(r, in.string());
        EXPECT_TRUE(listDir(dir).empty());
    }
}

TEST(BadInputCli, ConvertIntoMissingDirectoryLeavesNothing) {
    const fs::path dir = test::freshTempDir("convnodir");
    const fs::path teapot = test::dataDir() / "teapot.bpt";
    for (const char* out : {"out.patchwork", "out.bpt", "out.gltf", "out.glb"}) {
        const fs::path target = dir / "no" / "such" / "dir" / out;
        const auto r = test::runCommand(bin() + " convert " + quote(teapot) + " " + quote(target));
        SCOPED_TRACE(out);
        expectOneLineError(r, target.string());
        EXPECT_TRUE(listDir(dir).empty());
    }
    // A target that is itself a directory.
    fs::create_directories(dir / "taken.patchwork");
    const auto r = test::runCommand(bin() + " convert " + quote(teapot) + " " + quote(dir / "taken.patchwork"));
    expectOneLineError(r, (dir / "taken.patchwork").string());
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"taken.patchwork"});
    EXPECT_TRUE(listDir(dir / "taken.patchwork").empty());
}

TEST(BadInputCli, FailedConversionLeavesExistingOutputIntact) {
    const fs::path dir = test::freshTempDir("convkeep");
    for (const char* out : {"keep.patchwork", "keep.bpt", "keep.glb"}) {
        const fs::path target = dir / out;
        { std::ofstream(target, std::ios::binary) << "ORIGINAL CONTENT\n"; }
        const fs::path in = corpusDir() / "index_out_of_range.patchwork";
        const auto r = test::runCommand(bin() + " convert " + quote(in) + " " + quote(target));
        SCOPED_TRACE(out);
        expectOneLineError(r, in.string());
        EXPECT_EQ(test::readBytes(target), "ORIGINAL CONTENT\n");
    }
    // Unknown output type: refused before anything is read or written.
    const auto r = test::runCommand(bin() + " convert " + quote(test::dataDir() / "teapot.bpt") + " " + quote(dir / "x.fbx"));
    expectOneLineError(r, (dir / "x.fbx").string());
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"keep.bpt", "keep.glb", "keep.patchwork"}));
}

TEST(GoodInputCli, InfoAndConvertRoundTrip) {
    const fs::path teapot = test::dataDir() / "teapot.bpt";
    auto r = test::runCommand(bin() + " info " + quote(teapot));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("points      290"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("patches     32"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("joins       52  (C0 0, C1 46, G1 6, C2 0, G2 0)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("max constraint residual"), std::string::npos) << r.output;

    r = test::runCommand(bin() + " info --json " + quote(teapot) + " 2>/dev/null");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j["points"], 290);
    EXPECT_EQ(j["patches"], 32);
    EXPECT_EQ(j["windows"], 32);
    EXPECT_EQ(j["joins"]["total"], 52);
    EXPECT_EQ(j["joins"]["C1"], 46);
    EXPECT_EQ(j["joins"]["G1"], 6);
    EXPECT_EQ(j["joinReport"].size(), 52u);
    EXPECT_LE(j["maxConstraintResidual"].get<double>(), 1e-6 * j["modelSize"].get<double>());

    const fs::path dir = test::freshTempDir("convgood");
    r = test::runCommand(bin() + " convert " + quote(teapot) + " " + quote(dir / "pot.patchwork"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = test::runCommand(bin() + " convert " + quote(dir / "pot.patchwork") + " " + quote(dir / "pot2.bpt"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"pot.patchwork", "pot2.bpt"}));
    Document a = loadDocument(teapot), b = loadDocument(dir / "pot.patchwork"), c = loadDocument(dir / "pot2.bpt");
    EXPECT_TRUE(a == b);
    c.name = a.name;
    EXPECT_TRUE(a == c);
}

// `patchwork export --as-displayed` (validation layer on through PATCHWORK_VALIDATION, exit 1 on
// any message): the file holds the GPU's triangles for the document's own settings, passes the
// Khronos validator, says so in its extras and is reproduced byte for byte by a re-export or a
// convert without flags; misuse exits 2 and writes nothing.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/io/document_io.hpp"
#include "core/io/export_options.hpp"
#include "core/io/gltf_import.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

namespace fs = std::filesystem;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }
std::string bin() { return q(patchworkBinary()); }

// The teapot as a .patchwork with adaptive levels, fractional_odd, culling off screen.
fs::path adaptiveTeapot(const fs::path& dir) {
    Document doc = loadDocument(dataDir() / "teapot.bpt");
    doc.tess.spacing = Spacing::FractionalOdd;
    doc.tess.adaptive = AdaptiveMode::ScreenSpace;
    doc.tess.targetPixels = 12.0f;
    const fs::path p = dir / "adaptive.patchwork";
    saveDocument(doc, p);
    return p;
}

size_t trianglesSaid(const std::string& out, const std::string& after) {
    const size_t at = out.find(after);
    if (at == std::string::npos) return 0;
    return std::stoul(out.substr(at + after.size()));
}

TEST(ExportDisplayed, WritesTheGpusTrianglesValidAndReproducible) {
    const fs::path dir = freshTempDir("export-displayed");
    const fs::path doc = adaptiveTeapot(dir), glb = dir / "shown.glb", level = dir / "level.glb";
    RunResult r = runCommand(bin() + " export " + q(doc) + " -o " + q(glb) + " --as-displayed --size 640x400");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("as displayed at 640x400 on "), std::string::npos) << r.output;
    const size_t gpu = trianglesSaid(r.output, ": ");
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    // Screen-space levels: not what the document's uniform level gives.
    r = runCommand(bin() + " export " + q(doc) + " -o " + q(level));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const size_t written = trianglesSaid(r.output, "wrote " + level.string() + ": ");
    EXPECT_GT(gpu, 0u);
    EXPECT_NE(gpu, written + 8 * 16);  // the level export leaves out 8 x 16 pole triangles
    expectValidGltf({glb});

    // The extras say how it was made, and the editable document is still there.
    std::optional<ExportOptions> options;
    const Document back = importPatchworkGltf(glb, &options);
    ASSERT_TRUE(options);
    EXPECT_TRUE(options->asDisplayed);
    EXPECT_EQ(options->viewport, (std::array<int, 2>{640, 400}));
    EXPECT_EQ(back.tess.adaptive, AdaptiveMode::ScreenSpace);

    // A re-export and a convert without flags capture again, at the same size: the same bytes.
    const fs::path again = dir / "again.glb", converted = dir / "converted.glb";
    r = runCommand(bin() + " export " + q(glb) + " -o " + q(again));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("as displayed at 640x400"), std::string::npos) << r.output;
    EXPECT_EQ(readBytes(again), readBytes(glb));
    r = runCommand(bin() + " convert " + q(glb) + " " + q(converted));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readBytes(converted), readBytes(glb));
    // The same when the capture's first buffer is too small for all its pieces and it tries again.
    r = runCommand("PATCHWORK_CAPTURE_FIRST_BYTES=100000 " + bin() + " export " + q(glb) + " -o " + q(again));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    EXPECT_EQ(readBytes(again), readBytes(glb));
    // --tess or --no-as-displayed go back to the level.
    r = runCommand(bin() + " export " + q(glb) + " -o " + q(again) + " --no-as-displayed");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("as displayed"), std::string::npos) << r.output;
}

// What the view culled is said in the extras (and on stdout): the back faces of a culling teapot.
TEST(ExportDisplayed, TheExtrasSayWhatTheViewCulled) {
    const fs::path dir = freshTempDir("export-displayed-culled");
    Document doc = loadDocument(dataDir() / "teapot.bpt");
    doc.tess.cullBackfaces = true;
    const fs::path in = dir / "culling.patchwork", glb = dir / "shown.glb", plain = dir / "plain.glb";
    saveDocument(doc, in);
    RunResult r = runCommand(bin() + " export " + q(in) + " -o " + q(glb) + " --as-displayed");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const size_t at = r.output.find(" patches culled as on screen");  // "..., N patches culled as on screen"
    ASSERT_NE(at, std::string::npos) << r.output;
    const size_t said = std::stoul(r.output.substr(r.output.rfind(", ", at) + 2));
    EXPECT_GT(said, 0u) << r.output;
    std::optional<ExportOptions> options;
    (void)importPatchworkGltf(glb, &options);
    ASSERT_TRUE(options);
    EXPECT_EQ(options->culledPatches, int64_t(said));
    // A fixed level culls nothing and says nothing of culling.
    r = runCommand(bin() + " export " + q(in) + " -o " + q(plain) + " --tess 4");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    (void)importPatchworkGltf(plain, &options);
    ASSERT_TRUE(options);
    EXPECT_FALSE(options->asDisplayed);
    EXPECT_EQ(options->culledPatches, -1);
    EXPECT_EQ(trianglesSaid(r.output, "wrote " + plain.string() + ": "), 32u * 4 * 4 * 2 - 8 * 4);  // less the pole triangles
}

TEST(ExportDisplayed, ObjHoldsTheSameTriangles) {
    const fs::path dir = freshTempDir("export-displayed-obj");
    const fs::path doc = adaptiveTeapot(dir), glb = dir / "shown.glb", obj = dir / "shown.obj";
    RunResult r = runCommand(bin() + " export " + q(doc) + " -o " + q(glb) + " --as-displayed");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const size_t inGlb = trianglesSaid(r.output, "wrote " + glb.string() + ": ");
    r = runCommand(bin() + " export " + q(doc) + " -o " + q(obj) + " --as-displayed");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(trianglesSaid(r.output, "wrote " + obj.string() + " and shown.mtl: "), inGlb) << r.output;
    std::ifstream in(obj);
    std::string first;
    std::getline(in, first);
    EXPECT_NE(first.find("as displayed"), std::string::npos) << first;
}

TEST(ExportDisplayed, MisuseExitsTwoAndWritesNothing) {
    const fs::path dir = freshTempDir("export-displayed-bad");
    const fs::path doc = dataDir() / "teapot.bpt";
    struct Case {
        std::string out, args, says;
    };
    const Case cases[] = {{"x.glb", "--as-displayed --tess 8", "--tess"},
                          {"x.step", "--as-displayed", "STEP is exact"},
                          {"x.glb", "--as-displayed --size 0x10", "--size"},
                          {"x.obj", "--as-displayed --device no-such-gpu-xyz", "no-such-gpu-xyz"}};
    for (const Case& c : cases) {
        const RunResult r = runCommand(bin() + " export " + q(doc) + " -o " + q(dir / c.out) + " " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_EQ(entryCount(dir), 0u) << c.args;
    }
}

}  // namespace
}  // namespace pw::test

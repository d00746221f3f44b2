// Distance-adaptive and culling figures from the command line (issue 41): the notes' distance
// formulas as presets (from the patch centre or per edge, the terrain notes' pow2 curve), the debug
// camera that draws the patches the view culls greyed in place with the view's frustum, and a
// wireframe that stays readable at any level. Validation layer on (non-zero exit on any message).
#include <gtest/gtest.h>

#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/gpu/patch_math.h"
#include "core/io/document_io.hpp"
#include "render_support.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

std::string bin() { return "PATCHWORK_VALIDATION=1 " + patchworkBinary().string(); }

struct Figure {
    Png image;
    nlohmann::json stats;
};

// `render` of the built-in teapot with `opts`, its PNG and statistics.
Figure renderTeapot(const std::filesystem::path& dir, const std::string& opts) {
    const auto png = dir / "f.png", stats = dir / "f.json";
    const RunResult r =
        runCommand(bin() + " render --size 480x270 " + opts + " -o " + png.string() + " --stats " + stats.string() + " 2>&1");
    EXPECT_EQ(r.exitCode, 0) << opts << ": " << r.output;
    std::ifstream in(stats);
    return {loadPng(png), nlohmann::json::parse(in)};
}

size_t countPixels(const Png& img, bool (*match)(const uint8_t*)) {
    size_t n = 0;
    for (int y = 0; y < img.h; ++y)
        for (int x = 0; x < img.w; ++x) n += match(img.at(x, y));
    return n;
}

bool frustumOrange(const uint8_t* p) { return p[0] > 220 && p[1] > 110 && p[1] < 180 && p[2] < 70; }

// The view close to the teapot culls most of its patches off screen. Seen from the debug camera the
// same patches are culled (the same count: the view still decides), but drawn greyed, so more
// triangles reach the screen, and the view's frustum is drawn in orange; bad points are exit 2.
TEST(DistanceFigures, DebugCameraDrawsTheCulledPatchesAndTheFrustum) {
    const auto dir = freshTempDir("dist-debug");
    const std::string view = "--tess 6 --eye 1,-2.5,1.5 --target 1.5,0,1.2 ";
    const Figure seen = renderTeapot(dir, view);
    const Figure debug = renderTeapot(dir, view + "--debug-camera auto");
    const uint64_t culled = seen.stats["patches_culled"].get<uint64_t>();
    EXPECT_GT(culled, 8u);
    EXPECT_LT(culled, 32u);
    EXPECT_EQ(debug.stats["patches_culled"].get<uint64_t>(), culled);
    // Level 6, equal: 72 triangles a patch; the debug view draws all 32.
    EXPECT_EQ(seen.stats["triangles"].get<uint64_t>(), (32 - culled) * 72);
    EXPECT_EQ(debug.stats["triangles"].get<uint64_t>(), 32u * 72);
    EXPECT_EQ(countPixels(seen.image, frustumOrange), 0u);
    EXPECT_GT(countPixels(debug.image, frustumOrange), 150u);
    const Figure placed = renderTeapot(dir, view + "--debug-camera 6,-6,5");
    EXPECT_GT(countPixels(placed.image, frustumOrange), 100u);
    for (const std::string bad : {"--debug-camera 1,2", "--debug-camera far", "--debug-camera 1,2,nan"}) {
        const RunResult r = runCommand(bin() + " render " + bad + " -o " + (dir / "x.png").string() + " 2>&1");
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << bad;
    }
}

// Export as displayed under a debug camera captures what the frozen camera sees (its levels and
// culling), not the greyed patches the debug view draws: the same mesh as capturing from it.
class DebugCameraCapture : public RenderTest {};

TEST_F(DebugCameraCapture, IsTheFrozenCamerasView) {
    const Document doc = loadDocument(dataDir() / "teapot.bpt");
    Offscreen off(480, 270, false);
    off.setDocument(doc);
    render::RenderOptions frozen = plainOptions(doc, 6, 480.0 / 270.0);
    frozen.camera = *lookFrom(frozen.camera, {1, -2.5, 1.5}, {1.5, 0, 1.2});
    render::RenderOptions debug = frozen;
    debug.lodCamera = frozen.camera;
    debug.camera = *lookFrom(frozen.camera, {6, -6, 5}, {0, 0, 1});
    const render::CapturedSurface a = off.capture(frozen), b = off.capture(debug);
    EXPECT_GT(a.patchesCulled, 8u);
    EXPECT_EQ(b.patchesCulled, a.patchesCulled);
    EXPECT_EQ(b.gpuTriangles, a.gpuTriangles);
    EXPECT_EQ(b.mesh.indices.size(), a.mesh.indices.size());
}

// The notes' formula measured from the patch centre (`--adaptive notes`) and per edge
// (`notes-edges`) cull the same patches (the far cull is the centre's in both) but tessellate
// differently; `--distance-from`, `--distance-curve` and `--distance-exponents` set the same by hand;
// wrong words and numbers are exit 2.
TEST(DistanceFigures, NotesFormulasFromTheCentreOrPerEdge) {
    const auto dir = freshTempDir("dist-notes");
    const std::string view = "--eye 0,-6,3 --target 0,0,1 --distance 4,7.5 ";
    const Figure centre = renderTeapot(dir, view + "--adaptive notes");
    const Figure edges = renderTeapot(dir, view + "--adaptive notes-edges");
    const Figure byHand = renderTeapot(dir, view + "--adaptive distance --max-level 64 --cull-far --distance-from centre");
    EXPECT_GT(centre.stats["patches_culled"].get<uint64_t>(), 0u);
    EXPECT_EQ(centre.stats["patches_culled"], edges.stats["patches_culled"]);
    EXPECT_NE(centre.stats["triangles"], edges.stats["triangles"]);
    EXPECT_EQ(byHand.stats["triangles"], centre.stats["triangles"]);
    // The pow2 curve with exponents 6 and 6 is level 64 everywhere: 8192 triangles a patch.
    const Figure flat = renderTeapot(dir, view + "--adaptive distance --distance-curve pow2 --distance-exponents 6,6");
    EXPECT_EQ(flat.stats["triangles"].get<uint64_t>(), 32u * 8192);
    for (const std::string bad : {"--adaptive notes-centre", "--distance-from middle", "--distance-curve cubic",
                                  "--distance-exponents 40,4", "--distance-exponents 4"}) {
        const RunResult r = runCommand(bin() + " render " + bad + " -o " + (dir / "x.png").string() + " 2>&1");
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << bad;
    }
}

// The wire fades where its segments get small on screen (core/gpu/patch_math.h wireOpacity): at
// level 64 it changes the picture little more than at 16, where it stays opaque and crisp; before,
// level 64 turned the model black.
TEST(DistanceFigures, DenseWireframeStaysReadable) {
    EXPECT_FLOAT_EQ(gpu::wireOpacity(16.0f), 1.0f);
    EXPECT_FLOAT_EQ(gpu::wireOpacity(2.0f), 0.25f);
    EXPECT_FLOAT_EQ(gpu::wireOpacity(0.0f), 0.0f);
    // One segment of level 8 along a unit derivative 5 units in front of a 90° camera on 400 px: 400 / 2 / 5 / 8 = 5 px.
    const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
    EXPECT_NEAR(gpu::segmentPixels(glm::vec3(0, 0, -5), glm::vec3(1, 0, 0), 8.0f, proj, glm::vec2(400, 400)), 5.0f, 1e-3f);

    const auto dir = freshTempDir("dist-wire");
    const auto darkening = [&](const std::string& level) {
        const Figure lit = renderTeapot(dir, "--tess " + level);
        const Figure wired = renderTeapot(dir, "--tess " + level + " --overlay wire");
        double sum = 0.0;
        size_t n = 0;
        for (int y = 0; y < lit.image.h; ++y)
            for (int x = 0; x < lit.image.w; ++x) {
                const uint8_t *a = lit.image.at(x, y), *b = wired.image.at(x, y);
                if (a[0] < 80) continue;  // the background and the darkest shading
                sum += (a[0] + a[1] + a[2]) - (b[0] + b[1] + b[2]);
                ++n;
            }
        return sum / double(std::max<size_t>(n, 1)) / 3.0;
    };
    const double at16 = darkening("16"), at64 = darkening("64");
    EXPECT_GT(at16, 5.0);
    EXPECT_LT(at64, 2.0 * at16);
}

}  // namespace
}  // namespace pw::test

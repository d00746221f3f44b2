// Tessellators compared (issue 41, item 5): lavapipe's live patterns equal the capture shipped in
// data/captures; `patchwork capture` writes a file whose counts are the rules'; `render
// --compare-device FILE` draws this device beside the file's, counts and highlights the primitives
// that differ (none against itself, both triangles of a flipped diagonal), and refuses a set the
// file lacks (exit 2, naming the file). Validation layer on.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/io/tess_capture_file.hpp"
#include "core/tess/tess_presets.hpp"
#include "render/domain/domain_view.hpp"
#include "render_support.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

std::string bin() { return "PATCHWORK_VALIDATION=1 " + patchworkBinary().string(); }
std::filesystem::path lavapipeFile() { return dataDir() / "captures" / "lavapipe.json"; }

class DeviceCompare : public RenderTest {};

TEST_F(DeviceCompare, LavapipeMakesTheShippedPatternsBitForBit) {
    render::Device& dev = sharedDevice();
    if (dev.name().find("llvmpipe") == std::string::npos) GTEST_SKIP() << "not lavapipe: " << dev.name();
    render::DomainView view(dev, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_UNDEFINED, VK_SAMPLE_COUNT_1_BIT);
    const TessCaptureFile shipped = loadTessCaptureFile(lavapipeFile());
    ASSERT_GE(shipped.patterns.size(), tessPresets().size());  // every preset (test_tess_capture.cpp checks which)
    for (const TessPattern& want : shipped.patterns) {
        SCOPED_TRACE(describeSet(want.kind, want.spacing, want.levels));
        const TessPattern live = view.capture({want.kind, want.levels, want.spacing});
        EXPECT_EQ(live.uv, want.uv);  // the same points in the same emission order
    }
}

// Both triangles of one quad cell of `p` turned about the other diagonal (the choice a tessellator
// is free to make differently).
void flipOneDiagonal(TessPattern& p) {
    for (size_t a = 0; a < p.primitives(); ++a)
        for (size_t b = a + 1; b < p.primitives(); ++b) {
            auto* t1 = &p.uv[3 * a];
            auto* t2 = &p.uv[3 * b];
            // Shared edge: two points of t1 found in t2.
            std::vector<int> shared1, shared2;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    if (t1[i] == t2[j]) shared1.push_back(i), shared2.push_back(j);
            if (shared1.size() != 2) continue;
            const int o1 = 3 - shared1[0] - shared1[1], o2 = 3 - shared2[0] - shared2[1];
            const auto x = t1[o1], y = t2[o2], s0 = t1[shared1[0]], s1 = t1[shared1[1]];
            // Only a convex cell: the new diagonal x-y crosses the old one s0-s1 (no sliver made).
            const auto side = [](std::array<float, 2> p, std::array<float, 2> q, std::array<float, 2> r) {
                return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
            };
            if (side(x, y, s0) * side(x, y, s1) >= 0.0f || side(s0, s1, x) * side(s0, s1, y) >= 0.0f) continue;
            t1[0] = x, t1[1] = y, t1[2] = s0;
            t2[0] = y, t2[1] = x, t2[2] = s1;
            return;
        }
}

size_t highlightPixels(const Png& png, int x0, int x1) {
    size_t n = 0;
    for (int y = 0; y < png.h; ++y)
        for (int x = x0; x < x1; ++x) {
            const uint8_t* c = png.at(x, y);
            n += std::abs(c[0] - 250) < 6 && std::abs(c[1] - 153) < 6 && std::abs(c[2] - 56) < 6;
        }
    return n;
}

TEST(DeviceCompareCli, CaptureThenCompareHighlightsExactlyWhatDiffers) {
    const auto dir = freshTempDir("device-compare");
    const std::string set = "--preset quad-1_2_3_4-4_4 --spacing fractional_odd";
    // A capture of one preset under all four partitionings, counts as the rules say.
    const RunResult cap = runCommand(bin() + " capture --preset quad-1_2_3_4-4_4 --spacing all -o " + (dir / "c.json").string() + " 2>&1");
    ASSERT_EQ(cap.exitCode, 0) << cap.output;
    EXPECT_NE(cap.output.find("4 of 4 have the primitive count the rules predict"), std::string::npos) << cap.output;
    TessCaptureFile file = loadTessCaptureFile(dir / "c.json");
    ASSERT_EQ(file.patterns.size(), 4u);

    // Against itself: nothing differs, nothing highlighted.
    const auto png = dir / "same.png", stats = dir / "same.json";
    RunResult r = runCommand(bin() + " render " + set + " --compare-device " + (dir / "c.json").string() + " --size 800x400 -o " +
                             png.string() + " --stats " + stats.string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("the same pattern"), std::string::npos) << r.output;
    nlohmann::json j = nlohmann::json::parse(readBytes(stats));
    EXPECT_TRUE(j["identical"].get<bool>());
    const DomainCounts want = expectedDomainCounts(DomainKind::Quad, {{1, 2, 3, 4}, {4, 4}}, Spacing::FractionalOdd);
    EXPECT_EQ(j["this"]["primitives"].get<uint64_t>(), want.primitives);
    EXPECT_EQ(j["other"]["points"].get<uint64_t>(), want.vertices);
    Png same = loadPng(png);
    ASSERT_EQ(same.w, 800);
    EXPECT_EQ(highlightPixels(same, 0, 800), 0u);

    // One diagonal flipped in the file: two triangles differ on each side, highlighted on both.
    for (TessPattern& p : file.patterns)
        if (p.spacing == Spacing::FractionalOdd) flipOneDiagonal(p);
    file.device = "Imaginary GPU (flipped)";
    std::ofstream(dir / "flipped.json") << writeTessCaptureFile(file);
    r = runCommand(bin() + " render " + set + " --compare-device " + (dir / "flipped.json").string() + " --size 800x400 -o " +
                   png.string() + " --stats " + stats.string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("the patterns differ"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("Imaginary GPU"), std::string::npos) << r.output;
    j = nlohmann::json::parse(readBytes(stats));
    EXPECT_FALSE(j["identical"].get<bool>());
    EXPECT_EQ(j["this"]["primitivesDiffering"].get<uint64_t>(), 2u);
    EXPECT_EQ(j["other"]["primitivesDiffering"].get<uint64_t>(), 2u);
    const Png flipped = loadPng(png);
    EXPECT_GT(highlightPixels(flipped, 0, 400), 50u);
    EXPECT_GT(highlightPixels(flipped, 400, 800), 50u);

    // The same comparison as SVG: one highlighted path a differing triangle on each side.
    const auto svg = dir / "f.svg";
    r = runCommand(bin() + " render " + set + " --compare-device " + (dir / "flipped.json").string() + " -o " + svg.string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string text = readBytes(svg);
    size_t fills = 0;
    for (size_t at = text.find("rgb(98."); at != std::string::npos; at = text.find("rgb(98.", at + 1)) ++fills;
    EXPECT_EQ(fills, 4u) << "highlight fills in the SVG";
}

// The NVIDIA H200's shipped capture (driver 580.159.04) has lavapipe's triangles, bit for bit, but
// emits them in another order: the figure numbers them and says so.
TEST(DeviceCompareCli, TheShippedNvidiaCaptureHasTheSameTrianglesInAnotherOrder) {
    const auto dir = freshTempDir("device-compare-nvidia");
    const RunResult r = runCommand(bin() + " render --preset tri-4.9_4.5_4.1-4.4-fractional_odd --compare-device " +
                                   (dataDir() / "captures" / "nvidia_h200.json").string() + " -o " + (dir / "c.svg").string() +
                                   " --stats " + (dir / "c.json").string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("NVIDIA H200"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("emitted in another order"), std::string::npos) << r.output;
    const nlohmann::json j = nlohmann::json::parse(readBytes(dir / "c.json"));
    EXPECT_TRUE(j["identical"].get<bool>());
    EXPECT_FALSE(j["sameOrder"].get<bool>());
    EXPECT_EQ(j["other"]["device"], "NVIDIA H200");
}

TEST(DeviceCompareCli, RefusesWhatItCannotCompare) {
    const auto dir = freshTempDir("device-compare-bad");
    const auto out = dir / "x.png";
    // A set the file does not hold: exit 2 naming the file and the set, nothing written.
    RunResult r = runCommand(bin() + " render --domain quad --outer 7,7,7,7 --inner 7,7 --compare-device " + lavapipeFile().string() +
                             " -o " + out.string() + " 2>&1");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("lavapipe.json"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("no capture of quad {7,7,7,7 | 7,7} equal"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
    // A model, or several panes, cannot be compared.
    r = runCommand(bin() + " render --compare-device " + lavapipeFile().string() + " -o " + out.string() + " 2>&1");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    r = runCommand(bin() + " render --preset quad-4_4_4_4-4_4 --compare equal,fractional_odd --compare-device " + lavapipeFile().string() +
                   " -o " + out.string() + " 2>&1");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    // A file that is not a capture: exit 2 naming the field.
    std::ofstream(dir / "not.json") << R"({"format":"other"})";
    r = runCommand(bin() + " render --preset quad-4_4_4_4-4_4 --compare-device " + (dir / "not.json").string() + " -o " + out.string() +
                   " 2>&1");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("format"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_EQ(entryCount(dir), 1u);  // only not.json
}

// `integer`, the notes' (D3D) name, is accepted wherever `equal` is and draws the same.
TEST(DeviceCompareCli, IntegerSpacingIsEqualSpacing) {
    const auto dir = freshTempDir("integer-spacing");
    const RunResult a =
        runCommand(bin() + " render --preset quad-1_2_3_4-4_4 --spacing integer --size 400x400 -o " + (dir / "i.png").string() + " 2>&1");
    ASSERT_EQ(a.exitCode, 0) << a.output;
    const RunResult b =
        runCommand(bin() + " render --preset quad-1_2_3_4-4_4 --spacing equal --size 400x400 -o " + (dir / "e.png").string() + " 2>&1");
    ASSERT_EQ(b.exitCode, 0) << b.output;
    EXPECT_EQ(readBytes(dir / "i.png"), readBytes(dir / "e.png"));
}

}  // namespace
}  // namespace pw::test

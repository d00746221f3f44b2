// Tessellators compared (issue 41, item 5): patterns of two devices are compared primitive by
// primitive (order, vertex rotation and float noise aside), capture files round-trip exactly and
// refuse malformed content naming the field, and the captures shipped in data/captures (lavapipe
// and an NVIDIA H200) hold every preset under every partitioning with the counts the rules predict.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/io/tess_capture_file.hpp"
#include "core/tess/tess_presets.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

// The unit square as two triangles, split along the diagonal (0,0)-(1,1) or (1,0)-(0,1).
TessPattern square(bool mainDiagonal) {
    TessPattern p;
    p.levels = {{1, 1, 1, 1}, {1, 1}};
    if (mainDiagonal)
        p.uv = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    else
        p.uv = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {0, 1}};
    return p;
}

TEST(TessPatternCompare, OrderRotationAndNoiseAreNotDifferences) {
    const TessPattern a = square(true);
    TessPattern b;
    b.levels = a.levels;
    // Second triangle first, each rotated by one vertex, every coordinate off by 2e-7.
    for (int t : {1, 0})
        for (int k : {1, 2, 0}) {
            auto q = a.uv[size_t(3 * t + k)];
            b.uv.push_back({q[0] + 2e-7f, q[1] - 2e-7f});
        }
    const PatternDiff d = comparePatterns(a, b);
    EXPECT_TRUE(d.identical());
    EXPECT_EQ(d.windingFlips, 0u);
    EXPECT_EQ(std::count(d.onlyInA.begin(), d.onlyInA.end(), 1), 0);
    EXPECT_FALSE(d.sameOrder);  // second triangle first
    EXPECT_TRUE(comparePatterns(a, a).sameOrder);
    // The same triangles wound the other way are the same triangles, counted as flips.
    TessPattern c = a;
    std::swap(c.uv[1], c.uv[2]);
    const PatternDiff e = comparePatterns(a, c);
    EXPECT_TRUE(e.identical());
    EXPECT_EQ(e.windingFlips, 1u);
}

TEST(TessPatternCompare, TheOtherDiagonalDiffersInBothTriangles) {
    const PatternDiff d = comparePatterns(square(true), square(false));
    EXPECT_FALSE(d.identical());
    EXPECT_EQ(d.primitivesOnlyA, 2u);
    EXPECT_EQ(d.primitivesOnlyB, 2u);
    EXPECT_EQ(d.pointsOnlyA + d.pointsOnlyB, 0u);  // the same four corners
    EXPECT_EQ(d.onlyInA, (std::vector<uint8_t>{1, 1}));
    // A point moved by more than the tolerance is another point.
    TessPattern moved = square(true);
    moved.uv[2] = moved.uv[3 + 1] = {1.0f, 0.999f};
    const PatternDiff m = comparePatterns(square(true), moved);
    EXPECT_EQ(m.pointsOnlyA, 1u);
    EXPECT_EQ(m.pointsOnlyB, 1u);
    EXPECT_EQ(m.primitivesOnlyA, 2u);
}

TEST(TessPatternCompare, TrianglePicturePointsAreTheEquilateralCorners) {
    const auto at = [](float u, float v) { return domainPicturePoint(DomainKind::Triangle, {u, v}); };
    EXPECT_EQ(at(1, 0), (std::array<float, 2>{0.0f, 0.0f}));
    EXPECT_EQ(at(0, 1), (std::array<float, 2>{1.0f, 0.0f}));
    EXPECT_NEAR(at(0, 0)[0], 0.5f, 1e-7f);
    EXPECT_NEAR(at(0, 0)[1], 0.8660254f, 1e-7f);
    EXPECT_EQ(domainPicturePoint(DomainKind::Quad, {0.25f, 0.75f}), (std::array<float, 2>{0.25f, 0.75f}));
}

TEST(TessCaptureFile, RoundTripsExactlyWithShortDecimals) {
    TessCaptureFile f;
    f.device = "test device";
    f.driver = "driver 1.0";
    f.vulkan = "1.3.0";
    TessPattern p;
    p.kind = DomainKind::Triangle;
    p.spacing = Spacing::FractionalOdd;
    p.levels = {{4.9f, 4.5f, 4.1f, 0.0f}, {4.4f, 0.0f}};
    p.uv = {{0.6f, 0.2f}, {1.0f / 3.0f, 0.1f}, {0.0f, 0.0f}, {0.6f, 0.2f}, {0.0f, 0.0f}, {0.0f, 1.0f}};
    f.patterns.push_back(p);
    const std::string text = writeTessCaptureFile(f);
    EXPECT_NE(text.find("0.6,0.2"), std::string::npos) << text;  // not 0.6000000238418579
    EXPECT_NE(text.find("[4.9,4.5,4.1]"), std::string::npos) << text;
    const TessCaptureFile g = readTessCaptureFile(text, "t.json");
    EXPECT_EQ(g.device, f.device);
    EXPECT_EQ(g.driver, f.driver);
    ASSERT_EQ(g.patterns.size(), 1u);
    EXPECT_EQ(g.patterns[0].uv, p.uv);  // bit for bit, in emission order
    EXPECT_TRUE(g.patterns[0].sameSet(p.kind, p.spacing, p.levels));
    EXPECT_NE(g.find(p.kind, p.spacing, p.levels), nullptr);
    EXPECT_EQ(g.find(p.kind, Spacing::Equal, p.levels), nullptr);
}

void expectRefused(const std::string& text, const std::string& field, const std::string& words) {
    try {
        (void)readTessCaptureFile(text, "bad.json");
        ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "bad.json");
        EXPECT_EQ(e.field(), field) << e.what();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

TEST(TessCaptureFile, MalformedFilesAreRefusedNamingTheField) {
    const std::string head = R"({"format":"patchwork-tessellation-capture","version":1,"device":"d","captures":[)";
    const std::string quad = R"({"domain":"quad","spacing":"equal","outer":[1,1,1,1],"inner":[1,1],)";
    expectRefused(R"({"format":"glTF","version":1,"device":"d","captures":[]})", "format", "not a tessellation capture");
    expectRefused(head + quad + R"("points":[0,0,1,0,1,1],"primitives":[0,1,3]}]})", "captures[0].primitives[2]", "out of range");
    expectRefused(head + quad + R"("points":[0,0,1,0,1],"primitives":[]}]})", "captures[0].points", "pairs");
    expectRefused(head + quad + R"("points":[0,0,1,0,1,1],"primitives":[0,1]}]})", "captures[0].primitives", "whole primitives");
    expectRefused(head + R"({"domain":"quad","spacing":"equal","outer":[1,1,1,65],"inner":[1,1],"points":[],"primitives":[]}]})",
                  "captures[0].outer[3]", "outside");
    expectRefused(head + R"({"domain":"tri","spacing":"equal","outer":[1,1,1],"inner":[1],"points":[0.7,0.7],"primitives":[]}]})",
                  "captures[0].points[0]", "triangle domain");
    expectRefused(head + R"({"domain":"hex","spacing":"equal"}]})", "captures[0].domain", "unknown value");
    const std::string one = quad + R"("points":[0,0,1,0,1,1],"primitives":[0,1,2]})";
    expectRefused(head + one + "," + one + "]}", "captures[1]", "captured twice");
}

// Every shipped capture: each preset under each partitioning, with the rules' primitive count and
// (where no ring collapses, as in the render test of captures) vertex count.
TEST(TessCaptureFile, ShippedCapturesHoldEveryPresetWithTheRulesCounts) {
    size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dataDir() / "captures")) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        SCOPED_TRACE(entry.path().string());
        const TessCaptureFile f = loadTessCaptureFile(entry.path());
        EXPECT_FALSE(f.device.empty());
        for (const TessPreset& preset : tessPresets())
            for (Spacing s : {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2}) {
                SCOPED_TRACE(describeSet(preset.kind, s, preset.levels));
                const TessPattern* p = f.find(preset.kind, s, preset.levels);
                ASSERT_NE(p, nullptr);
                const DomainCounts want = expectedDomainCounts(p->kind, p->levels, p->spacing);
                EXPECT_EQ(p->primitives(), want.primitives);
                const bool collapsedRing = p->kind == DomainKind::Triangle && s == Spacing::FractionalOdd && p->levels.inner[0] <= 1.0f;
                if (!collapsedRing) {
                    EXPECT_EQ(p->distinctPoints().size(), want.vertices);
                }
            }
    }
    EXPECT_GE(files, 2u);  // lavapipe and the NVIDIA GPU
}

}  // namespace
}  // namespace pw::test

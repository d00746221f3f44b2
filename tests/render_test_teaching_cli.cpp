// Teaching figures from the command line: `render --domain/--preset/--compare` (GPU counts against
// the rounding rules, labels drawn), `sweep` (numbered frames), `presets`; bad options are exit 2
// naming the option, and write nothing. Validation layer on (non-zero exit on any message).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "core/eval/patch_eval.hpp"
#include "core/tess/tess_presets.hpp"
#include "render/domain/domain_labels.hpp"
#include "render/figures/domain_figure.hpp"
#include "render/figures/stage_bars.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

std::string bin() { return "PATCHWORK_VALIDATION=1 " + patchworkBinary().string(); }

// Pixels of the edge-label colour (render/figures/domain_figure.cpp: dark red text) inside a rectangle.
size_t labelPixels(const Png& img, int x0, int y0, int x1, int y1) {
    size_t n = 0;
    for (int y = std::max(0, y0); y < std::min(img.h, y1); ++y)
        for (int x = std::max(0, x0); x < std::min(img.w, x1); ++x) {
            const uint8_t* p = img.at(x, y);
            n += p[0] > 120 && p[1] < 110 && p[2] < 100 && p[0] > p[1] + 50;
        }
    return n;
}

nlohmann::json readJson(const std::filesystem::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

}  // namespace

TEST(TeachingCli, PresetFigureCountsFollowTheRulesAndIsLabelled) {
    const auto dir = freshTempDir("teach-preset");
    const auto png = dir / "d.png", stats = dir / "d.json";
    const RunResult r =
        runCommand(bin() + " render --preset quad-1_2_3_4-4_4 --size 400x400 -o " + png.string() + " --stats " + stats.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = readJson(stats);
    ASSERT_EQ(j["panes"].size(), 1u);
    const auto& p = j["panes"][0];
    EXPECT_TRUE(p["statisticsValid"].get<bool>());
    // lavapipe runs the evaluation shader once per distinct vertex: 1+2+3+4 boundary + 3x3 interior.
    EXPECT_EQ(p["evaluations"].get<uint64_t>(), 19u);
    EXPECT_EQ(p["primitives"].get<uint64_t>(), 26u);
    EXPECT_EQ(p["evaluations"], p["expectedVertices"]);
    const Png img = loadPng(png);
    ASSERT_EQ(img.w, 400);
    // The four edge labels sit in the margins beside the middle of each edge; nothing red elsewhere
    // in the corners.
    render::DomainViewOptions o;
    o.rect = {0, 0, 400, 400};
    o.margin = render::domainLabelMargin(std::clamp(400.0f / 26.0f, 11.0f, 40.0f));
    const render::DomainPlacement at = render::placeDomain(o);
    const int left = int(at.originX), right = int(at.originX + at.size), top = int(at.originY - at.size), bottom = int(at.originY);
    const int mid = (top + bottom) / 2, cx = (left + right) / 2;
    EXPECT_GT(labelPixels(img, 0, mid - 12, left, mid + 12), 10u) << "outer[0] label (u = 0, left)";
    EXPECT_GT(labelPixels(img, right, mid - 12, 400, mid + 12), 10u) << "outer[2] label (u = 1, right)";
    EXPECT_GT(labelPixels(img, cx - 20, bottom, cx + 20, bottom + 30), 10u) << "outer[1] label (v = 0, bottom)";
    EXPECT_GT(labelPixels(img, cx - 20, top - 30, cx + 20, top), 10u) << "outer[3] label (v = 1, top)";
    EXPECT_EQ(labelPixels(img, 0, 0, left - 2, top - 2), 0u);
}

TEST(TeachingCli, ComparisonPanesEachHaveTheirPartitioning) {
    const auto dir = freshTempDir("teach-compare");
    const auto png = dir / "c.png", stats = dir / "c.json";
    const RunResult r = runCommand(bin() +
                                   " render --domain tri --outer 4.9,4.5,4.1 --inner 4.4 --compare "
                                   "equal,fractional_odd,fractional_even,pow2 --size 600x500 -o " +
                                   png.string() + " --stats " + stats.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = readJson(stats);
    ASSERT_EQ(j["panes"].size(), 4u);
    const char* spacings[] = {"equal", "fractional_odd", "fractional_even", "pow2"};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(j["panes"][i]["spacing"], spacings[i]);
        EXPECT_EQ(j["panes"][i]["evaluations"], j["panes"][i]["expectedVertices"]) << spacings[i];
        EXPECT_EQ(j["panes"][i]["primitives"], j["panes"][i]["expectedPrimitives"]) << spacings[i];
    }
    // Integer and fractional_odd both give 5 segments per edge here; pow2 rounds 5 up to 8.
    EXPECT_EQ(j["panes"][0]["evaluations"], j["panes"][1]["evaluations"]);
    EXPECT_GT(j["panes"][3]["evaluations"].get<uint64_t>(), j["panes"][0]["evaluations"].get<uint64_t>());
    const Png img = loadPng(png);
    EXPECT_EQ(img.w, 600);
    EXPECT_EQ(img.h, 500);
}

TEST(TeachingCli, ModelComparisonPanesHaveTheirOwnPartitioningAndLevel) {
    const auto dir = freshTempDir("teach-model-compare");
    const auto png = dir / "m.png", stats = dir / "m.json";
    const RunResult r = runCommand(bin() + " render --tess 4.5 --compare equal,fractional_odd,fractional_even,pow2:5 --size 480x300 -o " +
                                   png.string() + " --stats " + stats.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = readJson(stats);
    ASSERT_EQ(j["panes"].size(), 4u);
    const char* spacings[] = {"equal", "fractional_odd", "fractional_even", "pow2"};
    for (size_t i = 0; i < 4; ++i) EXPECT_EQ(j["panes"][i]["spacing"], spacings[i]);
    EXPECT_EQ(j["panes"][3]["outer"][0].get<float>(), 5.0f);  // the pane's own level
    EXPECT_EQ(j["panes"][1]["outer"][0].get<float>(), 4.5f);
    // 32 teapot patches: equal and fractional_odd 4.5 both cut 5 segments, fractional_even 6,
    // pow2 5 -> 8 (2 n^2 triangles a patch).
    const uint64_t t[] = {32 * 2 * 25, 32 * 2 * 25, 32 * 2 * 36, 32 * 2 * 64};
    for (size_t i = 0; i < 4; ++i) EXPECT_EQ(j["panes"][i]["triangles"].get<uint64_t>(), t[i]) << spacings[i];
    EXPECT_EQ(j["panes"][2]["rect"], nlohmann::json::array({0, 150, 240, 150}));
    EXPECT_NE(r.output.find("pow2 · level 5 · 4,096 triangles"), std::string::npos) << r.output;
    const Png img = loadPng(png);
    ASSERT_EQ(img.w, 480);
    // The divider between the top panes is the grey line; the captions are drawn in each pane.
    EXPECT_EQ(img.at(240, 75)[0], 160);
    // A model sweep compares partitionings frame by frame.
    const RunResult s = runCommand(bin() + " sweep --compare equal,fractional_odd --from 2 --to 3 --frames 2 --size 240x120 -o " +
                                   (dir / "s%d.png").string());
    ASSERT_EQ(s.exitCode, 0) << s.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "s1.png"));
}

TEST(TeachingCli, IsolineDomainCountsLinesTimesSegments) {
    const auto dir = freshTempDir("teach-iso");
    const auto stats = dir / "i.json";
    const RunResult r = runCommand(bin() + " render --domain isoline --outer 3,5 --size 200x200 -o " + (dir / "i.png").string() +
                                   " --stats " + stats.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = readJson(stats);
    EXPECT_EQ(j["panes"][0]["primitives"].get<uint64_t>(), 15u);
    EXPECT_EQ(j["panes"][0]["evaluations"].get<uint64_t>(), 18u);
}

TEST(TeachingCli, SweepWritesNumberedFramesThatChange) {
    const auto dir = freshTempDir("teach-sweep");
    const RunResult r = runCommand(bin() + " sweep --domain quad --spacing fractional_odd --from 3 --to 5 --frames 3 --size 240x240 -o " +
                                   (dir / "f%02d.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Png a = loadPng(dir / "f00.png"), b = loadPng(dir / "f01.png"), c = loadPng(dir / "f02.png");
    ASSERT_EQ(a.w, 240);
    ASSERT_EQ(c.w, 240);
    EXPECT_FALSE(std::filesystem::exists(dir / "f03.png"));
    EXPECT_NE(a.rgba, b.rgba);
    EXPECT_NE(b.rgba, c.rgba);
    // The model: two frames into a new directory, each captioned.
    const RunResult m = runCommand(bin() + " sweep --from 1 --to 8 --frames 2 --size 200x120 -o " + (dir / "model").string());
    ASSERT_EQ(m.exitCode, 0) << m.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "model" / "frame_0000.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "model" / "frame_0001.png"));
}

TEST(TeachingCli, BadOptionsNameTheProblemAndWriteNothing) {
    const auto dir = freshTempDir("teach-bad");
    const auto png = dir / "x.png";
    struct Case {
        std::string args, says;
    };
    const Case cases[] = {
        {"render --domain hex", "--domain"},
        {"render --domain tri --outer 1,2", "--outer"},
        {"render --domain isoline --inner 2", "--inner"},
        {"render --domain quad --tess 65", "--tess"},
        {"render --preset quad-9", "--preset"},
        {"render --preset quad-4_4_4_4-4_4 --tess 3", "--preset"},
        {"render --domain quad --compare equal,odd", "--compare"},
        {"render --domain quad --compare equal,equal,equal,equal,equal", "--compare"},
        {"render --compare equal,pow2:65", "--compare"},
        {"render --compare equal:x", "--compare"},
        {"render --compare odd", "--compare"},
        {"sweep --compare equal,fractional_odd:4.5", "--compare"},
        {"sweep --from 0", "--from"},
        {"sweep --to 1e9", "--to"},
        {"sweep --frames 1", "--frames"},
        {"sweep --tess 4", "--tess"},
    };
    for (const Case& c : cases) {
        const bool sweep = c.args.rfind("sweep", 0) == 0;
        const std::string out = sweep ? (dir / "s%d.png").string() : png.string();
        const RunResult r = runCommand(bin() + " " + c.args + " -o " + out);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    }
    const RunResult p = runCommand(bin() + " sweep --frames 2 -o " + (dir / "x%d%d.png").string());
    EXPECT_EQ(p.exitCode, 2);
    EXPECT_NE(p.output.find("exactly one %d"), std::string::npos) << p.output;
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(TeachingCli, PresetsListsEveryFactorSetOfTheNotes) {
    const RunResult r = runCommand(bin() + " presets");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const TessPreset& p : tessPresets()) EXPECT_NE(r.output.find(p.name), std::string::npos) << p.name;
}

TEST(TeachingLabels, EdgesLabelledWithLevelAndRounding) {
    render::DomainViewOptions o;
    o.kind = DomainKind::Triangle;
    o.levels = {{4.5f, 4.0f, 1.0f, 0.0f}, {3.0f, 0.0f}};
    o.spacing = Spacing::FractionalOdd;
    o.rect = {0, 0, 300, 300};
    const auto labels = render::domainLabels(o, 10, 12, 16);
    std::vector<std::string> edges;
    std::string caption;
    for (const auto& l : labels) {
        if (l.role == render::DomainLabel::Role::Edge) edges.push_back(l.text);
        if (l.role == render::DomainLabel::Role::Caption) caption = l.text;
    }
    // fractional_odd: the next odd count, and how far the two short segments have grown, the notes'
    // (f - 3) / (5 - 3), on a line below on the side edges.
    ASSERT_EQ(edges.size(), 5u);
    EXPECT_EQ(edges[0], "4.5 \u2192 5");
    EXPECT_EQ(edges[1], "75 %");
    EXPECT_EQ(edges[2], "4 \u2192 5");
    EXPECT_EQ(edges[3], "50 %");
    EXPECT_EQ(edges[4], "1");
    EXPECT_NE(caption.find("inner 3  "), std::string::npos) << caption;  // odd already: no rounding
    // The inner levels' rounding (an inner 1 with a finer edge counts as 1 + epsilon) and slide; the
    // bottom edge's slide beside it.
    o.kind = DomainKind::Quad;
    o.levels = {{4, 4.4f, 4, 4}, {4.4f, 1.0f}};
    std::vector<std::string> quadEdges;
    for (const auto& l : render::domainLabels(o, 10, 12, 16)) {
        if (l.role == render::DomainLabel::Role::Edge) quadEdges.push_back(l.text);
        if (l.role == render::DomainLabel::Role::Caption && l.text.find("inner") != std::string::npos) caption = l.text;
    }
    EXPECT_NE(caption.find("inner 4.4 \u2192 5 (70 % slid), 1 \u2192 3"), std::string::npos) << caption;
    EXPECT_EQ(quadEdges[2], "4.4 \u2192 5 (70 %)");
    o.spacing = Spacing::FractionalEven;
    for (const auto& l : render::domainLabels(o, 10, 12, 16))
        if (l.role == render::DomainLabel::Role::Caption && l.text.find("inner") != std::string::npos) caption = l.text;
    EXPECT_NE(caption.find("inner 4.4 \u2192 6 (20 % slid), 1 \u2192 2"), std::string::npos) << caption;
    EXPECT_NE(caption.find("10 vertices, 12 triangles"), std::string::npos);
    EXPECT_EQ(render::formatLevel(4.25f), "4.25");
    EXPECT_EQ(render::formatLevel(16.0f), "16");
    // Two and four panes tile the area.
    const auto two = render::splitPanes(2, {0, 0, 200, 100});
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[1][0], 100.0f);
    const auto four = render::splitPanes(4, {0, 0, 200, 100});
    EXPECT_EQ(four[3][1], 50.0f);
}

// Panes that compare partitionings are titled by them (presentation mode and `--compare` figures);
// panes of one partitioning, and a single pane, keep the domain's name.
TEST(TeachingLabels, ComparedPanesAreTitledByPartitioning) {
    const auto titleOf = [](const render::DomainViewOptions& o) {
        for (const auto& l : render::domainLabels(o, 10, 12, 16))
            if (l.role == render::DomainLabel::Role::Title) return l.text;
        return std::string();
    };
    std::vector<render::DomainViewOptions> panes(2);
    panes[0].rect = {0, 0, 300, 300};
    panes[1].rect = {300, 0, 300, 300};
    panes[1].spacing = Spacing::FractionalOdd;
    render::titleByPartitioning(panes);
    EXPECT_EQ(titleOf(panes[0]), "equal");
    EXPECT_EQ(titleOf(panes[1]), "fractional_odd");
    panes[1].spacing = Spacing::Equal;
    panes[1].levels.outer[0] = 2.0f;  // levels compared, one partitioning
    render::titleByPartitioning(panes);
    EXPECT_EQ(titleOf(panes[0]), "quad domain");
    EXPECT_EQ(titleOf(panes[1]), "quad domain");
    const auto layout =
        render::layoutDomainFigure({{DomainKind::Triangle, {}, Spacing::Equal}, {DomainKind::Triangle, {}, Spacing::Pow2}}, 800, 400, 0.0f);
    EXPECT_EQ(layout.panes[1].title, "pow2");
}

// The notes' "a factor of 0 culls the patch": `--outer 0,4,4,4` draws nothing and says so, on the
// figure, on stdout and in the statistics (GPU counts 0); `--tess 0` is still refused (no inner 0).
TEST(TeachingCli, OuterLevelZeroCullsThePatchAndSaysSo) {
    const auto dir = freshTempDir("teach-cull");
    const auto png = dir / "c.png", stats = dir / "c.json";
    RunResult r = runCommand(bin() + " render --domain quad --outer 0,4,4,4 --inner 4,4 --size 800x500 -o " + png.string() + " --stats " +
                             stats.string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("culled (an outer level is 0"), std::string::npos) << r.output;
    const nlohmann::json j = readJson(stats);
    EXPECT_TRUE(j["panes"][0]["culled"].get<bool>());
    EXPECT_EQ(j["panes"][0]["primitives"].get<uint64_t>(), 0u);
    EXPECT_EQ(j["panes"][0]["expectedVertices"].get<uint64_t>(), 0u);
    const Png img = loadPng(png);
    ASSERT_EQ(img.w, 800);
    size_t filled = 0;  // the domain's fill colour (0.80, 0.87, 0.97)
    for (int y = 0; y < img.h; ++y)
        for (int x = 0; x < img.w; ++x) filled += std::abs(img.at(x, y)[0] - 204) < 4 && std::abs(img.at(x, y)[2] - 247) < 4;
    EXPECT_EQ(filled, 0u);
    // The caption says it: dark text along the bottom where counts would be.
    size_t text = 0;
    for (int y = img.h - 70; y < img.h; ++y)
        for (int x = 0; x < img.w; ++x) text += img.at(x, y)[0] < 80;
    EXPECT_GT(text, 200u);
    // The vector figure has no triangle; a triangle domain with an edge of 0 is culled too.
    r = runCommand(bin() + " render --domain tri --outer 4,0,4 --inner 4 -o " + (dir / "c.svg").string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("culled"), std::string::npos) << r.output;
    const std::string svg = readBytes(dir / "c.svg");
    ASSERT_FALSE(svg.empty());
    EXPECT_EQ(svg.find("fill:rgb(80."), std::string::npos);  // no triangle in the domain's fill colour
    r = runCommand(bin() + " render --domain quad --tess 0 -o " + (dir / "t.png").string() + " 2>&1");
    EXPECT_EQ(r.exitCode, 2) << r.output;
}

// `--eye X,Y,Z --target X,Y,Z` place the camera for near/far figures (render and sweep): the same
// view from twice as far covers about a quarter of the pixels; bad points are exit 2.
TEST(TeachingCli, EyeAndTargetPlaceTheCamera) {
    const auto dir = freshTempDir("teach-eye");
    const auto coverage = [&](const std::string& eye) {
        const auto png = dir / "e.png";
        const RunResult r = runCommand(bin() + " render " + (dataDir() / "teapot.bpt").string() + " --tess 4 --size 320x180 --eye " + eye +
                                       " --target 0,0,1.5 -o " + png.string() + " 2>&1");
        EXPECT_EQ(r.exitCode, 0) << r.output;
        const Png img = loadPng(png);
        size_t n = 0;  // pixels not of the background (its top-left pixel)
        for (int y = 0; y < img.h; ++y)
            for (int x = 0; x < img.w; ++x)
                n += std::abs(img.at(x, y)[0] - img.at(0, 0)[0]) + std::abs(img.at(x, y)[2] - img.at(0, 0)[2]) > 30;
        return double(n);
    };
    const double near = coverage("0,-12,6"), far = coverage("0,-24,12");
    EXPECT_GT(near, 2000.0);
    EXPECT_NEAR(far / near, 0.25, 0.08);
    const RunResult sweep =
        runCommand(bin() + " sweep --eye 0,-12,6 --from 2 --to 3 --fps 2 --seconds 1 --size 160x90 -o " + (dir / "s").string() + "/ 2>&1");
    EXPECT_EQ(sweep.exitCode, 0) << sweep.output;
    for (const char* bad : {"1,2", "1,2,x", "1,2,3,4", "0,0,1e10"}) {
        const RunResult r = runCommand(bin() + " render --eye " + bad + " -o " + (dir / "x.png").string() + " 2>&1");
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
        EXPECT_NE(r.output.find("--eye"), std::string::npos) << r.output;
    }
    const RunResult both = runCommand(bin() + " render --eye 0,-9,3 --view top -o " + (dir / "x.png").string() + " 2>&1");
    EXPECT_EQ(both.exitCode, 2) << both.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

// `--origin upper-left`: the D3D notes' and Vulkan's default picture, v = 0 on top, each edge tagged
// with its index (SV_TessFactor[i] = gl_TessLevelOuter[i]): the notes' {1,2,3,4 | 4,4} has its
// 2-segment edge [1] on top. The domain is the lower-left picture mirrored, pixel for pixel.
TEST(TeachingCli, UpperLeftOriginPutsEdgeOneOnTopTagged) {
    render::DomainViewOptions o;
    o.kind = DomainKind::Quad;
    o.levels = {{1, 2, 3, 4}, {4, 4}};
    o.rect = {0, 0, 400, 400};
    o.upperLeft = true;
    std::map<std::string, float> y;
    for (const auto& l : render::domainLabels(o, 19, 26, 16))
        if (l.role == render::DomainLabel::Role::Edge) y[l.text] = l.y;
    ASSERT_EQ(y.size(), 4u);
    EXPECT_LT(y.at("[1] 2"), y.at("[0] 1"));  // on top
    EXPECT_GT(y.at("[3] 4"), y.at("[2] 3"));  // at the bottom
    const render::DomainPlacement at = render::placeDomain(o);
    EXPECT_LT(at.toPixels(0.5f, 0.0f)[1], at.toPixels(0.5f, 1.0f)[1]);

    const auto dir = freshTempDir("teach-origin");
    const auto ul = dir / "ul.png", ll = dir / "ll.png";
    for (const auto& [file, origin] : {std::pair{ul, "upper-left"}, std::pair{ll, "lower-left"}}) {
        const RunResult r = runCommand(bin() + " render --preset quad-1_2_3_4-4_4 --origin " + std::string(origin) + " --size 600x600 -o " +
                                       file.string() + " 2>&1");
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const Png a = loadPng(ul), b = loadPng(ll);
    ASSERT_EQ(a.w, 600);
    ASSERT_EQ(b.w, 600);
    const render::DomainFigureLayout layout = render::layoutDomainFigure({{DomainKind::Quad, o.levels, Spacing::Equal}}, 600, 600, 0.0f);
    const render::DomainPlacement p = render::placeDomain(layout.panes[0]);
    const int x0 = int(std::ceil(p.originX)) + 2, x1 = int(p.originX + p.size) - 2;
    const int top = int(std::ceil(p.originY - p.size)) + 2, bottom = int(p.originY) - 2;
    double diff = 0.0;
    size_t n = 0;
    for (int yy = top; yy <= bottom; ++yy)
        for (int x = x0; x <= x1; ++x, ++n) {
            const int mirrored = int(std::lround(2.0 * p.originY - p.size)) - yy - 1;
            for (int c = 0; c < 3; ++c) diff += std::abs(int(a.at(x, yy)[c]) - int(b.at(x, mirrored)[c]));
        }
    EXPECT_LT(diff / double(3 * n), 6.0) << "mean difference per channel";
    const RunResult bad = runCommand(bin() + " render --preset quad-1_2_3_4-4_4 --origin top -o " + (dir / "x.png").string() + " 2>&1");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
}

// `render --shading level` draws the legend: the ramp's yellow (level 64) and violet (level 1) in
// the bottom-right corner, nowhere else (the teapot at level 6 is neither).
TEST(TeachingCli, LevelShadingHasALegend) {
    const auto dir = freshTempDir("teach-level");
    const auto png = dir / "l.png";
    const RunResult r = runCommand(bin() + " render --shading level --tess 6 --size 640x360 -o " + png.string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Png img = loadPng(png);
    ASSERT_EQ(img.w, 640);
    size_t yellowCorner = 0, yellowElsewhere = 0;
    for (int y = 0; y < img.h; ++y)
        for (int x = 0; x < img.w; ++x) {
            const uint8_t* p = img.at(x, y);
            const bool yellow = p[0] > 230 && p[1] > 210 && p[2] < 70;
            (x > img.w / 2 && y > img.h * 2 / 3 ? yellowCorner : yellowElsewhere) += yellow;
        }
    EXPECT_GT(yellowCorner, 20u);
    EXPECT_EQ(yellowElsewhere, 0u);
}

// `--theme light` for slides: a light background, the surface framed to fill the frame (not its
// control net's bounding sphere), a grey wire instead of a black one; unknown themes are exit 2.
TEST(TeachingCli, LightThemeFramesTheSurfaceTightly) {
    const auto dir = freshTempDir("teach-theme");
    const auto extent = [](const Png& img) {
        int x0 = img.w, x1 = -1, y0 = img.h, y1 = -1;
        for (int y = 0; y < img.h; ++y)
            for (int x = 0; x < img.w; ++x) {
                const uint8_t* p = img.at(x, y);
                if (std::abs(p[0] - img.at(0, 0)[0]) + std::abs(p[1] - img.at(0, 0)[1]) + std::abs(p[2] - img.at(0, 0)[2]) < 24) continue;
                x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
        return std::max(double(x1 - x0 + 1) / img.w, double(y1 - y0 + 1) / img.h);
    };
    for (const char* theme : {"light", "dark"}) {
        const RunResult r =
            runCommand(bin() + " render " + (dataDir() / "teacup.bpt").string() + " --view iso --tess 8 --overlay wire --theme " + theme +
                       " --size 480x270 -o " + (dir / (std::string(theme) + ".png")).string() + " 2>&1");
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const Png light = loadPng(dir / "light.png"), dark = loadPng(dir / "dark.png");
    ASSERT_EQ(light.w, 480);
    EXPECT_GT(light.at(0, 0)[0], 235);
    EXPECT_LT(dark.at(0, 0)[0], 60);
    EXPECT_GT(extent(light), 0.93);
    EXPECT_LT(extent(dark), extent(light) - 0.1);
    size_t black = 0;  // the dark theme's wire colour (0.08, 0.09, 0.12) is not on the light figure
    for (int y = 0; y < light.h; ++y)
        for (int x = 0; x < light.w; ++x) black += light.at(x, y)[0] < 40 && light.at(x, y)[2] < 50;
    EXPECT_EQ(black, 0u);
    const RunResult bad = runCommand(bin() + " render --theme blue -o " + (dir / "x.png").string() + " 2>&1");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
}

// The notes' distance formula culls at level 0: `--adaptive distance --distance 20,100` keeps far
// patches at level 1, `--cull-far` (and `--adaptive notes`, the notes' 64 saturate((100 - d) / 80))
// culls those centred beyond 100, so fewer triangles and patches reported culled.
TEST(TeachingCli, DistanceFormulaCullsBeyondFar) {
    const auto dir = freshTempDir("teach-cullfar");
    const auto run = [&](const std::string& opts) {
        const auto stats = dir / "s.json";
        const RunResult r =
            runCommand(bin() + " render " + (dataDir() / "terrain.patchwork").string() + " --eye 0,-110,45 --target 0,0,0 --size 320x180 " +
                       opts + " -o " + (dir / "t.png").string() + " --stats " + stats.string() + " 2>&1");
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readJson(stats);
    };
    const nlohmann::json keep = run("--adaptive distance --distance 20,100");
    const nlohmann::json cull = run("--adaptive distance --distance 20,100 --cull-far");
    const nlohmann::json notes = run("--adaptive notes");
    EXPECT_EQ(keep["patches_culled"].get<uint64_t>(), 0u);
    EXPECT_GT(cull["patches_culled"].get<uint64_t>(), 100u);
    EXPECT_LT(cull["patches_culled"].get<uint64_t>(), 1024u);
    EXPECT_LT(cull["triangles"].get<uint64_t>(), keep["triangles"].get<uint64_t>());
    EXPECT_EQ(notes["patches_culled"], cull["patches_culled"]);  // the same far distance
    const RunResult bad = runCommand(bin() + " render --adaptive distance --distance 50,10 -o " + (dir / "x.png").string() + " 2>&1");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
}

// `render --notes-patch 1 --math U,V`: the notes' patch with its evaluation at (U, V) drawn on the net
// (weights in the net's orange, the de Casteljau column in magenta, the point in white) and the
// point printed, equal to the CPU evaluation; bad parameters, patches and combinations are exit 2
// with nothing written.
TEST(TeachingCli, MathFigureDrawsTheEvaluationOnTheNet) {
    const auto dir = freshTempDir("teach-math");
    const auto png = dir / "m.png";
    const RunResult r = runCommand(bin() + " render --notes-patch 1 --math 0.35,0.6 --size 640x360 -o " + png.string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Document notes = notesBezierPatch();
    const Vec3 s = evaluateBezierBernsteinSum(gatherNet(notes, notes.patches[0].idx), 0.35, 0.6);
    char want[96];
    std::snprintf(want, sizeof want, "S = (%.3f, %.3f, %.3f)", s.x, s.y, s.z);
    EXPECT_NE(r.output.find(want), std::string::npos) << want << "\n" << r.output;
    const Png img = loadPng(png);
    size_t orange = 0, magenta = 0;
    for (int y = 0; y < img.h; ++y)
        for (int x = 0; x < img.w; ++x) {
            const auto p = img.at(x, y);
            orange += p[0] > 230 && p[1] > 120 && p[1] < 180 && p[2] < 80;
            magenta += p[0] > 220 && p[1] < 130 && p[2] > 190;
        }
    EXPECT_GT(orange, 300u);
    EXPECT_GT(magenta, 100u);
    for (const std::string& bad : std::vector<std::string>{"--math 1.5,0.5", "--math 0.5", "--math 0.5,0.5 --math-patch 1",
                                                           "--math 0.5,0.5 --compare equal,pow2", (dataDir() / "teapot.bpt").string()}) {
        const RunResult b = runCommand(bin() + " render --notes-patch 1 " + bad + " -o " + (dir / "x.png").string() + " 2>&1");
        EXPECT_EQ(b.exitCode, 2) << bad << ": " << b.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << bad;
    }
}

// `render --stage-bars`: each pane's per-stage counters, log-scaled bars in its bottom-right corner;
// the numbers are the GPU's pipeline statistics (the control shader runs once per patch, the
// evaluation shader once per tessellated vertex: 17 x 17 a patch at level 16; the vertex shader at
// most once per control point fed, fewer where the implementation reuses shared ones).
TEST(TeachingCli, StageBarsShowTheGpusCountersPerPane) {
    render::FrameStats s;
    EXPECT_TRUE(render::stageCounts(s).empty());  // no pipeline statistics: no bars
    s.pipelineStatsValid = true;
    s.vsInvocations = 9;
    s.tcsPatches = 0;
    s.tesInvocations = 99;
    s.clippingInvocations = 999;
    const auto c = render::stageCounts(s);
    ASSERT_EQ(c.size(), 4u);
    EXPECT_FLOAT_EQ(c[3].bar, 1.0f);
    EXPECT_NEAR(c[0].bar, std::log(10.0) / std::log(1000.0), 1e-6);
    EXPECT_EQ(c[1].bar, 0.0f);

    const auto dir = freshTempDir("teach-stages");
    const auto green = [](const Png& img) {
        size_t n = 0;  // the primitives bar, bottom-right quadrant
        for (int y = img.h / 2; y < img.h; ++y)
            for (int x = img.w / 2; x < img.w; ++x) {
                const auto p = img.at(x, y);
                n += p[0] > 100 && p[0] < 140 && p[1] > 200 && p[2] > 70 && p[2] < 110;
            }
        return n;
    };
    const std::string base = bin() + " render " + (dataDir() / "teapot.bpt").string() + " --tess 16 --size 640x360 ";
    const RunResult r =
        runCommand(base + "--stage-bars --stats " + (dir / "s.json").string() + " -o " + (dir / "s.png").string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const RunResult plain = runCommand(base + "-o " + (dir / "p.png").string() + " 2>&1");
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_GT(green(loadPng(dir / "s.png")), 100u);
    EXPECT_EQ(green(loadPng(dir / "p.png")), 0u);
    std::ifstream in(dir / "s.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j["pipeline_statistics"].get<bool>()) {
        EXPECT_EQ(j["tess_control_patches"].get<uint64_t>(), 32u);
        EXPECT_EQ(j["tess_eval_invocations"].get<uint64_t>(), 32u * 17u * 17u);
        EXPECT_GT(j["vertex_shader_invocations"].get<uint64_t>(), 0u);
        EXPECT_LE(j["vertex_shader_invocations"].get<uint64_t>(), 32u * 16u);
    }
}

// `render --near-far F`: the distance-adaptive slide in one command: the view beside the same view F
// times farther, each pane captioned and counted; the far pane has fewer triangles and the ratio
// is printed and in the stats. A factor of 1 or less, or --compare beside it, is exit 2.
TEST(TeachingCli, NearFarFigureComparesOneViewAtTwoDistances) {
    const auto dir = freshTempDir("teach-nearfar");
    const std::string base =
        bin() + " render " + (dataDir() / "teapot.bpt").string() + " --adaptive distance --distance 10,60 --size 320x180 ";
    const RunResult r =
        runCommand(base + "--near-far 4 --stats " + (dir / "s.json").string() + " -o " + (dir / "nf.png").string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("near \u00b7"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("far \u00d74 \u00b7"), std::string::npos) << r.output;
    std::ifstream in(dir / "s.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_EQ(j["panes"].size(), 2u);
    const double nearTris = j["panes"][0]["triangles"].get<double>(), farTris = j["panes"][1]["triangles"].get<double>();
    EXPECT_GT(nearTris, 4.0 * farTris);
    EXPECT_NEAR(j["nearOverFar"].get<double>(), nearTris / farTris, 1e-9);
    for (const std::string bad : {"--near-far 1", "--near-far x", "--near-far 4 --compare equal,pow2"}) {
        const RunResult b = runCommand(base + bad + " -o " + (dir / "x.png").string() + " 2>&1");
        EXPECT_EQ(b.exitCode, 2) << bad << ": " << b.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << bad;
    }
}

}  // namespace pw::test

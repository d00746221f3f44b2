// Vector domain figures: the primitives read back from the tessellator (DomainView::capture) follow
// the rules for every domain and partitioning; `render --domain ... -o f.svg|f.pdf` writes one path
// per triangle, the SVG is valid XML (xmllint) and, rasterised by rsvg-convert (the PDF by poppler's
// pdftoppm), matches the PNG figure; a model cannot be written as SVG. Validation layer on.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "render/domain/domain_view.hpp"
#include "render/figures/figure_vector.hpp"
#include "render_support.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

std::string bin() { return "PATCHWORK_VALIDATION=1 " + patchworkBinary().string(); }

const DomainLevels kNotes{{4.9f, 4.5f, 4.1f, 4.4f}, {4.4f, 4.4f}};  // the lecture's {4.9,4.5,4.1 | 4.4} (quad: a fourth edge)
const Spacing kSpacings[] = {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2};

DomainLevels levelsFor(DomainKind kind, const DomainLevels& l) {
    DomainLevels out = l;
    if (kind == DomainKind::Triangle) out.outer[3] = 0.0f, out.inner[1] = 0.0f;
    if (kind == DomainKind::Isoline) out.outer = {l.outer[0], l.outer[1], 0.0f, 0.0f}, out.inner = {0.0f, 0.0f};
    return out;
}

// The paths drawn on the page (not the glyph outlines in <defs>), split by shape.
struct SvgPaths {
    size_t triangles = 0, segments = 0, other = 0;
};
SvgPaths countPaths(const std::string& svg) {
    SvgPaths c;
    const size_t body = svg.find("</defs>");
    static const std::regex path(R"re(<path[^>]* d="([^"]*)")re");
    static const std::regex triangle(R"(^M [-0-9.e]+ [-0-9.e]+ L [-0-9.e]+ [-0-9.e]+ L [-0-9.e]+ [-0-9.e]+ Z( M [-0-9.e]+ [-0-9.e]+)? ?$)");
    static const std::regex segment(R"(^M [-0-9.e]+ [-0-9.e]+ L [-0-9.e]+ [-0-9.e]+ ?$)");
    const std::string page = svg.substr(body == std::string::npos ? 0 : body);
    for (std::sregex_iterator it(page.begin(), page.end(), path), end; it != end; ++it) {
        const std::string d = (*it)[1];
        if (std::regex_match(d, triangle))
            ++c.triangles;
        else if (std::regex_match(d, segment))
            ++c.segments;
        else
            ++c.other;
    }
    return c;
}

// The PNG figure and a rasterised vector figure look the same: mean difference under 3 of 255 per
// channel, under 2 % of the pixels off by more than a quarter (antialiasing of lines and glyphs).
void expectSameFigure(const Png& a, const Png& b) {
    ASSERT_GT(a.w, 0);
    ASSERT_EQ(b.w, a.w);
    ASSERT_EQ(b.h, a.h);
    double sum = 0.0;
    size_t far = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
        int worst = 0;
        for (size_t k = 0; k < 3; ++k) {
            const int d = std::abs(int(a.rgba[i + k]) - int(b.rgba[i + k]));
            sum += d;
            worst = std::max(worst, d);
        }
        far += worst > 64;
    }
    const double pixels = double(a.w) * double(a.h);
    EXPECT_LT(sum / (3.0 * pixels), 3.0) << "mean difference per channel (of 255)";
    EXPECT_LT(double(far) / pixels, 0.02) << "pixels that differ by more than a quarter";
}

class DomainCapture : public RenderTest {};

}  // namespace

// Every primitive the tessellator made is read back: the count equals the rules' (and the GPU's
// statistics), the distinct points are the rules' vertex count, and all lie in the domain.
TEST_F(DomainCapture, PatternFollowsTheRulesForEveryDomainAndPartitioning) {
    render::Device& dev = sharedDevice();
    if (!dev.caps().transformFeedback) GTEST_SKIP() << "no VK_EXT_transform_feedback";
    render::DomainView view(dev, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT);
    const std::vector<DomainLevels> sets = {kNotes,
                                            {{1, 2, 3, 4}, {4, 4}},
                                            {{7.3f, 2.2f, 5.5f, 9.9f}, {3.1f, 6.6f}},
                                            {{1, 1, 1, 1}, {1, 1}},
                                            {{64, 64, 64, 64}, {64, 64}},
                                            {{2.5f, 13.f, 1.f, 6.f}, {1.f, 17.5f}}};
    for (DomainKind kind : {DomainKind::Quad, DomainKind::Triangle, DomainKind::Isoline})
        for (Spacing s : kSpacings)
            for (const DomainLevels& raw : sets) {
                const DomainLevels l = levelsFor(kind, raw);
                const TessPattern p = view.capture({kind, l, s});
                const DomainCounts want = expectedDomainCounts(kind, l, s, float(dev.caps().maxTessLevel));
                SCOPED_TRACE(std::string(domainName(kind)) + " " + std::string(spacingName(s)) + " outer " + std::to_string(l.outer[0]) +
                             "," + std::to_string(l.outer[1]));
                EXPECT_EQ(p.primitives(), want.primitives);
                // A triangle with inner level 1 and a finer edge is tessellated as inner 1 + epsilon
                // (Vulkan spec): under fractional_odd that is 3 segments, two of them of length ~0,
                // so tessellator vertices land on one point. Everywhere else each is its own point.
                const bool collapsedRing = kind == DomainKind::Triangle && s == Spacing::FractionalOdd && l.inner[0] <= 1.0f &&
                                           std::max({l.outer[0], l.outer[1], l.outer[2]}) > 1.0f;
                if (collapsedRing) {
                    EXPECT_LT(p.distinctPoints().size(), want.vertices);
                } else {
                    EXPECT_EQ(p.distinctPoints().size(), want.vertices);
                }
                for (const auto& q : p.uv) {  // tessellation coordinates: in [0,1]^2, u + v <= 1 on triangles
                    ASSERT_GE(q[0], -1e-6f);
                    ASSERT_LE(q[0], 1.0f + 1e-6f);
                    ASSERT_GE(q[1], -1e-6f);
                    ASSERT_LE(q[1], 1.0f + 1e-6f);
                    if (kind == DomainKind::Triangle) {
                        ASSERT_LE(q[0] + q[1], 1.0f + 1e-6f);
                    }
                }
            }
    // A culled patch (an outer level 0) makes nothing.
    EXPECT_EQ(view.capture({DomainKind::Quad, {{0, 4, 4, 4}, {4, 4}}, Spacing::Equal}).primitives(), 0u);
}

TEST(VectorFigureCli, SvgHasOnePathPerTriangleAndMatchesThePng) {
    const auto dir = freshTempDir("vector-svg");
    const auto svg = dir / "f.svg", png = dir / "f.png", raster = dir / "r.png";
    const std::string args =
        " render --domain quad --outer 4.9,4.5,4.1,4.4 --inner 4.4,4.4 --compare equal,fractional_odd,fractional_even,pow2 --size 1024x640 "
        "-o ";
    RunResult r = runCommand(bin() + args + svg.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runCommand(bin() + args + png.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(runCommand("xmllint --noout " + svg.string()).exitCode, 0) << "the SVG is not well-formed XML";

    size_t want = 0;
    for (Spacing s : kSpacings) want += expectedDomainCounts(DomainKind::Quad, kNotes, s).primitives;
    const SvgPaths paths = countPaths(readBytes(svg));
    EXPECT_EQ(paths.triangles, want);
    EXPECT_EQ(paths.segments, 0u);

    // rsvg-convert (librsvg, not cairo's reader) draws it as the PNG figure shows it.
    r = runCommand("rsvg-convert " + svg.string() + " -o " + raster.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    expectSameFigure(loadPng(png), loadPng(raster));
}

TEST(VectorFigureCli, IsolinesAreOpenPathsAndPdfIsOnePage) {
    const auto dir = freshTempDir("vector-pdf");
    const auto svg = dir / "i.svg", pdf = dir / "t.pdf";
    RunResult r = runCommand(bin() + " render --domain isoline --outer 3,5.5 --spacing fractional_odd --size 800x600 -o " + svg.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const SvgPaths paths = countPaths(readBytes(svg));
    EXPECT_EQ(paths.segments, expectedDomainCounts(DomainKind::Isoline, {{3, 5.5f, 0, 0}, {0, 0}}, Spacing::FractionalOdd).primitives);
    EXPECT_EQ(paths.triangles, 0u);

    r = runCommand(bin() + " render --preset tri-4.9_4.5_4.1-4.4 --size 1024x640 -o " + pdf.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // Poppler (not cairo) draws the PDF at one pixel a point as the PNG figure shows it.
    const auto png = dir / "t.png", raster = dir / "p";
    r = runCommand(bin() + " render --preset tri-4.9_4.5_4.1-4.4 --size 1024x640 -o " + png.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runCommand("pdftoppm -png -r 72 -singlefile " + pdf.string() + " " + raster.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    expectSameFigure(loadPng(png), loadPng(dir / "p.png"));
    const std::string bytes = readBytes(pdf);
    EXPECT_EQ(bytes.rfind("%PDF-", 0), 0u);
    EXPECT_NE(bytes.find("%%EOF", bytes.size() - 16), std::string::npos);
    EXPECT_NE(bytes.find("/MediaBox [ 0 0 1024 640 ]"), std::string::npos);
    size_t pages = 0;
    for (size_t at = bytes.find("/Type /Page"); at != std::string::npos; at = bytes.find("/Type /Page", at + 1))
        pages += bytes.compare(at, 12, "/Type /Pages") != 0;
    EXPECT_EQ(pages, 1u);
}

TEST(VectorFigureCli, AModelIsNotWrittenAsSvgAndNothingIsLost) {
    const auto dir = freshTempDir("vector-model");
    const auto svg = dir / "m.svg";
    std::ofstream(svg) << "keep";
    const RunResult r = runCommand(bin() + " render --size 320x200 -o " + svg.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("-o"), std::string::npos) << r.output;
    EXPECT_EQ(readBytes(svg), "keep");
}

}  // namespace pw::test

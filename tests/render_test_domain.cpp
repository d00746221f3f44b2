// The domain view on the GPU: for every partitioning and the quad, triangle and isoline domains, the
// vertex and primitive counts the fixed tessellator produces (pipeline statistics) follow the
// rounding rules of core/tess_domain over a sweep of levels 1-64 with fractions, and over random
// per-edge level sets; the pictures show what they should. Validation layer on throughout.
#include <cstdio>
#include <random>
#include <sstream>

#include "render/domain/domain_view.hpp"
#include "render_support.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

class DomainTest : public RenderTest {};

const Spacing kSpacings[] = {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2};
const DomainKind kDomains[] = {DomainKind::Quad, DomainKind::Triangle, DomainKind::Isoline};

std::string describe(const DomainLevels& l) {
    std::ostringstream s;
    s << "{" << l.outer[0] << "," << l.outer[1] << "," << l.outer[2] << "," << l.outer[3] << " | " << l.inner[0] << "," << l.inner[1]
      << "}";
    return s.str();
}

// Compares the GPU's counts for `sets` with the rules; returns the number of sets checked.
size_t checkAgainstRules(DomainKind kind, Spacing spacing, const std::vector<DomainLevels>& sets) {
    const std::vector<render::DomainStats> got = render::countDomain(sharedDevice(), kind, spacing, sets);
    EXPECT_EQ(got.size(), sets.size());
    int reported = 0;
    for (size_t i = 0; i < sets.size() && i < got.size(); ++i) {
        EXPECT_TRUE(got[i].valid);
        const DomainCounts want = expectedDomainCounts(kind, sets[i], spacing, float(sharedDevice().caps().maxTessLevel));
        if ((got[i].vertices != want.vertices || got[i].primitives != want.primitives) && reported++ < 5)
            ADD_FAILURE() << domainName(kind) << " " << spacingName(spacing) << " " << describe(sets[i]) << ": GPU " << got[i].vertices
                          << " vertices / " << got[i].primitives << " primitives, rules " << want.vertices << " / " << want.primitives;
    }
    return sets.size();
}

}  // namespace

TEST_F(DomainTest, UniformSweepFollowsTheRoundingRules) {
    ASSERT_TRUE(sharedDevice().caps().pipelineStatistics);
    // Levels 1 to 64 in steps of 1/8: every integer and the fractions between them (every half
    // level in the sanitizer build, where lavapipe's time is the same and the point is memory).
    std::vector<DomainLevels> sets;
    for (int k = 8; k <= 64 * 8; k += kSanitized ? 4 : 1) {
        const float l = float(k) / 8.0f;
        sets.push_back({{l, l, l, l}, {l, l}});
    }
    size_t checked = 0;
    for (DomainKind d : kDomains)
        for (Spacing s : kSpacings) checked += checkAgainstRules(d, s, sets);
    std::printf("domain sweep: %zu uniform level sets checked (3 domains x 4 partitionings x %zu levels)\n", checked, sets.size());
}

TEST_F(DomainTest, MixedLevelsFollowTheRoundingRules) {
    // Random per-edge levels (fractions included), with many ones and twos where the special rules
    // (all ones; an inner level of one counted as 1 + ε) apply.
    std::mt19937 rng(20261122);
    std::uniform_real_distribution<float> any(1.0f, 64.0f);
    std::uniform_int_distribution<int> small(1, 4), pick(0, 3);
    auto level = [&] {
        switch (pick(rng)) {
            case 0:
                return float(small(rng));
            case 1:
                return 1.0f;
            case 2:
                return std::round(any(rng) * 4.0f) / 4.0f;
            default:
                return any(rng);
        }
    };
    std::vector<DomainLevels> sets;
    for (int i = 0; i < (kSanitized ? 150 : 600); ++i) sets.push_back({{level(), level(), level(), level()}, {level(), level()}});
    // The notes' factor sets.
    sets.push_back({{1, 2, 3, 4}, {4, 4}});
    sets.push_back({{2, 2, 4, 4}, {2, 4}});
    sets.push_back({{6, 12, 3, 0}, {1, 0}});
    sets.push_back({{4.9f, 4.5f, 4.1f, 0}, {4.4f, 0}});
    sets.push_back({{1, 1, 1, 1}, {1, 1}});
    for (DomainKind d : kDomains)
        for (Spacing s : kSpacings) checkAgainstRules(d, s, sets);
}

TEST_F(DomainTest, PicturesShowTheTessellation) {
    render::OffscreenTarget target(sharedDevice(), 320, 320, true);
    render::DomainView view(sharedDevice(), target.colorFormat(), target.depthFormat(), target.samples());
    auto shot = [&](DomainKind kind, DomainLevels levels, Spacing spacing, render::DomainStats* stats = nullptr) {
        render::DomainViewOptions o;
        o.kind = kind;
        o.levels = levels;
        o.spacing = spacing;
        o.rect = {0, 0, 320, 320};
        o.margin = 20;
        const render::DomainStats s = view.draw(target, o, true);
        if (stats) *stats = s;
        Image img{320, 320, target.pixels()};
        return img;
    };
    const auto count = [](const Image& img, const std::array<float, 4>& c, int tol) {
        size_t n = 0;
        for (uint32_t y = 0; y < img.h; ++y)
            for (uint32_t x = 0; x < img.w; ++x) n += sameColor(img.at(int(x), int(y)), {c[0], c[1], c[2]}, tol);
        return n;
    };
    const render::DomainViewOptions colours;
    // Lines are one pixel wide and multisampled: count pixels clearly darker than the background.
    const auto dark = [](const Image& img) {
        size_t n = 0;
        for (size_t i = 0; i < img.rgba.size(); i += 4) n += img.rgba[i] + img.rgba[i + 1] + img.rgba[i + 2] < 3 * 160;
        return n;
    };
    render::DomainStats st;
    const Image q = shot(DomainKind::Quad, {{4, 4, 4, 4}, {4, 4}}, Spacing::Equal, &st);
    EXPECT_EQ(st.vertices, 25u);
    EXPECT_EQ(st.primitives, 32u);
    // The square is filled (fill colour inside, background outside the margin), with lines drawn.
    EXPECT_TRUE(sameColor(q.at(5, 5), {colours.background[0], colours.background[1], colours.background[2]}, 3));
    EXPECT_GT(count(q, colours.fillColor, 6), 30000u);
    EXPECT_GT(dark(q), 1000u);
    // fractional_odd 4.5 slides two new vertices in: a different picture from 5, same counts.
    render::DomainStats s45, s5;
    const Image odd45 = shot(DomainKind::Quad, {{4.5f, 4.5f, 4.5f, 4.5f}, {4.5f, 4.5f}}, Spacing::FractionalOdd, &s45);
    const Image odd5 = shot(DomainKind::Quad, {{5, 5, 5, 5}, {5, 5}}, Spacing::FractionalOdd, &s5);
    EXPECT_EQ(s45.vertices, s5.vertices);
    EXPECT_GT(countDifferent(odd45, odd5, 30), 500u);
    // pow2 at 5 is equal at 8, pixel for pixel.
    const Image p2 = shot(DomainKind::Quad, {{5, 5, 5, 5}, {5, 5}}, Spacing::Pow2);
    const Image eq8 = shot(DomainKind::Quad, {{8, 8, 8, 8}, {8, 8}}, Spacing::Equal);
    EXPECT_EQ(countDifferent(p2, eq8, 0), 0u);
    // The triangle fills less of its square than the quad; the isolines leave most background.
    const Image t = shot(DomainKind::Triangle, {{4, 4, 4, 0}, {4, 0}}, Spacing::Equal);
    const size_t triFill = count(t, colours.fillColor, 6);
    EXPECT_GT(triFill, 10000u);
    EXPECT_LT(triFill, count(q, colours.fillColor, 6));
    render::DomainStats is;
    const Image iso = shot(DomainKind::Isoline, {{4, 8, 0, 0}, {0, 0}}, Spacing::Equal, &is);
    EXPECT_EQ(is.primitives, 32u);
    EXPECT_GT(dark(iso), 4u * 250u);  // four lines across ~280 pixels
    EXPECT_EQ(count(iso, colours.fillColor, 6), 0u);
}

}  // namespace pw::test

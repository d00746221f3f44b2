// The CPU model of the tessellator's rounding and counting rules (core/tess_domain), checked against
// counts worked out by hand from the Vulkan specification's description of each domain. The GPU's
// own counts are held against the same rules in render_test_domain.cpp.
#include <gtest/gtest.h>

#include "core/tess/tess_domain.hpp"

using namespace pw;

namespace {
DomainLevels quad(float o0, float o1, float o2, float o3, float i0, float i1) { return {{o0, o1, o2, o3}, {i0, i1}}; }
DomainLevels tri(float o0, float o1, float o2, float i0) { return {{o0, o1, o2, 0}, {i0, 0}}; }
}  // namespace

TEST(TessDomain, RoundingFollowsEachPartitioning) {
    // equal: ceil in [1, 64]
    EXPECT_EQ(segmentCount(0.3f, Spacing::Equal), 1);
    EXPECT_EQ(segmentCount(4.0f, Spacing::Equal), 4);
    EXPECT_EQ(segmentCount(4.1f, Spacing::Equal), 5);
    EXPECT_EQ(segmentCount(99.0f, Spacing::Equal), 64);
    // fractional_odd: next odd in [1, 63]
    EXPECT_EQ(segmentCount(1.0f, Spacing::FractionalOdd), 1);
    EXPECT_EQ(segmentCount(1.5f, Spacing::FractionalOdd), 3);
    EXPECT_EQ(segmentCount(4.5f, Spacing::FractionalOdd), 5);
    EXPECT_EQ(segmentCount(5.0f, Spacing::FractionalOdd), 5);
    EXPECT_EQ(segmentCount(64.0f, Spacing::FractionalOdd), 63);
    // fractional_even: next even in [2, 64]
    EXPECT_EQ(segmentCount(1.0f, Spacing::FractionalEven), 2);
    EXPECT_EQ(segmentCount(2.0f, Spacing::FractionalEven), 2);
    EXPECT_EQ(segmentCount(2.01f, Spacing::FractionalEven), 4);
    EXPECT_EQ(segmentCount(63.5f, Spacing::FractionalEven), 64);
    // culling
    EXPECT_EQ(segmentCount(0.0f, Spacing::Equal), 0);
    EXPECT_EQ(segmentCount(-1.0f, Spacing::FractionalOdd), 0);
    EXPECT_EQ(segmentCount(std::nanf(""), Spacing::Equal), 0);
    // pow2 is emulated in the control shader: next power of two of the integer level
    EXPECT_EQ(controlShaderLevel(5.0f, Spacing::Pow2), 8.0f);
    EXPECT_EQ(controlShaderLevel(4.0f, Spacing::Pow2), 4.0f);
    EXPECT_EQ(controlShaderLevel(4.2f, Spacing::Pow2), 8.0f);
    EXPECT_EQ(controlShaderLevel(1.0f, Spacing::Pow2), 1.0f);
    EXPECT_EQ(controlShaderLevel(33.0f, Spacing::Pow2), 64.0f);
    EXPECT_EQ(controlShaderLevel(4.5f, Spacing::FractionalOdd), 4.5f);
}

TEST(TessDomain, QuadCounts) {
    // Uniform n: an n x n grid, (n+1)^2 vertices and 2 n^2 triangles.
    for (int n : {2, 3, 8, 64}) {
        auto c = expectedDomainCounts(DomainKind::Quad, quad(n, n, n, n, n, n), Spacing::Equal);
        EXPECT_EQ(c.vertices, uint64_t((n + 1) * (n + 1))) << n;
        EXPECT_EQ(c.primitives, uint64_t(2 * n * n)) << n;
    }
    // All ones: one quad, two triangles.
    auto one = expectedDomainCounts(DomainKind::Quad, quad(1, 1, 1, 1, 1, 1), Spacing::Equal);
    EXPECT_EQ(one.vertices, 4u);
    EXPECT_EQ(one.primitives, 2u);
    // Inner 1 with an outer above 1 counts as 1 + ε: two segments (equal).
    auto eps = expectedDomainCounts(DomainKind::Quad, quad(1, 1, 1, 2, 1, 1), Spacing::Equal);
    EXPECT_EQ(eps.innerSegments[0], 2);
    EXPECT_EQ(eps.vertices, 5u + 1u);  // 5 boundary points + the centre
    // ... and three under fractional_odd.
    auto epsOdd = expectedDomainCounts(DomainKind::Quad, quad(1, 1, 1, 2, 1, 1), Spacing::FractionalOdd);
    EXPECT_EQ(epsOdd.innerSegments[0], 3);
    EXPECT_EQ(epsOdd.outerSegments[3], 3);
    // The notes' {1,2,3,4 | 4,4}: 10 boundary points, 3x3 interior; 10 + 18 - 2 triangles.
    auto mixed = expectedDomainCounts(DomainKind::Quad, quad(1, 2, 3, 4, 4, 4), Spacing::Equal);
    EXPECT_EQ(mixed.vertices, 19u);
    EXPECT_EQ(mixed.primitives, 26u);
    // fractional_odd 4.5 everywhere behaves like 5 segments; fractional_even 4.5 like 6.
    auto odd = expectedDomainCounts(DomainKind::Quad, quad(4.5, 4.5, 4.5, 4.5, 4.5, 4.5), Spacing::FractionalOdd);
    EXPECT_EQ(odd.vertices, 36u);
    auto even = expectedDomainCounts(DomainKind::Quad, quad(4.5, 4.5, 4.5, 4.5, 4.5, 4.5), Spacing::FractionalEven);
    EXPECT_EQ(even.vertices, 49u);
    // pow2 at 5 is equal at 8.
    auto p2 = expectedDomainCounts(DomainKind::Quad, quad(5, 5, 5, 5, 5, 5), Spacing::Pow2);
    EXPECT_EQ(p2.primitives, 128u);
    EXPECT_TRUE(expectedDomainCounts(DomainKind::Quad, quad(4, 0, 4, 4, 4, 4), Spacing::Equal).culled);
}

TEST(TessDomain, TriangleCounts) {
    auto one = expectedDomainCounts(DomainKind::Triangle, tri(1, 1, 1, 1), Spacing::Equal);
    EXPECT_EQ(one.vertices, 3u);
    EXPECT_EQ(one.primitives, 1u);
    // Level 2: 6 boundary points and the centre, 6 triangles.
    auto two = expectedDomainCounts(DomainKind::Triangle, tri(2, 2, 2, 2), Spacing::Equal);
    EXPECT_EQ(two.vertices, 7u);
    EXPECT_EQ(two.primitives, 6u);
    // Level 3: 9 boundary points, an inner triangle of 3; 9 + 3 triangles in the ring, 1 inside.
    auto three = expectedDomainCounts(DomainKind::Triangle, tri(3, 3, 3, 3), Spacing::Equal);
    EXPECT_EQ(three.vertices, 12u);
    EXPECT_EQ(three.primitives, 13u);
    // Level 4: 12 boundary points, a ring of 6, the centre: 19 vertices; 18 + 6 triangles.
    auto four = expectedDomainCounts(DomainKind::Triangle, tri(4, 4, 4, 4), Spacing::Equal);
    EXPECT_EQ(four.vertices, 19u);
    EXPECT_EQ(four.primitives, 24u);
    // {6,12,3 | 1}: inner 1 counts as 1 + ε, two segments, so one interior point.
    auto mixed = expectedDomainCounts(DomainKind::Triangle, tri(6, 12, 3, 1), Spacing::Equal);
    EXPECT_EQ(mixed.innerSegments[0], 2);
    EXPECT_EQ(mixed.vertices, 22u);
    EXPECT_EQ(mixed.primitives, 21u);
}

TEST(TessDomain, IsolineCounts) {
    // 4 lines of 8 segments: 36 vertices, 32 segments.
    auto c = expectedDomainCounts(DomainKind::Isoline, {{4, 8, 0, 0}, {0, 0}}, Spacing::Equal);
    EXPECT_EQ(c.vertices, 36u);
    EXPECT_EQ(c.primitives, 32u);
    // The line count ignores the partitioning (integer); the segments follow it.
    auto odd = expectedDomainCounts(DomainKind::Isoline, {{2.5f, 2.5f, 0, 0}, {0, 0}}, Spacing::FractionalOdd);
    EXPECT_EQ(odd.outerSegments[0], 3);
    EXPECT_EQ(odd.outerSegments[1], 3);
    auto even = expectedDomainCounts(DomainKind::Isoline, {{2.5f, 2.5f, 0, 0}, {0, 0}}, Spacing::FractionalEven);
    EXPECT_EQ(even.outerSegments[0], 3);
    EXPECT_EQ(even.outerSegments[1], 4);
}

TEST(TessDomain, NamesRoundTrip) {
    for (DomainKind k : {DomainKind::Quad, DomainKind::Triangle, DomainKind::Isoline}) EXPECT_EQ(parseDomain(domainName(k)), k);
    EXPECT_FALSE(parseDomain("hexagon"));
}

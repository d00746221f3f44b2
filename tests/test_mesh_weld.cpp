// weldTriangleSoup (core/mesh/mesh_weld.hpp): the captured triangle soup becomes the export mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/mesh/mesh_weld.hpp"

namespace pw::test {
namespace {

SoupVertex v(float x, float y, float z, uint32_t item, float nx = 0, float ny = 0, float nz = 1) {
    return SoupVertex{{x, y, z}, {nx, ny, nz}, {x, y}, item};
}

TEST(MeshWeld, SharedEdgesWeldWithinTheToleranceAndOnlyThere) {
    // Two windows sharing the edge x = 1; the second's copy of it is off by float rounding.
    const float e = 1e-7f;
    const std::vector<SoupVertex> soup = {v(0, 0, 0, 0), v(1, 0, 0, 0), v(1, 1, 0, 0), v(1 + e, 0, 0, 1), v(2, 0, 0, 1), v(1, 1 + e, 0, 1)};
    const TriangleMesh m = weldTriangleSoup(soup, 2, 0, 1e-6);
    EXPECT_EQ(m.positions.size(), 4u);
    ASSERT_EQ(m.indices.size(), 6u);
    EXPECT_EQ(m.indices[1], m.indices[3]);
    EXPECT_EQ(m.indices[2], m.indices[5]);
    ASSERT_EQ(m.perWindow.size(), 2u);
    EXPECT_EQ(m.perWindow[1].firstIndex, 3u);
    // With no tolerance only bit-identical positions weld.
    EXPECT_EQ(weldTriangleSoup(soup, 2, 0, 0.0).positions.size(), 6u);
}

// Within one window, vertices at other (u, v) weld only on a collapsed edge, and that holds for
// every window in a cluster, not only the one that made it: across a seam, window 1's second
// vertex near window 1's first may not merge because the cluster was started by window 0.
TEST(MeshWeld, AWindowsOwnVerticesStayApartInAClusterAnotherWindowStarted) {
    const float e = 1.2e-7f;
    auto at = [](float x, float y, float u, float w, uint32_t item) { return SoupVertex{{x, y, 0}, {0, 0, 1}, {u, w}, item}; };
    const std::vector<SoupVertex> soup = {
        at(0, 0, 0, 0, 0), at(1, 0, 1, 0, 0), at(1, 1, 1, 1, 0), at(1 + e, 0, 0, 0, 1), at(1 + 2 * e, 0, 0, 1e-3f, 1), at(2, 1, 1, 1, 1)};
    const std::vector<uint8_t> noneCollapsed(2, 0);
    WeldStats st;
    const TriangleMesh m = weldTriangleSoup(soup, 2, 0, 1e-6, &st, &noneCollapsed);
    EXPECT_EQ(m.positions.size(), 5u);  // window 1's first vertex on window 0's; its second its own
    EXPECT_EQ(st.degenerateTriangles, 0u);
    // Marked collapsed (u = 0 of window 1), they do weld, and window 1's triangle collapses with them.
    const std::vector<uint8_t> collapsed{0, 1};
    EXPECT_EQ(weldTriangleSoup(soup, 2, 0, 1e-6, &st, &collapsed).positions.size(), 3u);
    EXPECT_EQ(st.degenerateTriangles, 1u);
}

TEST(MeshWeld, CreasesKeepTheirNormalsAndSmoothSeamsAverageThem) {
    // A crease (normals 90 degrees apart) along x = 1 ...
    std::vector<SoupVertex> soup = {v(0, 0, 0, 0),          v(1, 0, 0, 0),           v(1, 1, 0, 0),
                                    v(1, 0, 0, 1, 1, 0, 0), v(1, 0, -1, 1, 1, 0, 0), v(1, 1, 0, 1, 1, 0, 0)};
    EXPECT_EQ(weldTriangleSoup(soup, 2, 0, 1e-6).positions.size(), 6u);
    // ... and a seam whose sides' normals differ by 0.5 degrees: one vertex, the normals averaged.
    const float c = std::cos(0.0087266f), d = std::sin(0.0087266f);
    soup = {v(0, 0, 0, 0, 0, 0, 1), v(1, 0, 0, 0, 0, 0, 1), v(1, 1, 0, 0, 0, 0, 1),
            v(1, 0, 0, 1, d, 0, c), v(2, 0, 0, 1, d, 0, c), v(1, 1, 0, 1, d, 0, c)};
    const TriangleMesh m = weldTriangleSoup(soup, 2, 0, 1e-6);
    EXPECT_EQ(m.positions.size(), 4u);
    const auto& n = m.normals[m.indices[1]];
    EXPECT_NEAR(n[0], std::sin(0.0043633f), 1e-6);
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0f, 1e-6);
}

TEST(MeshWeld, TrianglesCollapsedByTheWeldAreLeftOutWithTheirVertices) {
    // A pole: the last two corners agree only to rounding, so the triangle collapses.
    const std::vector<SoupVertex> soup = {v(0, 0, 0, 0), v(1, 0, 0, 0), v(1, 1e-9f, 0, 0), v(0, 0, 0, 1), v(1, 0, 0, 1), v(0, 1, 0, 1)};
    WeldStats st;
    const TriangleMesh m = weldTriangleSoup(soup, 1, 1, 1e-6, &st);
    EXPECT_EQ(st.soupTriangles, 2u);
    EXPECT_EQ(st.degenerateTriangles, 1u);
    EXPECT_EQ(m.indices.size(), 3u);
    EXPECT_EQ(m.positions.size(), 3u);  // no vertex only the dropped triangle used
    ASSERT_EQ(m.perWindow.size(), 1u);
    ASSERT_EQ(m.perTriangle.size(), 1u);
    EXPECT_EQ(m.perWindow[0].indexCount, 0u);
    EXPECT_EQ(m.perTriangle[0].indexCount, 3u);
}

TEST(MeshWeld, TrianglesAreGroupedByItemKeepingTheirOrder) {
    const std::vector<SoupVertex> soup = {v(0, 0, 0, 1), v(1, 0, 0, 1), v(0, 1, 0, 1), v(5, 0, 0, 0), v(6, 0, 0, 0),
                                          v(5, 1, 0, 0), v(0, 2, 0, 1), v(1, 2, 0, 1), v(0, 3, 0, 1)};
    const TriangleMesh m = weldTriangleSoup(soup, 2, 0, 1e-6);
    ASSERT_EQ(m.perWindow.size(), 2u);
    EXPECT_EQ(m.perWindow[0].indexCount, 3u);
    EXPECT_EQ(m.perWindow[1].firstIndex, 3u);
    EXPECT_EQ(m.perWindow[1].indexCount, 6u);
    EXPECT_EQ(m.positions[m.indices[0]][0], 5.0f);
    EXPECT_EQ(m.positions[m.indices[6]][1], 2.0f);  // item 1's second triangle stays second
}

TEST(MeshWeld, MalformedSoupsAreRefused) {
    EXPECT_THROW(weldTriangleSoup({v(0, 0, 0, 0), v(1, 0, 0, 0)}, 1, 0, 1e-6), std::invalid_argument);
    EXPECT_THROW(weldTriangleSoup({v(0, 0, 0, 3), v(1, 0, 0, 3), v(0, 1, 0, 3)}, 1, 1, 1e-6), std::invalid_argument);
}

// The capture welds its pieces while the device makes the next: fed in pieces (item ranges in
// order, empty items between and after them, triangles turned as read), the weld is the one of the
// whole soup turned.
TEST(MeshWeld, PiecesWeldAsTheWholeSoupDoes) {
    std::vector<SoupVertex> soup;
    for (uint32_t item : {0u, 0u, 2u, 3u, 3u, 5u}) {  // items 1, 4 and 6 make nothing
        const float x = float(item), y = float(soup.size() % 2);
        for (const SoupVertex& s : {v(x, y, 0, item), v(x + 1, y, 0, item), v(x, y + 1, 0, item, 0.01f, 0, 1)}) soup.push_back(s);
    }
    std::vector<SoupVertex> turned = soup;
    for (size_t t = 0; t < turned.size(); t += 3) std::swap(turned[t + 1], turned[t + 2]);
    WeldStats whole, pieces;
    const TriangleMesh a = weldTriangleSoup(turned, 5, 2, 1e-6, &whole);
    SoupWelder welder(5, 2, 1e-6, nullptr, soup.size());
    welder.add(soup.data(), 6, SoupWinding::Turned);       // item 0
    welder.add(soup.data() + 6, 9, SoupWinding::Turned);   // items 2 and 3
    welder.add(soup.data() + 15, 3, SoupWinding::Turned);  // item 5, the first Bézier triangle
    const TriangleMesh b = welder.finish(&pieces);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(b.perWindow.size(), 5u);
    ASSERT_EQ(b.perTriangle.size(), 2u);
    for (size_t i = 0; i < 5; ++i) EXPECT_EQ(a.perWindow[i].firstIndex, b.perWindow[i].firstIndex) << i;
    EXPECT_EQ(b.perWindow[1].indexCount, 0u);
    EXPECT_EQ(b.perTriangle[0].indexCount, 3u);
    EXPECT_EQ(b.perTriangle[1].indexCount, 0u);
    for (size_t i = 0; i < 2; ++i) EXPECT_EQ(a.perTriangle[i].firstIndex, b.perTriangle[i].firstIndex) << i;
    EXPECT_EQ(pieces.soupTriangles, whole.soupTriangles);
    // A piece whose items go back is refused.
    SoupWelder back(5, 2, 1e-6, nullptr, 0);
    back.add(soup.data() + 6, 3);
    EXPECT_THROW(back.add(soup.data(), 3), std::invalid_argument);
}

}  // namespace
}  // namespace pw::test

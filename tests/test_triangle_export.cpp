// Cubic Bézier triangles in the export mesh: the dome builder is exact and watertight (shared edges
// welded through the pool, hexagon counts), normals are analytic, finite and outward, triangles
// wind with their normals, and a triangle next to a quad meets it without a gap.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/construct/model_builders.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/mesh/mesh_tessellate.hpp"

using namespace pw;

namespace {

struct MeshStats {
    size_t boundaryEdges = 0, nonManifoldEdges = 0;
};

MeshStats edgeStats(const TriangleMesh& m) {
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = m.indices[t + e], b = m.indices[t + (e + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    MeshStats s;
    for (const auto& [edge, n] : uses) {
        if (n == 1) ++s.boundaryEdges;
        if (n > 2) ++s.nonManifoldEdges;
    }
    return s;
}

Vec3 v3(const std::array<float, 3>& a) { return Vec3(a[0], a[1], a[2]); }

}  // namespace

TEST(TriangleDome, ControlPointsAreSharedAlongEdges) {
    const Document doc = makeTriangleDome();
    ASSERT_EQ(doc.triangles.size(), 6u);
    EXPECT_TRUE(doc.patches.empty());
    // Lattice points of a hexagon of side 3 (37) minus nothing, plus 6 interiors counted in: the
    // hexagon lattice with 3 segments per side has 3·3² + 3·3 + 1 = 37 points.
    EXPECT_EQ(doc.points.size(), 37u);
    // Triangle m's edge 0 (v corner → centre) is triangle m+1's edge 1 (centre → u corner) reversed.
    for (int m = 0; m < 6; ++m) {
        const auto a = triEdgePool(doc.triangles[size_t(m)].idx, 0);
        const auto b = triEdgePool(doc.triangles[size_t((m + 1) % 6)].idx, 1);
        EXPECT_EQ(a, (std::array<uint32_t, 4>{b[3], b[2], b[1], b[0]})) << m;
    }
}

TEST(TriangleDome, SurfaceIsTheParaboloidWithUpwardNormals) {
    const double R = 1.5, h = 0.6;
    const Document doc = makeTriangleDome(R, h);
    for (const TrianglePatch& t : doc.triangles) {
        const Net10 net = gatherTriangleNet(doc, t.idx);
        for (int i = 0; i <= 6; ++i)
            for (int j = 0; j <= 6 - i; ++j) {
                const TriPoint tp = evaluateTriangle(net, i / 6.0, j / 6.0);
                const double r2 = tp.p.x * tp.p.x + tp.p.y * tp.p.y;
                EXPECT_NEAR(tp.p.z, h * (1 - r2 / (R * R)), 1e-12);
                // Paraboloid normal: (2h x/R², 2h y/R², 1), normalised.
                const Vec3 n = glm::normalize(Vec3(2 * h * tp.p.x / (R * R), 2 * h * tp.p.y / (R * R), 1.0));
                EXPECT_LT(glm::length(tp.n - n), 1e-12);
            }
    }
}

TEST(TriangleMesh, DomeIsWeldedAndWatertight) {
    const Document doc = makeTriangleDome();
    for (int L : {1, 2, 5, 16}) {
        SCOPED_TRACE(L);
        const TriangleMesh m = tessellateDocument(doc, L);
        // A hexagon of 6 triangles each split into L²: 3L² + 3L + 1 welded vertices, 6L² triangles,
        // and only the hexagon's rim (6L edges) open.
        EXPECT_EQ(m.positions.size(), size_t(3 * L * L + 3 * L + 1));
        EXPECT_EQ(m.indices.size(), size_t(3 * 6 * L * L));
        ASSERT_EQ(m.perTriangle.size(), 6u);
        for (const MeshRange& r : m.perTriangle) EXPECT_EQ(r.indexCount, uint32_t(3 * L * L));
        const MeshStats st = edgeStats(m);
        EXPECT_EQ(st.boundaryEdges, size_t(6 * L));
        EXPECT_EQ(st.nonManifoldEdges, 0u);
        ASSERT_EQ(m.normals.size(), m.positions.size());
        ASSERT_EQ(m.uvs.size(), m.positions.size());
        for (size_t v = 0; v < m.positions.size(); ++v) {
            const Vec3 n = v3(m.normals[v]);
            ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
            EXPECT_NEAR(glm::length(n), 1.0, 1e-6);
            EXPECT_GT(n.z, 0.0);
            EXPECT_GE(m.uvs[v][0], 0.0f);
            EXPECT_LE(m.uvs[v][0] + m.uvs[v][1], 1.0f + 1e-6f);
        }
        // Winding agrees with the normals (counter-clockwise seen from the normal side).
        for (size_t t = 0; t < m.indices.size(); t += 3) {
            const Vec3 a = v3(m.positions[m.indices[t]]), b = v3(m.positions[m.indices[t + 1]]), c = v3(m.positions[m.indices[t + 2]]);
            const Vec3 face = glm::cross(b - a, c - a);
            EXPECT_GT(glm::dot(face, v3(m.normals[m.indices[t]])), 0.0);
        }
    }
}

TEST(TriangleMesh, TriangleBesideAQuadMeetsItWithoutAGap) {
    // A flat quad on [0,1]² (z = 0) and a curved triangle on its edge y = 0 (pool 0..3), sharing the
    // edge's pool points: the mesh positions along the edge are the same floats on both sides.
    Document doc;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) doc.points.push_back(Vec3(c / 3.0, r / 3.0, 0.0));
    Patch q;
    for (uint32_t k = 0; k < 16; ++k) q.idx[k] = k;
    doc.patches.push_back(q);
    // Triangle: edge 2 (u corner → v corner, slots 0,1,3,6) = pool 3,2,1,0 (the quad's v = 0 row,
    // reversed so that the triangle lies at y < 0 with an upward normal).
    auto add = [&](Vec3 p) {
        doc.points.push_back(p);
        return uint32_t(doc.points.size() - 1);
    };
    TrianglePatch t;
    t.idx[0] = 3;
    t.idx[1] = 2;
    t.idx[3] = 1;
    t.idx[6] = 0;
    t.idx[2] = add(Vec3(0.9, -0.3, 0.2));
    t.idx[4] = add(Vec3(0.5, -0.25, 0.3));
    t.idx[5] = add(Vec3(0.7, -0.6, 0.1));
    t.idx[7] = add(Vec3(0.1, -0.3, 0.2));
    t.idx[8] = add(Vec3(0.3, -0.6, 0.1));
    t.idx[9] = add(Vec3(0.5, -0.9, 0.0));
    doc.triangles.push_back(t);
    const int L = 7;
    const TriangleMesh m = tessellateDocument(doc, L);
    EXPECT_EQ(m.indices.size(), size_t(3 * (2 * L * L + L * L)));
    // Every triangle-mesh position on y = 0 has a quad position with the same floats.
    std::vector<std::array<float, 3>> quadEdge;
    for (uint32_t k = m.perWindow[0].firstIndex; k < m.perWindow[0].firstIndex + m.perWindow[0].indexCount; ++k)
        if (m.positions[m.indices[k]][1] == 0.0f) quadEdge.push_back(m.positions[m.indices[k]]);
    size_t onEdge = 0;
    for (uint32_t k = m.perTriangle[0].firstIndex; k < m.perTriangle[0].firstIndex + m.perTriangle[0].indexCount; ++k) {
        const auto& p = m.positions[m.indices[k]];
        if (std::abs(p[1]) > 1e-6f) continue;
        ++onEdge;
        EXPECT_NE(std::find(quadEdge.begin(), quadEdge.end(), p), quadEdge.end()) << p[0] << " " << p[1] << " " << p[2];
    }
    EXPECT_GT(onEdge, size_t(L));
}

// A flat quad on [0,3]² (z = 0) and a triangle on its edge y = 0, sharing the edge's pool points;
// the triangle's far corner at (1.5, -3, z).
Document quadAndTriangle(double z) {
    Document doc;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) doc.points.push_back(Vec3(c, r, 0.0));
    Patch q;
    for (uint32_t k = 0; k < 16; ++k) q.idx[k] = k;
    doc.patches.push_back(q);
    const Vec3 U(3, 0, 0), V(0, 0, 0), W(1.5, -3, z);  // edge 2 (u -> v) = pool 3, 2, 1, 0
    auto add = [&](Vec3 p) {
        doc.points.push_back(p);
        return uint32_t(doc.points.size() - 1);
    };
    TrianglePatch t;
    t.idx[0] = 3;
    t.idx[1] = 2;
    t.idx[3] = 1;
    t.idx[6] = 0;
    t.idx[2] = add((2.0 * U + W) / 3.0);  // b201
    t.idx[4] = add((U + V + W) / 3.0);    // b111
    t.idx[5] = add((U + 2.0 * W) / 3.0);  // b102
    t.idx[7] = add((2.0 * V + W) / 3.0);  // b021
    t.idx[8] = add((V + 2.0 * W) / 3.0);  // b012
    t.idx[9] = add(W);
    doc.triangles.push_back(t);
    return doc;
}

TEST(TriangleMesh, TriangleBesideAQuadIsWeldedWhereSmoothAndSplitAtACrease) {
    const int L = 6;
    const size_t quadVerts = size_t(L + 1) * (L + 1), triVerts = size_t(L + 1) * (L + 2) / 2;
    // Coplanar: the seam's L + 1 vertices are the quad's, so the seam is inside the mesh.
    const TriangleMesh flat = tessellateDocument(quadAndTriangle(0.0), L);
    EXPECT_EQ(flat.positions.size(), quadVerts + triVerts - size_t(L + 1));
    EXPECT_EQ(edgeStats(flat).boundaryEdges, size_t(3 * L + 2 * L));  // 3 quad sides + 2 triangle sides
    EXPECT_EQ(edgeStats(flat).nonManifoldEdges, 0u);
    for (const auto& n : flat.normals) EXPECT_NEAR(n[2], 1.0f, 1e-5f);
    // Folded down by 45 degrees: a crease, so each side keeps its own vertices (and normals).
    const TriangleMesh fold = tessellateDocument(quadAndTriangle(3.0), L);
    EXPECT_EQ(fold.positions.size(), quadVerts + triVerts);
    EXPECT_EQ(edgeStats(fold).boundaryEdges, size_t(4 * L + 3 * L));
}

TEST(TriangleMesh, CollapsedEdgeLeavesNoDegenerateTrianglesOrNaN) {
    Document doc = makeTriangleDome();
    // Collapse triangle 0's edge 2 (its two hexagon corners and the points between) to one point.
    TrianglePatch t = doc.triangles[0];
    for (int k = 1; k < 4; ++k) t.idx[size_t(triEdgeSlot(2, k))] = t.idx[size_t(triEdgeSlot(2, 0))];
    doc.triangles = {t};
    const TriangleMesh m = tessellateDocument(doc, 6);
    EXPECT_EQ(m.indices.size(), size_t(3 * (36 - 6)));  // the row of 6 triangles on the edge is gone
    for (size_t i = 0; i < m.indices.size(); i += 3) {
        const Vec3 a = v3(m.positions[m.indices[i]]), b = v3(m.positions[m.indices[i + 1]]), c = v3(m.positions[m.indices[i + 2]]);
        EXPECT_GT(glm::length(glm::cross(b - a, c - a)), 0.0);
    }
    for (const auto& n : m.normals) {
        ASSERT_TRUE(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]));
        EXPECT_NEAR(glm::length(v3(n)), 1.0, 1e-6);
    }
}

TEST(TriangleMesh, CageHasEighteenSegmentsPerTriangle) {
    Document one = makeTriangleDome();
    one.triangles.resize(1);
    EXPECT_EQ(controlCage(one).indices.size(), 36u);
    // The dome: shared edges counted once: 6 · 18 − 6 · 3 (each interior edge curve has 3 segments).
    EXPECT_EQ(controlCage(makeTriangleDome()).indices.size(), size_t(2 * (6 * 18 - 6 * 3)));
}

// Trimmed surfaces as meshes (issue 64): the glTF and OBJ exports cut each trimmed window along its
// loops (a constrained triangulation of its (u, v) square), and two surfaces cut by one
// intersection share the vertices of their cut, so the mesh is watertight there.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "core/edit/edit_session.hpp"
#include "core/io/gltf_export.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"
#include "core/trim/trim_mesh.hpp"
#include "support.hpp"

using namespace pw;

namespace {

Document plateAndTube() {
    Document d;
    d.name = "plate and tube";
    Patch p;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            p.idx[size_t(i * 4 + j)] = uint32_t(d.points.size());
            d.points.emplace_back(2.0 * j / 3.0, 2.0 * i / 3.0, 0.0);
        }
    d.patches.push_back(p);
    Surface s;  // a closed B-spline tube round (1, 1), its surface from z = -0.1 to 0.9
    s.rows = 5;
    s.cols = 8;
    s.closedU = true;
    for (uint32_t i = 0; i < s.rows; ++i)
        for (uint32_t j = 0; j < s.cols; ++j) {
            const double a = 2.0 * std::numbers::pi * j / s.cols;
            s.idx.push_back(uint32_t(d.points.size()));
            d.points.emplace_back(1.0 + 0.4 * std::cos(a), 1.0 + 0.4 * std::sin(a), -0.6 + 0.5 * i);
        }
    d.surfaces.push_back(s);
    return d;
}

struct EdgeCount {
    size_t open = 0, overused = 0;
    std::vector<std::array<float, 3>> openEnds;
};
EdgeCount edges(const TriangleMesh& m) {
    std::map<std::pair<uint32_t, uint32_t>, int> n;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = m.indices[t + size_t(k)], b = m.indices[t + size_t((k + 1) % 3)];
            ++n[{std::min(a, b), std::max(a, b)}];
        }
    EdgeCount c;
    for (const auto& [e, k] : n) {
        if (k == 1) {
            ++c.open;
            c.openEnds.push_back(m.positions[e.first]);
            c.openEnds.push_back(m.positions[e.second]);
        }
        if (k > 2) ++c.overused;
    }
    return c;
}

}  // namespace

// The plate with the tube's hole and the tube cut off below it: open edges only on the plate's
// outside and the tube's top; none along the cut, where both share their vertices.
TEST(TrimMesh, ACutSharedByTwoSurfacesIsWatertight) {
    EditSession s;
    s.reset(plateAndTube(), "");
    test::runEditScript(s, "intersect 0 n0; trim 0 c0 remove; trim n0 c0 remove");
    for (int level : {4, 8, 16}) {
        SCOPED_TRACE("level " + std::to_string(level));
        const TriangleMesh mesh = tessellateTrimmed(s.doc, level);
        const EdgeCount c = edges(mesh);
        EXPECT_EQ(c.overused, 0u);
        EXPECT_GT(c.open, 0u);
        size_t elsewhere = 0;
        for (const auto& p : c.openEnds) {
            const bool plateEdge = std::abs(p[2]) < 1e-6 && (std::min(p[0], p[1]) < 1e-5 || std::max(p[0], p[1]) > 2.0 - 1e-5);
            const bool tubeTop = p[2] > 0.85;
            elsewhere += plateEdge || tubeTop ? 0 : 1;
        }
        EXPECT_EQ(elsewhere, 0u) << "open edges along the cut";
        // Nothing of the plate inside the hole, nothing of the tube below the plate.
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            std::array<float, 3> c3{0, 0, 0};
            for (int k = 0; k < 3; ++k)
                for (int d = 0; d < 3; ++d) c3[size_t(d)] += mesh.positions[mesh.indices[t + size_t(k)]][size_t(d)] / 3.0f;
            EXPECT_GT(c3[2], -1e-4) << "a triangle of the tube below the plate";
            if (std::abs(c3[2]) < 1e-6) {
                EXPECT_TRUE(trimKeeps(s.doc.patches[0].trims, glm::dvec2(c3[0] / 2.0, c3[1] / 2.0)))
                    << "a triangle of the plate in the hole";
            }
        }
    }
    // The kept plate's triangles add up to its trimmed area.
    const TriangleMesh fine = tessellateTrimmed(s.doc, 32);
    double plate = 0.0;
    const MeshRange r = fine.perWindow[0];
    for (uint32_t i = r.firstIndex; i < r.firstIndex + r.indexCount; i += 3) {
        const auto& a = fine.positions[fine.indices[i]];
        const auto& b = fine.positions[fine.indices[i + 1]];
        const auto& c = fine.positions[fine.indices[i + 2]];
        plate += 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    }
    EXPECT_NEAR(plate, trimmedArea(DomainSurface(s.doc, {false, 0}), s.doc.patches[0].trims), 2e-3);
    // The export is a valid glTF.
    const auto dir = test::freshTempDir("trim-mesh");
    exportGltf(s.doc, dir / "cut.glb", ExportOptions{});
    test::expectValidGltf({dir / "cut.glb"});
}

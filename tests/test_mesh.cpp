// CPU tessellation (DESIGN §5): welded, crack-free meshes of the tea set with consistent winding,
// finite outward unit normals, fans at collapsed edges; seams split at C0 and shared at C1; the
// control cage.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/construct/model_builders.hpp"
#include "core/io/bpt_format.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/model/document.hpp"
#include "core/ops/net_ops.hpp"
#include "support.hpp"

namespace {

using pw::TriangleMesh;
using Float3 = std::array<float, 3>;

// Welds vertices by exact float position, independently of the tessellator's own welding.
std::vector<uint32_t> weldByPosition(const TriangleMesh& mesh, size_t* distinct = nullptr) {
    std::map<Float3, uint32_t> ids;
    std::vector<uint32_t> out(mesh.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v)
        out[v] = ids.emplace(mesh.positions[v], static_cast<uint32_t>(ids.size())).first->second;
    if (distinct) *distinct = ids.size();
    return out;
}

struct EdgeStats {
    size_t boundaryEdges = 0;
    size_t overusedEdges = 0;      // used by more than two triangles
    size_t inconsistentEdges = 0;  // two triangles traversing it in the same direction
    size_t degenerateTriangles = 0;
};

// Edge use after welding by position; the triangles of the windows in `skip` are left out.
EdgeStats edgeStats(const TriangleMesh& mesh, const std::set<size_t>& skip = {}) {
    const std::vector<uint32_t> w = weldByPosition(mesh);
    std::vector<bool> skipped(mesh.indices.size() / 3, false);
    for (size_t win : skip) {
        const pw::MeshRange& r = mesh.perWindow[win];
        for (uint32_t i = r.firstIndex; i < r.firstIndex + r.indexCount; i += 3) skipped[i / 3] = true;
    }
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    EdgeStats st;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        if (skipped[t / 3]) continue;
        const uint32_t v[3] = {w[mesh.indices[t]], w[mesh.indices[t + 1]], w[mesh.indices[t + 2]]};
        const Float3& a = mesh.positions[mesh.indices[t]];
        const Float3& b = mesh.positions[mesh.indices[t + 1]];
        const Float3& c = mesh.positions[mesh.indices[t + 2]];
        const double e1[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
        const double e2[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
        const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2], cz = e1[0] * e2[1] - e1[1] * e2[0];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] || cx * cx + cy * cy + cz * cz == 0.0) ++st.degenerateTriangles;
        for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
    }
    std::set<std::pair<uint32_t, uint32_t>> seen;
    for (const auto& [e, n] : directed) {
        const std::pair<uint32_t, uint32_t> key{std::min(e.first, e.second), std::max(e.first, e.second)};
        if (!seen.insert(key).second) continue;
        const auto rev = directed.find({e.second, e.first});
        const int forward = n, backward = rev == directed.end() ? 0 : rev->second;
        const int total = forward + backward;
        if (total == 1) ++st.boundaryEdges;
        if (total > 2) ++st.overusedEdges;
        if (total == 2 && (forward != 1 || backward != 1)) ++st.inconsistentEdges;
    }
    return st;
}

double length(const Float3& n) { return std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]); }

pw::Document teapot() { return pw::loadBpt(pw::test::dataDir() / "teapot.bpt"); }

// Vertices of one window (through its triangles).
std::set<uint32_t> windowVertices(const TriangleMesh& mesh, size_t window) {
    std::set<uint32_t> out;
    const pw::MeshRange& r = mesh.perWindow[window];
    for (uint32_t i = r.firstIndex; i < r.firstIndex + r.indexCount; ++i) out.insert(mesh.indices[i]);
    return out;
}

TEST(Mesh, TeapotIsWatertightWithSixteenOpenCurves) {
    const pw::Document doc = teapot();
    ASSERT_EQ(doc.patches.size(), 32u);
    for (int level : {1, 2, 4, 8, 16}) {
        SCOPED_TRACE("level " + std::to_string(level));
        const TriangleMesh mesh = pw::tessellateDocument(doc, level);
        ASSERT_EQ(mesh.perWindow.size(), 32u);
        ASSERT_EQ(mesh.indices.size() % 3, 0u);
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        if (level > 1) {
            const EdgeStats st = edgeStats(mesh);
            EXPECT_EQ(st.boundaryEdges, 16u * level);  // rim, lid bottom, handle and spout ends
            EXPECT_EQ(st.overusedEdges, 0u);
            EXPECT_EQ(st.inconsistentEdges, 0u);
            EXPECT_EQ(st.degenerateTriangles, 0u);
        } else {
            // Level 1 is one quad per patch, and the handle and spout (patches 13–20) are made of
            // mirror-image halves whose corners all lie in the symmetry plane y = 0: at level 1
            // both halves are the same flat strip (the spout tip patches 19 and 20 even have all
            // four corners on one line), so their triangles overlap or have no area. The rest of
            // the pot is watertight with two open loops of 4 segments (rim and lid bottom).
            std::set<size_t> handleAndSpout;
            for (size_t w = 12; w < 20; ++w) handleAndSpout.insert(w);
            const EdgeStats st = edgeStats(mesh, handleAndSpout);
            EXPECT_EQ(st.boundaryEdges, 8u);
            EXPECT_EQ(st.overusedEdges, 0u);
            EXPECT_EQ(st.inconsistentEdges, 0u);
            EXPECT_EQ(st.degenerateTriangles, 0u);
            for (size_t w : handleAndSpout) {
                const pw::MeshRange& r = mesh.perWindow[w];
                EXPECT_EQ(r.indexCount, 6u);
                for (uint32_t i = r.firstIndex; i < r.firstIndex + r.indexCount; ++i)
                    EXPECT_EQ(mesh.positions[mesh.indices[i]][1], 0.0f) << "patch " << w + 1;
            }
        }

        // Window ranges tile the index list in order.
        uint32_t next = 0;
        for (const pw::MeshRange& r : mesh.perWindow) {
            EXPECT_EQ(r.firstIndex, next);
            next += r.indexCount;
        }
        EXPECT_EQ(next, mesh.indices.size());

        // Every vertex is used, every index is in range.
        std::vector<bool> used(mesh.positions.size(), false);
        for (uint32_t i : mesh.indices) {
            ASSERT_LT(i, mesh.positions.size());
            used[i] = true;
        }
        for (size_t v = 0; v < used.size(); ++v) EXPECT_TRUE(used[v]) << "vertex " << v << " unused";

        // Normals: finite and unit length; UVs in [0, 1].
        for (size_t v = 0; v < mesh.normals.size(); ++v) {
            const Float3& n = mesh.normals[v];
            ASSERT_TRUE(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2])) << "vertex " << v;
            ASSERT_LT(std::abs(length(n) - 1.0), 1e-5) << "vertex " << v;
            ASSERT_GE(mesh.uvs[v][0], 0.0f);
            ASSERT_LE(mesh.uvs[v][0], 1.0f);
            ASSERT_GE(mesh.uvs[v][1], 0.0f);
            ASSERT_LE(mesh.uvs[v][1], 1.0f);
        }
    }
}

TEST(Mesh, TeacupAndTeaspoonAreWatertight) {
    // data/README.md: the teacup has 12 open boundary curves, the teaspoon 8.
    for (const auto& [file, open] : {std::pair{"teacup.bpt", 12u}, std::pair{"teaspoon.bpt", 8u}}) {
        const pw::Document doc = pw::loadBpt(pw::test::dataDir() / file);
        for (int level : {2, 4, 8, 16}) {
            SCOPED_TRACE(std::string(file) + " level " + std::to_string(level));
            const TriangleMesh mesh = pw::tessellateDocument(doc, level);
            const EdgeStats st = edgeStats(mesh);
            EXPECT_EQ(st.boundaryEdges, open * level);
            EXPECT_EQ(st.overusedEdges, 0u);
            EXPECT_EQ(st.inconsistentEdges, 0u);
            EXPECT_EQ(st.degenerateTriangles, 0u);
            for (const Float3& n : mesh.normals) ASSERT_LT(std::abs(length(n) - 1.0), 1e-5);
        }
    }
}

TEST(Mesh, TeapotTriangleCountsAndFans) {
    // 32 patches of level² cells, two triangles each, less one per cell along the 8 collapsed edges.
    const pw::Document doc = teapot();
    for (int level : {1, 2, 4, 8, 16}) {
        const TriangleMesh mesh = pw::tessellateDocument(doc, level);
        EXPECT_EQ(mesh.indices.size() / 3, static_cast<size_t>(32 * 2 * level * level - 8 * level)) << "level " << level;
    }
}

TEST(Mesh, TeapotNormalsPointOutward) {
    const pw::Document doc = teapot();
    for (int level : {1, 2, 4, 8, 16}) {
        SCOPED_TRACE("level " + std::to_string(level));
        const TriangleMesh mesh = pw::tessellateDocument(doc, level);
        // Body (patches 5–12, 1-based): the normal points away from the z axis.
        for (size_t w = 4; w < 12; ++w) {
            for (uint32_t v : windowVertices(mesh, w)) {
                const Float3& p = mesh.positions[v];
                const Float3& n = mesh.normals[v];
                const double r = std::hypot(p[0], p[1]);
                ASSERT_GT(r, 0.5);
                EXPECT_GT((n[0] * p[0] + n[1] * p[1]) / r, 0.0) << "patch " << w + 1 << " vertex " << v;
            }
        }
        // Lid top (0, 0, 3.15): +z; bottom centre (0, 0, 0): -z.
        int top = 0, bottom = 0;
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            const Float3& p = mesh.positions[v];
            const Float3& n = mesh.normals[v];
            if (p[0] == 0.0f && p[1] == 0.0f && p[2] == 3.15f) {
                ++top;
                EXPECT_GT(n[2], 0.999f) << "lid top normal " << n[0] << " " << n[1] << " " << n[2];
            }
            if (p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f) {
                ++bottom;
                EXPECT_LT(n[2], -0.999f) << "bottom centre normal " << n[0] << " " << n[1] << " " << n[2];
            }
        }
        EXPECT_GE(top, 1);
        EXPECT_GE(bottom, 1);
    }
}

TEST(Mesh, TeapotWindingAgreesWithNormals) {
    // Counter-clockwise seen from the normal side: the geometric triangle normal agrees with the
    // vertex normals.
    const TriangleMesh mesh = pw::tessellateDocument(teapot(), 8);
    size_t disagree = 0;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const Float3& a = mesh.positions[mesh.indices[t]];
        const Float3& b = mesh.positions[mesh.indices[t + 1]];
        const Float3& c = mesh.positions[mesh.indices[t + 2]];
        const double e1[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
        const double e2[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
        const double g[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double dot = 0;
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) dot += g[d] * mesh.normals[mesh.indices[t + k]][d];
        if (!(dot > 0)) ++disagree;
    }
    EXPECT_EQ(disagree, 0u);
}

// Two bicubic patches side by side, A over x in [0,3] and B over x in [3,6], sharing the column
// x = 3; B bends upwards (a crease) when `kink`.
pw::Document twoPatches(pw::Continuity continuity, bool kink) {
    pw::Document doc;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 7; ++j) doc.points.push_back(pw::Vec3(j, i, kink && j > 3 ? (j - 3) * 1.0 : 0.0));
    pw::Patch a, b;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            a.idx[i * 4 + j] = static_cast<uint32_t>(i * 7 + j);
            b.idx[i * 4 + j] = static_cast<uint32_t>(i * 7 + j + 3);
        }
    doc.patches = {a, b};
    pw::Join join;
    join.patchA = 0;
    join.edgeA = pw::Edge::U1;
    join.patchB = 1;
    join.edgeB = pw::Edge::U0;
    join.continuity = continuity;
    doc.joins = {join};
    return doc;
}

TEST(Mesh, C0SeamIsSplitAndC1SeamIsShared) {
    const int L = 6;
    for (bool c1 : {false, true}) {
        SCOPED_TRACE(c1 ? "C1" : "C0");
        const pw::Document doc = twoPatches(c1 ? pw::Continuity::C1 : pw::Continuity::C0, !c1);
        const TriangleMesh mesh = pw::tessellateDocument(doc, L);
        const size_t expected = c1 ? 2 * (L + 1) * (L + 1) - (L + 1) : 2 * (L + 1) * (L + 1);
        EXPECT_EQ(mesh.positions.size(), expected);
        size_t distinct = 0;
        weldByPosition(mesh, &distinct);
        EXPECT_EQ(distinct, static_cast<size_t>(2 * (L + 1) * (L + 1) - (L + 1)));  // bit-identical seam
        // Seam vertices (x == 3): one per position at C1, two (with different normals) at C0.
        std::map<Float3, std::vector<uint32_t>> seam;
        for (size_t v = 0; v < mesh.positions.size(); ++v)
            if (mesh.positions[v][0] == 3.0f) seam[mesh.positions[v]].push_back(static_cast<uint32_t>(v));
        EXPECT_EQ(seam.size(), static_cast<size_t>(L + 1));
        for (const auto& [p, vs] : seam) {
            ASSERT_EQ(vs.size(), c1 ? 1u : 2u);
            if (!c1) {
                const Float3 &n0 = mesh.normals[vs[0]], &n1 = mesh.normals[vs[1]];
                EXPECT_LT(n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2], 0.99f);  // a crease
            }
        }
        const EdgeStats st = edgeStats(mesh);
        EXPECT_EQ(st.boundaryEdges, static_cast<size_t>(6 * L));
        EXPECT_EQ(st.inconsistentEdges, 0u);
        EXPECT_EQ(st.overusedEdges, 0u);
    }
}

TEST(Mesh, C1SeamNormalIsTheAverage) {
    // A C1 seam between a flat patch and one that starts with the same tangent: the shared normal
    // is the normalised average of both sides' (equal) normals, i.e. +z.
    const pw::Document doc = twoPatches(pw::Continuity::C1, false);
    const TriangleMesh mesh = pw::tessellateDocument(doc, 4);
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        EXPECT_FLOAT_EQ(mesh.normals[v][2], 1.0f);
    }
}

TEST(Mesh, UnjoinedSharedBoundaryIsSplit) {
    pw::Document doc = twoPatches(pw::Continuity::C1, false);
    doc.joins.clear();
    const TriangleMesh mesh = pw::tessellateDocument(doc, 3);
    EXPECT_EQ(mesh.positions.size(), 2u * 16u);
}

TEST(Mesh, JoinedPatchGridSharesCornersAndEdges) {
    // A C1-joined 3x2 grid at level L welds into one (3L+1) x (2L+1) vertex grid.
    const int L = 5;
    const pw::Document doc = pw::makePatchGrid(3, 2, pw::Continuity::C1);
    const TriangleMesh mesh = pw::tessellateDocument(doc, L);
    EXPECT_EQ(mesh.positions.size(), static_cast<size_t>((3 * L + 1) * (2 * L + 1)));
    EXPECT_EQ(mesh.indices.size() / 3, static_cast<size_t>(2 * 6 * L * L));
    const EdgeStats st = edgeStats(mesh);
    EXPECT_EQ(st.boundaryEdges, static_cast<size_t>(2 * (3 + 2) * L));
    EXPECT_EQ(st.inconsistentEdges, 0u);
}

TEST(Mesh, SplineSurfaceWindowsShareOneGrid) {
    // A 6x5 uniform B-spline net has 3x2 windows; they weld into one (3L+1) x (2L+1) grid.
    pw::Document doc;
    pw::Surface s;
    s.rows = 6;
    s.cols = 5;
    s.basis = pw::Basis::BSpline;
    for (uint32_t i = 0; i < s.rows; ++i)
        for (uint32_t j = 0; j < s.cols; ++j) {
            s.idx.push_back(static_cast<uint32_t>(doc.points.size()));
            doc.points.push_back(pw::Vec3(j, i, 0.3 * std::sin(double(i + 2 * j))));
        }
    doc.surfaces = {s};
    const int L = 4;
    const TriangleMesh mesh = pw::tessellateDocument(doc, L);
    EXPECT_EQ(mesh.perWindow.size(), 6u);
    EXPECT_EQ(mesh.positions.size(), static_cast<size_t>((3 * L + 1) * (2 * L + 1)));
    const EdgeStats st = edgeStats(mesh);
    EXPECT_EQ(st.boundaryEdges, static_cast<size_t>(2 * (3 + 2) * L));
    EXPECT_EQ(st.inconsistentEdges, 0u);
    EXPECT_EQ(st.overusedEdges, 0u);
}

TEST(Mesh, ClosedSplineTubeWrapsAround) {
    // A B-spline net closed in u (8 columns around, 5 rows): 8 x 2 windows, one vertex ring per row
    // of the grid with no seam where it wraps; only the two end circles are open.
    pw::Document doc;
    pw::Surface s;
    s.rows = 5;
    s.cols = 8;
    s.basis = pw::Basis::BSpline;
    s.closedU = true;
    for (uint32_t i = 0; i < s.rows; ++i)
        for (uint32_t j = 0; j < s.cols; ++j) {
            s.idx.push_back(static_cast<uint32_t>(doc.points.size()));
            const double a = 2 * 3.14159265358979 * j / s.cols;
            doc.points.push_back(pw::Vec3(std::cos(a), std::sin(a), 0.5 * i));
        }
    doc.surfaces = {s};
    const int L = 4;
    const TriangleMesh mesh = pw::tessellateDocument(doc, L);
    EXPECT_EQ(mesh.perWindow.size(), 16u);
    EXPECT_EQ(mesh.positions.size(), static_cast<size_t>((2 * L + 1) * 8 * L));
    const EdgeStats st = edgeStats(mesh);
    EXPECT_EQ(st.boundaryEdges, static_cast<size_t>(2 * 8 * L));
    EXPECT_EQ(st.inconsistentEdges, 0u);
    EXPECT_EQ(st.overusedEdges, 0u);
    EXPECT_EQ(st.degenerateTriangles, 0u);
}

TEST(Mesh, CollapsedEdgeBecomesOneVertexFan) {
    // One patch whose v0 row is a single pool point: a fan, no degenerate triangle, no unused vertex.
    pw::Document doc;
    doc.points.push_back(pw::Vec3(0, 0, 1));
    pw::Patch p;
    for (int j = 0; j < 4; ++j) p.idx[j] = 0;
    for (int i = 1; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            p.idx[i * 4 + j] = static_cast<uint32_t>(doc.points.size());
            const double a = j * 0.5, r = i;
            doc.points.push_back(pw::Vec3(r * std::cos(a), r * std::sin(a), 1.0 - 0.1 * i));
        }
    doc.patches = {p};
    const int L = 4;
    const TriangleMesh mesh = pw::tessellateDocument(doc, L);
    EXPECT_EQ(mesh.positions.size(), static_cast<size_t>(L * (L + 1) + 1));
    EXPECT_EQ(mesh.indices.size() / 3, static_cast<size_t>(2 * L * L - L));
    EXPECT_EQ(edgeStats(mesh).degenerateTriangles, 0u);
    for (const Float3& n : mesh.normals) EXPECT_LT(std::abs(length(n) - 1.0), 1e-5);
}

TEST(Mesh, RejectsBadLevels) {
    const pw::Document doc = twoPatches(pw::Continuity::C1, false);
    EXPECT_THROW(pw::tessellateDocument(doc, 0), std::invalid_argument);
    EXPECT_THROW(pw::tessellateDocument(doc, 100000), std::invalid_argument);
}

TEST(Mesh, ControlCageOfTheTeapot) {
    const pw::Document doc = teapot();
    const pw::CageLines cage = pw::controlCage(doc);
    EXPECT_EQ(cage.positions.size(), doc.points.size());  // every pool point is used by a patch
    ASSERT_EQ(cage.indices.size() % 2, 0u);
    std::set<std::pair<uint32_t, uint32_t>> segs;
    for (size_t k = 0; k < cage.indices.size(); k += 2) {
        const uint32_t a = cage.indices[k], b = cage.indices[k + 1];
        ASSERT_LT(a, cage.positions.size());
        ASSERT_LT(b, cage.positions.size());
        EXPECT_NE(a, b);
        EXPECT_TRUE(segs.insert({std::min(a, b), std::max(a, b)}).second) << "duplicate segment";
    }
    // 24 net segments per patch, fewer after removing the shared and collapsed ones.
    EXPECT_LT(segs.size(), 32u * 24u);
    EXPECT_GT(segs.size(), 32u * 12u);
}

}  // namespace

TEST(Mesh, ClosedNetsAreWatertightAndKeptC1BezierSeamsShareVertices) {
    for (pw::Basis basis : {pw::Basis::BSpline, pw::Basis::CatmullRom, pw::Basis::Bezier}) {
        SCOPED_TRACE(std::string(pw::basisName(basis)));
        pw::Document doc;
        pw::addNetSurface(doc, 6, 9, pw::NetShape::Torus, basis, pw::Vec3(0.0), 2.0);
        pw::addNetSurface(doc, basis == pw::Basis::Bezier ? 7 : 5, 9, pw::NetShape::Tube, basis, pw::Vec3(3.0, 0.0, 0.0), 2.0);
        doc.surfaces[0].keepC1 = doc.surfaces[1].keepC1 = true;
        for (int level : {3, 8}) {
            const TriangleMesh mesh = pw::tessellateDocument(doc, level);
            const EdgeStats st = edgeStats(mesh);
            const size_t around = basis == pw::Basis::Bezier ? 3 : 9;  // windows around the tube
            EXPECT_EQ(st.boundaryEdges, 2 * around * level);           // the tube's two open ends only
            EXPECT_EQ(st.overusedEdges, 0u);
            EXPECT_EQ(st.inconsistentEdges, 0u);
            EXPECT_EQ(st.degenerateTriangles, 0u);
            size_t distinct = 0;
            weldByPosition(mesh, &distinct);
            EXPECT_EQ(mesh.positions.size(), distinct);  // every seam welded: one vertex per position
        }
    }
}

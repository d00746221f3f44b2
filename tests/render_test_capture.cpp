// Export as displayed (render/scene/surface_capture.cpp): the tessellator's triangles read back through
// transform feedback (validation layer on, any message fails). The capture holds exactly the
// triangles the frame's statistics count for every partitioning and adaptive mode; welded, the
// teapot is watertight (open edges only on its real boundary, no T-junctions, nothing left unwelded)
// and at a uniform level it is the CPU export's mesh; Bézier triangles and culling are captured as drawn.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/construct/model_builders.hpp"
#include "core/gpu/tess_place.h"
#include "core/io/bpt_format.hpp"
#include "core/io/document_io.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "render_support.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

class RenderCapture : public RenderTest {};

Document teapot() { return loadDocument(dataDir() / "teapot.bpt"); }

using Edge = std::pair<uint32_t, uint32_t>;

// Edges (by vertex index) used by exactly one triangle.
std::vector<Edge> openEdges(const TriangleMesh& m) {
    std::map<Edge, int> uses;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = m.indices[t + size_t(k)], b = m.indices[t + size_t((k + 1) % 3)];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    std::vector<Edge> open;
    for (const auto& [e, n] : uses) {
        EXPECT_LE(n, 2) << "an edge used by " << n << " triangles";
        if (n == 1) open.push_back(e);
    }
    return open;
}

double dist(const std::array<float, 3>& a, const std::array<float, 3>& b) {
    return std::sqrt(double(a[0] - b[0]) * (a[0] - b[0]) + double(a[1] - b[1]) * (a[1] - b[1]) + double(a[2] - b[2]) * (a[2] - b[2]));
}

// Cracks: an open edge's end strictly inside another open edge (a T-junction), or two open-edge
// ends closer than `tol` that were not welded.
size_t cracks(const TriangleMesh& m, const std::vector<Edge>& open, double tol) {
    std::set<uint32_t> ends;
    for (const auto& [a, b] : open) ends.insert(a), ends.insert(b);
    size_t n = 0;
    for (uint32_t v : ends) {
        const auto& p = m.positions[v];
        for (const auto& [a, b] : open) {
            if (v == a || v == b) continue;
            const auto &A = m.positions[a], &B = m.positions[b];
            double ab[3], ap[3], len2 = 0, t = 0;
            for (int i = 0; i < 3; ++i) ab[i] = double(B[i]) - A[i], ap[i] = double(p[i]) - A[i], len2 += ab[i] * ab[i], t += ab[i] * ap[i];
            t /= len2;
            if (t <= 1e-4 || t >= 1 - 1e-4) continue;
            double d2 = 0;
            for (int i = 0; i < 3; ++i) d2 += (ap[i] - t * ab[i]) * (ap[i] - t * ab[i]);
            if (std::sqrt(d2) < 10 * tol) ++n;
        }
        for (uint32_t w : ends)
            if (w > v && dist(p, m.positions[w]) < tol) ++n;
    }
    return n;
}

// The share of triangles that are counter-clockwise seen from their first vertex's normal.
double windingAgreement(const TriangleMesh& m) {
    size_t agree = 0;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const auto &a = m.positions[m.indices[t]], &b = m.positions[m.indices[t + 1]], &d = m.positions[m.indices[t + 2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const auto& vn = m.normals[m.indices[t]];
        if (n[0] * vn[0] + n[1] * vn[1] + n[2] * vn[2] > 0) ++agree;
    }
    return m.indices.empty() ? 0.0 : double(agree) / double(m.indices.size() / 3);
}

render::RenderOptions teapotOptions(const Document& doc, Spacing spacing, AdaptiveMode adaptive, float level) {
    render::RenderOptions o = plainOptions(doc, level, 320.0 / 240.0);
    o.tess.spacing = spacing;
    o.tess.adaptive = adaptive;
    o.tess.cullOffscreen = false;
    return o;
}

TEST_F(RenderCapture, TeapotAtAUniformLevelIsTheCpuExportsMesh) {
    const Document doc = teapot();
    Offscreen off(320, 240, false);
    off.setDocument(doc);
    const render::CapturedSurface c = off.capture(teapotOptions(doc, Spacing::Equal, AdaptiveMode::None, 16.0f));
    EXPECT_EQ(c.gpuTriangles, 32u * 2 * 16 * 16);
    const TriangleMesh cpu = tessellateDocument(doc, 16);
    EXPECT_EQ(c.mesh.indices.size(), cpu.indices.size());  // both leave out the same pole triangles
    EXPECT_EQ(c.gpuTriangles - c.degenerate, cpu.indices.size() / 3);
    ASSERT_EQ(c.mesh.perWindow.size(), 32u);
    for (size_t w = 0; w < 32; ++w) EXPECT_EQ(c.mesh.perWindow[w].indexCount, cpu.perWindow[w].indexCount) << "window " << w;
    // Every captured vertex is a CPU vertex (the same parameter values on the exact surface).
    std::vector<std::array<float, 3>> ref = cpu.positions;
    std::sort(ref.begin(), ref.end());
    const double tol = 1e-5 * modelSize(doc);
    for (const auto& p : c.mesh.positions) {
        auto it = std::lower_bound(ref.begin(), ref.end(), std::array<float, 3>{p[0] - float(tol), -1e30f, -1e30f});
        double best = 1e30;
        for (; it != ref.end() && (*it)[0] <= p[0] + float(tol); ++it) best = std::min(best, dist(*it, p));
        ASSERT_LT(best, tol) << p[0] << " " << p[1] << " " << p[2];
    }
    const auto open = openEdges(c.mesh);
    EXPECT_EQ(open.size(), 256u);  // 16 boundary curves x 16 segments, as the CPU export
    EXPECT_EQ(open.size(), openEdges(cpu).size());
    EXPECT_EQ(cracks(c.mesh, open, tol), 0u);
    EXPECT_GT(windingAgreement(c.mesh), 0.99);  // counter-clockwise seen from the normal, like the CPU mesh
    EXPECT_GT(windingAgreement(cpu), 0.99);
}

// The tessellator's own coordinates (the captured UVs of one patch at level n, equal spacing) are
// where core/gpu/tess_place.h says a fixed-point tessellator puts them: merged blocks place their
// vertices by it (render/scene/merged_blocks.hpp), so a window in a block is where it would be alone.
TEST_F(RenderCapture, TheFixedPointTessellatorPlacesPointsAsTessPlaceSays) {
    if (!sharedDevice().caps().fixedPointTessellator) GTEST_SKIP() << "not Mesa's fixed-point tessellator";
    const Document doc = makePatchGrid(1, 1);
    Offscreen off(64, 64, false);
    off.setDocument(doc);
    for (uint32_t n = 1; n <= 64; n += (n < 16 ? 1 : 8)) {
        const render::CapturedSurface c = off.capture(teapotOptions(doc, Spacing::Equal, AdaptiveMode::None, float(n)));
        std::set<float> us, vs, want;
        for (const auto& uv : c.mesh.uvs) us.insert(uv[0]), vs.insert(uv[1]);
        for (uint32_t i = 0; i <= n; ++i) want.insert(gpu::fixedTessPlace(i, n));
        EXPECT_EQ(us, want) << "level " << n;
        EXPECT_EQ(vs, want) << "level " << n;
        if (n == 3) {
            EXPECT_EQ(want.count(1.0f / 3.0f), 0u);  // not i / n: 16.16 rounding
        }
    }
}

// Every partitioning and adaptive mode: the capture holds the triangles the frame's statistics
// count, and the welded teapot has no crack.
TEST_F(RenderCapture, EveryPartitioningAndAdaptiveModeIsCapturedWholeAndWatertight) {
    const Document doc = teapot();
    Offscreen off(320, 240, false);
    off.setDocument(doc);
    const double tol = 1e-5 * modelSize(doc);
    struct Case {
        Spacing spacing;
        AdaptiveMode adaptive;
        float level;
    };
    const Case cases[] = {{Spacing::FractionalOdd, AdaptiveMode::None, 5.3f},
                          {Spacing::FractionalEven, AdaptiveMode::None, 6.7f},
                          {Spacing::Pow2, AdaptiveMode::None, 5.0f},
                          {Spacing::Equal, AdaptiveMode::Distance, 8.0f},
                          {Spacing::FractionalOdd, AdaptiveMode::ScreenSpace, 8.0f},
                          {Spacing::FractionalEven, AdaptiveMode::Orientation, 4.0f}};
    for (const Case& k : cases) {
        const render::RenderOptions o = teapotOptions(doc, k.spacing, k.adaptive, k.level);
        const Rendered frame = off.render(o);
        const render::CapturedSurface c = off.capture(o);
        const std::string what = std::string(spacingName(k.spacing)) + " " + std::string(adaptiveName(k.adaptive));
        EXPECT_EQ(c.gpuTriangles, frame.stats.triangles()) << what;
        EXPECT_EQ(c.mesh.indices.size() / 3, c.gpuTriangles - c.degenerate) << what;
        EXPECT_LT(c.degenerate, c.gpuTriangles / 20) << what;  // pole triangles only
        const auto open = openEdges(c.mesh);
        EXPECT_EQ(cracks(c.mesh, open, tol), 0u) << what;
        if (k.adaptive == AdaptiveMode::None) {  // uniform: 16 boundary curves of equal segments
            const int seg = k.spacing == Spacing::FractionalOdd ? 7 : k.spacing == Spacing::FractionalEven ? 8 : 8;
            EXPECT_EQ(open.size(), size_t(16 * seg)) << what;
        }
    }
}

// The teaspoon's tip edge doubles back: at level 16 two of its vertices lie 7e-7 apart, inside the
// weld's 1e-6 × size. Only collapsed edges (poles) weld within the tolerance, so no triangle folds
// onto its neighbour (before: one edge used by four triangles, two of them one triangle reversed).
TEST_F(RenderCapture, AShortEdgeIsNotWeldedLikeAPole) {
    const Document doc = loadDocument(dataDir() / "teaspoon.bpt");
    Offscreen off(320, 240, false);
    off.setDocument(doc);
    const render::CapturedSurface c = off.capture(render::optionsFromDocument(doc));  // as `export --as-displayed`
    EXPECT_EQ(c.mesh.indices.size() / 3, c.gpuTriangles - c.degenerate);
    // By position (a crease keeps two vertices at one position): no edge of more than two triangles.
    // (The tip's open edge keeps vertices closer than any crack tolerance apart, as the CPU export
    // does, so cracks() does not apply.)
    TriangleMesh byPosition = c.mesh;
    std::map<std::array<float, 3>, uint32_t> ids;
    for (uint32_t& i : byPosition.indices) i = ids.emplace(c.mesh.positions[i], uint32_t(ids.size())).first->second;
    EXPECT_FALSE(openEdges(byPosition).empty());
    EXPECT_GT(windingAgreement(c.mesh), 0.99);
}

TEST_F(RenderCapture, BezierTrianglesAreCapturedWeldedAndInTheirRanges) {
    const Document dome = makeTriangleDome(1.0, 0.5);
    Offscreen off(320, 240, false);
    off.setDocument(dome);
    render::RenderOptions o = plainOptions(dome, 6.0f, 320.0 / 240.0);
    o.tess.spacing = Spacing::FractionalOdd;
    o.tess.outer = {5.5f, 5.5f, 5.5f, 5.5f};
    o.tess.inner = {3.2f, 3.2f};
    const Rendered frame = off.render(o);
    const render::CapturedSurface c = off.capture(o);
    EXPECT_EQ(c.gpuTriangles, frame.stats.triangles());
    ASSERT_EQ(c.mesh.perTriangle.size(), dome.triangles.size());
    for (const MeshRange& r : c.mesh.perTriangle) EXPECT_GT(r.indexCount, 0u);
    const auto open = openEdges(c.mesh);
    EXPECT_EQ(open.size(), 6u * 7);  // the hexagon's six sides at 7 segments (5.5 -> odd 7)
    EXPECT_EQ(cracks(c.mesh, open, 1e-5), 0u);
    EXPECT_GT(windingAgreement(c.mesh), 0.99);
    for (const auto& p : c.mesh.positions) {  // on the paraboloid
        const double z = 0.5 * (1.0 - (double(p[0]) * p[0] + double(p[1]) * p[1]));
        EXPECT_NEAR(p[2], z, 1e-5);
    }
}

TEST_F(RenderCapture, CulledPatchesAreLeftOutAsOnScreen) {
    const Document doc = teapot();
    Offscreen off(320, 240, false);
    off.setDocument(doc);
    render::RenderOptions o = teapotOptions(doc, Spacing::Equal, AdaptiveMode::None, 8.0f);
    const render::CapturedSurface all = off.capture(o);
    o.tess.cullBackfaces = true;
    const Rendered frame = off.render(o);
    const render::CapturedSurface culled = off.capture(o);
    EXPECT_EQ(all.patchesCulled, 0u);
    EXPECT_GT(culled.patchesCulled, 0u);
    EXPECT_EQ(culled.patchesCulled, frame.stats.patchesCulled);
    EXPECT_EQ(culled.gpuTriangles, frame.stats.triangles());
    EXPECT_EQ(culled.gpuTriangles, all.gpuTriangles - culled.patchesCulled * 2 * 8 * 8);
}

}  // namespace
}  // namespace pw::test

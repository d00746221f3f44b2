// No cracks with mismatched adaptive levels, and a large batched model renders like its CPU
// pre-tessellated mesh drawn as plain triangles.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/construct/model_builders.hpp"
#include "core/gpu/patch_math.h"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/tess/tess_domain.hpp"
#include "core/tess/tess_presets.hpp"
#include "render/targets/png_writer.hpp"
#include "render_support.hpp"

namespace pw::test {
namespace {

class RenderSeams : public RenderTest {};

bool insideConvex(const std::array<glm::dvec2, 4>& q, glm::dvec2 p) {
    int sign = 0;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec2 a = q[size_t(i)], b = q[size_t((i + 1) % 4)];
        const double c = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        const int s = c > 0 ? 1 : -1;
        if (sign == 0)
            sign = s;
        else if (s != sign)
            return false;
    }
    return true;
}

// Counts background pixels inside the projected grid, shrunk by 10 % towards its centre (the wave
// bends the projected boundary), that the background around the model does not reach (4-connected):
// a crack between two patches is closed at their shared corners, while the space between a coarse
// outer boundary and its curve opens to the outside.
size_t holesInside(const Rendered& r, const render::RenderOptions& o, const Document& doc, int rows, int cols) {
    const ViewMatrices vm = viewMatrices(o.camera, double(r.image.w) / r.image.h);
    const int lc = 3 * cols + 1;
    const uint32_t corners[4] = {0u, uint32_t(3 * cols), uint32_t(3 * rows * lc + 3 * cols), uint32_t(3 * rows * lc)};
    std::array<glm::dvec2, 4> q;
    glm::dvec2 centre(0.0);
    for (int i = 0; i < 4; ++i) {
        q[size_t(i)] = *projectToPixel(vm, doc.points[corners[i]], int(r.image.w), int(r.image.h));
        centre += q[size_t(i)] * 0.25;
    }
    for (auto& p : q) p = centre + (p - centre) * 0.90;
    const int W = int(r.image.w), H = int(r.image.h);
    const auto background = [&](int x, int y) { return sameColor(r.image.at(x, y), doc.display.background, 6); };
    std::vector<uint8_t> outside(size_t(W) * H, 0);
    std::vector<std::pair<int, int>> stack;
    const auto reach = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= W || y >= H || outside[size_t(y) * W + x] || !background(x, y)) return;
        outside[size_t(y) * W + x] = 1;
        stack.push_back({x, y});
    };
    for (int x = 0; x < W; ++x) reach(x, 0), reach(x, H - 1);
    for (int y = 0; y < H; ++y) reach(0, y), reach(W - 1, y);
    while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        reach(x + 1, y), reach(x - 1, y), reach(x, y + 1), reach(x, y - 1);
    }
    size_t holes = 0;
    std::vector<uint8_t> marked = r.image.rgba;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            if (insideConvex(q, {x + 0.5, y + 0.5}) && background(x, y) && !outside[size_t(y) * W + x]) {
                ++holes;
                uint8_t* m = &marked[(size_t(y) * r.image.w + size_t(x)) * 4];
                m[0] = 255, m[1] = 0, m[2] = 255;
            }
    if (holes && std::getenv("PATCHWORK_TEST_DUMP"))  // look at the holes (magenta)
        render::writePng(std::getenv("PATCHWORK_TEST_DUMP"), r.image.w, r.image.h, marked);
    return holes;
}

TEST_F(RenderSeams, ScreenSpaceAdaptiveGridHasNoCracks) {
    const int rows = 6, cols = 6;
    const Document doc = makePatchGrid(rows, cols);
    Offscreen off(640, 480, false);  // single sample: a crack would show as a background pixel
    off.setDocument(doc);
    for (Spacing s : {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2}) {
        render::RenderOptions o = plainOptions(doc, 16, 640.0 / 480.0, "top");
        o.camera.pitchDeg = 55;  // tilted: near patches get higher levels than far ones
        o.camera.distance *= 0.8;
        o.tess.adaptive = AdaptiveMode::ScreenSpace;
        o.tess.targetPixels = 6.0f;
        o.tess.spacing = s;
        const Rendered r = off.render(o);
        EXPECT_EQ(holesInside(r, o, doc, rows, cols), 0u) << spacingName(s);
        EXPECT_GT(r.stats.triangles(), 0u);
    }
}

// A 6 x 6 grid seen from above, tilted 50°: the near patches nearer the eye than the far ones;
// single sample, so a crack shows as a background pixel.
struct TiltedGrid {
    static constexpr int rows = 6, cols = 6;
    const Document doc = makePatchGrid(rows, cols);
    Offscreen off{640, 480, false};
    render::RenderOptions o;
    TiltedGrid() {
        off.setDocument(doc);
        o = plainOptions(doc, 16, 640.0 / 480.0, "top");
        o.camera.pitchDeg = 50;
    }
};

TEST_F(RenderSeams, DistanceAdaptiveGridHasNoCracks) {
    TiltedGrid g;
    const Document& doc = g.doc;
    Offscreen& off = g.off;
    render::RenderOptions& o = g.o;
    const int rows = TiltedGrid::rows, cols = TiltedGrid::cols;
    o.tess.adaptive = AdaptiveMode::Distance;
    o.tess.distanceNear = float(o.camera.distance * 0.7);
    o.tess.distanceFar = float(o.camera.distance * 1.5);
    o.tess.spacing = Spacing::FractionalOdd;
    const Rendered r = off.render(o);
    EXPECT_EQ(holesInside(r, o, doc, rows, cols), 0u);
}

// The level belongs to the edge (core/tess/edge_levels.hpp): patches with their own levels (2 next to
// 16, and next to patches without) meet without a crack under every partitioning and adaptive mode.
TEST_F(RenderSeams, MixedPerPatchLevelsHaveNoCracks) {
    const int rows = 4, cols = 4;
    Document doc = makePatchGrid(rows, cols);
    for (size_t p = 0; p < doc.patches.size(); ++p) {
        const size_t r = p / size_t(cols), c = p % size_t(cols);
        if ((r + c) % 3 == 0)
            doc.patches[p].tessOverride = std::array<float, 6>{2, 2, 2, 2, 2, 2};
        else if ((r + c) % 3 == 1)
            doc.patches[p].tessOverride = std::array<float, 6>{16, 5, 16, 5, 9, 9};
    }
    Offscreen off(640, 480, false);
    off.setDocument(doc);
    for (AdaptiveMode a : {AdaptiveMode::None, AdaptiveMode::Distance, AdaptiveMode::ScreenSpace, AdaptiveMode::Orientation})
        for (Spacing s : {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2}) {
            render::RenderOptions o = plainOptions(doc, 7, 640.0 / 480.0, "top");
            o.camera.pitchDeg = 55;
            o.camera.distance *= 0.8;
            o.tess.adaptive = a;
            o.tess.targetPixels = 10.0f;
            o.tess.distanceNear = float(o.camera.distance * 0.7);
            o.tess.distanceFar = float(o.camera.distance * 1.5);
            o.tess.spacing = s;
            const Rendered r = off.render(o);
            EXPECT_EQ(holesInside(r, o, doc, rows, cols), 0u) << adaptiveName(a) << " " << spacingName(s);
        }
}

// Distance measured where the notes measure it (issue 41): the first notes' formula from the
// patch centre gives every level of a patch the one value 64 saturate((d1 - d) / (d1 - d0)) at the
// centre of its control points and culls patches centred beyond d1; the terrain notes' variant takes
// each edge from its midpoint and the inner levels from the centre, on the pow2 curve
// 2^lerp(e0, e1, s) under fractional_even. The GPU's triangle count is the count model's sum over
// the patches of the levels computed here, patch by patch; the crack-free per-edge rule differs.
TEST_F(RenderSeams, DistanceFromTheCentreOrTheEdgesIsTheNotesFormula) {
    TiltedGrid g;
    const Document& doc = g.doc;
    Offscreen& off = g.off;
    const render::RenderOptions& o = g.o;
    const int rows = TiltedGrid::rows, cols = TiltedGrid::cols;
    const glm::vec3 eye = viewMatrices(o.camera, 640.0 / 480.0).eye;
    const auto net = [&](size_t p, int slot) { return glm::vec3(doc.points[doc.patches[p].idx[size_t(slot)]]); };
    const auto centreOf = [&](size_t p) {
        glm::vec3 c(0.0f);
        for (int k = 0; k < 16; ++k) c += net(p, k);
        return c / 16.0f;
    };
    const auto expected = [&](const TessSettings& t, bool perEdge) {
        const glm::vec2 exps(t.distanceExponents[0], t.distanceExponents[1]);
        const auto level = [&](const glm::vec3& at) {
            return std::clamp(
                gpu::distanceLevel(glm::distance(eye, at), 64.0f, t.distanceNear, t.distanceFar, uint32_t(t.distanceCurve), exps), 1.0f,
                64.0f);
        };
        uint64_t triangles = 0, culled = 0;
        for (size_t p = 0; p < doc.patches.size(); ++p) {
            if (t.cullFar && glm::distance(eye, centreOf(p)) >= t.distanceFar) {
                ++culled;
                continue;
            }
            const float c = level(centreOf(p));
            DomainLevels l{{c, c, c, c}, {c, c}};
            const int ends[4][2] = {{0, 12}, {0, 3}, {3, 15}, {12, 15}};  // edges u0, v0, u1, v1
            if (perEdge)
                for (int e = 0; e < 4; ++e) l.outer[size_t(e)] = level(0.5f * (net(p, ends[e][0]) + net(p, ends[e][1])));
            triangles += expectedDomainCounts(DomainKind::Quad, l, t.spacing).primitives;
        }
        return std::pair(triangles, culled);
    };
    const double d = glm::distance(eye, centreOf(0));
    // The first notes' formula from the centre, its distances scaled to this camera.
    render::RenderOptions notes = o;
    applyNotesDistanceFormula(notes.tess);
    notes.tess.distanceNear = float(d * 0.5);
    notes.tess.distanceFar = float(d * 1.05);
    const auto [want, wantCulled] = expected(notes.tess, false);
    ASSERT_GT(wantCulled, 0u);
    ASSERT_LT(wantCulled, doc.patches.size());
    const Rendered centre = off.render(notes);
    EXPECT_EQ(centre.stats.triangles(), want);
    EXPECT_EQ(centre.stats.patchesCulled, wantCulled);
    // The same formula per edge (crack-free): other levels, so another count.
    render::RenderOptions edges = notes;
    edges.tess.distanceFrom = DistanceFrom::Edges;
    const Rendered perEdge = off.render(edges);
    EXPECT_NE(perEdge.stats.triangles(), want);
    // The terrain notes' variant: edges from their midpoints, inner from the centre, pow2 curve,
    // fractional_even (exponents chosen so the levels stay under 64 here).
    render::RenderOptions terrain = o;
    applyNotesTerrainFormula(terrain.tess);
    terrain.tess.distanceNear = float(d * 0.5);
    terrain.tess.distanceFar = float(d * 1.5);
    terrain.tess.distanceExponents = {5.5f, 1.5f};
    const auto [wantTerrain, none] = expected(terrain.tess, true);
    EXPECT_EQ(none, 0u);
    const Rendered t = off.render(terrain);
    EXPECT_EQ(t.stats.triangles(), wantTerrain);
    EXPECT_EQ(holesInside(t, terrain, doc, rows, cols), 0u);  // the edges agree: no crack
}

TEST_F(RenderSeams, BatchedLargeModelMatchesPlainMesh) {
    const Document doc = makePatchGrid(16, 16);
    Offscreen off(640, 480);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 16, 640.0 / 480.0, "iso");
    const Rendered tess = off.render(o);
    EXPECT_EQ(tess.stats.triangles(), 256u * 2 * 16 * 16);
    EXPECT_GT(tess.stats.draws, 20u);  // batched: 12 patches per draw at level 16

    off.setPlainMesh(tessellateDocument(doc, 16));
    o.plainMesh = true;
    const Rendered plain = off.render(o);
    EXPECT_EQ(plain.stats.triangles(), tess.stats.triangles());
    const size_t n = size_t(tess.image.w) * tess.image.h;
    EXPECT_LT(countDifferent(tess.image, plain.image, 24), n / 200);  // < 0.5 % of the pixels
    EXPECT_LT(countDifferent(tess.image, plain.image, 6), n / 50);
}

}  // namespace
}  // namespace pw::test

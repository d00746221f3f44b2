// Pipeline statistics of the surface pass: a single patch at uniform level n gives 2n² triangles;
// per-edge levels give what the quad-domain rules predict (independent CPU formula below);
// back-facing and off-screen patches are culled to 0 evaluations (whole windows on the CPU, a wholly
// visible model without the per-patch test); batching bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/construct/model_builders.hpp"
#include "core/tess/tess_levels.hpp"
#include "render_support.hpp"

namespace pw::test {
namespace {

constexpr uint32_t W = 256, H = 256;

// Segments a requested level becomes (Vulkan spec, "Tessellator Spacing"), written independently
// of core/tess/tess_levels.cpp.
int segments(float f, Spacing s) {
    switch (s) {
        case Spacing::Equal:
            return int(std::ceil(std::clamp(f, 1.0f, 64.0f)));
        case Spacing::FractionalOdd: {
            int n = int(std::ceil(std::clamp(f, 1.0f, 63.0f)));
            return n % 2 ? n : n + 1;
        }
        case Spacing::FractionalEven: {
            int n = int(std::ceil(std::clamp(f, 2.0f, 64.0f)));
            return n % 2 ? n + 1 : n;
        }
        case Spacing::Pow2: {
            int n = 1;
            while (n < std::ceil(f)) n *= 2;
            return n;
        }
    }
    return 0;
}

// Triangles of the quad domain: an inner grid of (i0-2) x (i1-2) quads, and a ring strip between
// every outer edge (o segments) and the facing inner edge (m segments) with o + m triangles. An
// inner level of 1 is treated as 1+ε (2 segments, 3 for fractional_odd) unless all levels are 1.
long quadTriangles(std::array<float, 4> outer, std::array<float, 2> inner, Spacing s) {
    const Spacing rs = s == Spacing::Pow2 ? Spacing::Equal : s;
    std::array<int, 4> o;
    std::array<int, 2> in;
    for (int e = 0; e < 4; ++e) o[size_t(e)] = segments(s == Spacing::Pow2 ? float(segments(outer[size_t(e)], s)) : outer[size_t(e)], rs);
    for (int k = 0; k < 2; ++k) in[size_t(k)] = segments(s == Spacing::Pow2 ? float(segments(inner[size_t(k)], s)) : inner[size_t(k)], rs);
    const bool allOne = o == std::array<int, 4>{1, 1, 1, 1} && in == std::array<int, 2>{1, 1};
    if (allOne) return 2;
    for (int& i : in)
        if (i == 1) i = rs == Spacing::FractionalOdd ? 3 : 2;
    const long mu = in[0] - 2, mv = in[1] - 2;  // inner edge segments along u and along v
    // outer[0], outer[2] run along v (edges u = 0, 1); outer[1], outer[3] along u.
    return 2 * mu * mv + (o[0] + mv) + (o[2] + mv) + (o[1] + mu) + (o[3] + mu);
}

class RenderStats : public RenderTest {};

render::RenderOptions flatView(const Document& doc, const char* view) {
    render::RenderOptions o = plainOptions(doc, 1, double(W) / H, view);
    return o;
}

TEST(QuadFormula, HandComputedCases) {
    EXPECT_EQ(quadTriangles({4, 4, 4, 4}, {4, 4}, Spacing::Equal), 32);
    EXPECT_EQ(quadTriangles({1, 1, 1, 1}, {1, 1}, Spacing::Equal), 2);
    // inner 2x2: a single centre vertex, a fan of o triangles per edge
    EXPECT_EQ(quadTriangles({1, 2, 3, 4}, {2, 2}, Spacing::Equal), 10);
    // inner 3x4: 1x2 inner quads (4 triangles), rings (o0+2)+(o2+2)+(o1+1)+(o3+1)
    EXPECT_EQ(quadTriangles({1, 1, 1, 1}, {3, 4}, Spacing::Equal), 4 + 3 + 3 + 2 + 2);
}

TEST_F(RenderStats, SinglePatchUniformLevelGivesTwoNSquaredTriangles) {
    const Document doc = flatPatch();
    Offscreen off(W, H);
    off.setDocument(doc);
    for (int n : {1, 2, 3, 5, 8, 16, 33, 64}) {
        render::RenderOptions o = flatView(doc, "top");
        o.tess.outer = {float(n), float(n), float(n), float(n)};
        o.tess.inner = {float(n), float(n)};
        const Rendered r = off.render(o);
        ASSERT_TRUE(r.stats.pipelineStatsValid);
        EXPECT_EQ(r.stats.triangles(), uint64_t(2 * n * n)) << "level " << n;
        EXPECT_EQ(r.stats.tcsPatches, 1u);
        EXPECT_GT(r.stats.tesInvocations, 0u);
    }
}

TEST_F(RenderStats, PerEdgeLevelsGiveTheCountsTheSpacingRulesPredict) {
    const Document doc = flatPatch();
    Offscreen off(W, H);
    off.setDocument(doc);
    struct Case {
        std::array<float, 4> outer;
        std::array<float, 2> inner;
        Spacing spacing;
    };
    const Case cases[] = {
        {{1, 2, 3, 4}, {5, 6}, Spacing::Equal},
        {{7, 3, 5, 2}, {4, 4}, Spacing::Equal},
        {{1, 1, 1, 1}, {1, 1}, Spacing::Equal},
        {{2, 3, 4, 5}, {1, 1}, Spacing::Equal},
        {{2.5f, 3.2f, 7.9f, 1.0f}, {5.5f, 2.1f}, Spacing::Equal},
        {{4.5f, 4.5f, 4.5f, 4.5f}, {4.5f, 4.5f}, Spacing::FractionalOdd},
        {{2, 3, 6, 9}, {3, 8}, Spacing::FractionalOdd},
        {{3, 3, 3, 3}, {3, 3}, Spacing::FractionalEven},
        {{1, 5, 2, 7}, {3.5f, 6.2f}, Spacing::FractionalEven},
        {{5, 5, 5, 5}, {5, 5}, Spacing::Pow2},
        {{3, 9, 17, 2}, {6, 12}, Spacing::Pow2},
        {{64, 64, 64, 64}, {64, 64}, Spacing::Equal},
    };
    for (const Case& c : cases) {
        render::RenderOptions o = flatView(doc, "top");
        o.tess.outer = c.outer;
        o.tess.inner = c.inner;
        o.tess.spacing = c.spacing;
        const Rendered r = off.render(o);
        EXPECT_EQ(long(r.stats.triangles()), quadTriangles(c.outer, c.inner, c.spacing))
            << spacingName(c.spacing) << " outer " << c.outer[0] << "," << c.outer[1] << "," << c.outer[2] << "," << c.outer[3] << " inner "
            << c.inner[0] << "," << c.inner[1];
    }
}

TEST_F(RenderStats, PerPatchOverrideWinsOverUniformLevels) {
    Document doc = flatPatch();
    doc.patches[0].tessOverride = std::array<float, 6>{1, 2, 3, 4, 5, 6};
    Offscreen off(W, H);
    off.setDocument(doc);
    render::RenderOptions o = flatView(doc, "top");
    o.tess.outer = {16, 16, 16, 16};
    o.tess.inner = {16, 16};
    EXPECT_EQ(long(off.render(o).stats.triangles()), quadTriangles({1, 2, 3, 4}, {5, 6}, Spacing::Equal));
    o.tess.adaptive = AdaptiveMode::ScreenSpace;  // overrides win over adaptive levels too
    EXPECT_EQ(long(off.render(o).stats.triangles()), quadTriangles({1, 2, 3, 4}, {5, 6}, Spacing::Equal));
}

// A per-patch level edit (the inspector's sliders) rewrites the levels alone: the frame after it is
// the frame a fresh upload of the edited document gives, the neighbour's shared edge raised too.
TEST_F(RenderStats, LevelEditsRewriteOnlyTheLevelsWithTheSameFrame) {
    Document doc = makePatchGrid(3, 3);
    Offscreen off(W, H, false);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 4.0f, double(W) / H);
    const Rendered before = off.render(o);
    EXPECT_EQ(long(before.stats.triangles()), 9 * quadTriangles({4, 4, 4, 4}, {4, 4}, Spacing::Equal));
    doc.patches[4].tessOverride = std::array<float, 6>{9, 9, 9, 9, 9, 9};
    off.updateLevels(doc);
    const Rendered edited = off.render(o);
    off.setDocument(doc);
    const Rendered fresh = off.render(o);
    EXPECT_GT(edited.stats.triangles(), before.stats.triangles());
    EXPECT_EQ(edited.stats.triangles(), fresh.stats.triangles());
    EXPECT_EQ(countDifferent(edited.image, fresh.image), 0u);
    doc.patches[4].tessOverride.reset();  // and back
    off.updateLevels(doc);
    EXPECT_EQ(off.render(o).stats.triangles(), before.stats.triangles());
}

TEST_F(RenderStats, BackFacingPatchIsCulledWithZeroEvaluations) {
    const Document doc = flatPatch();
    Offscreen off(W, H);
    off.setDocument(doc);
    render::RenderOptions o = flatView(doc, "bottom");  // looking at the back (normal +z)
    o.tess.outer = {8, 8, 8, 8};
    o.tess.inner = {8, 8};
    o.tess.cullBackfaces = true;
    const Rendered culled = off.render(o);
    EXPECT_EQ(culled.stats.tesInvocations, 0u);
    EXPECT_EQ(culled.stats.triangles(), 0u);
    EXPECT_EQ(culled.stats.patchesCulled, 1u);

    o.tess.cullBackfaces = false;
    const Rendered drawn = off.render(o);
    EXPECT_EQ(drawn.stats.triangles(), 128u);
    EXPECT_EQ(drawn.stats.patchesCulled, 0u);

    // Seen from the front, culling keeps it; at a grazing oblique view too.
    render::RenderOptions front = flatView(doc, "top");
    front.tess = o.tess;
    front.tess.cullBackfaces = true;
    EXPECT_EQ(off.render(front).stats.triangles(), 128u);
    front.camera.pitchDeg = 10;
    EXPECT_EQ(off.render(front).stats.triangles(), 128u);
}

TEST_F(RenderStats, CurvedPatchesOnBothSidesOfTheSilhouetteAreKept) {
    // Teapot from the side with back-face culling: some patches culled, none of the visible ones.
    const Document doc = makePatchGrid(4, 4);
    Offscreen off(W, H);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 4, 1.0, "top");
    o.tess.cullBackfaces = true;
    const Rendered r = off.render(o);
    EXPECT_EQ(r.stats.patchesCulled, 0u);
    EXPECT_EQ(r.stats.triangles(), 16u * 32u);
    render::RenderOptions b = plainOptions(doc, 4, 1.0, "bottom");
    b.tess.cullBackfaces = true;
    const Rendered rb = off.render(b);
    EXPECT_EQ(rb.stats.patchesCulled, 16u);
    EXPECT_EQ(rb.stats.tesInvocations, 0u);
    // Issue 19: the wireframe and normals overlays run the same control shader; they counted the
    // culled patches again ("Patches 2 (culled 4)").
    b.display.showWireframe = true;
    b.display.showNormals = true;
    const Rendered overlays = off.render(b);
    EXPECT_EQ(overlays.stats.patches, 16u);
    EXPECT_EQ(overlays.stats.patchesCulled, 16u);
}

TEST_F(RenderStats, OffscreenPatchIsCulled) {
    const Document doc = flatPatch();
    Offscreen off(W, H);
    off.setDocument(doc);
    render::RenderOptions o = flatView(doc, "top");
    o.tess.outer = {8, 8, 8, 8};
    o.tess.inner = {8, 8};
    o.camera.target = {100.0, 100.0, 0.0};
    o.tess.cullOffscreen = true;
    const Rendered r = off.render(o);
    EXPECT_EQ(r.stats.tesInvocations, 0u);
    EXPECT_EQ(r.stats.patchesCulled, 1u);
    o.tess.cullOffscreen = false;
    EXPECT_EQ(off.render(o).stats.triangles(), 128u);
}

// Off-screen culling decided on the CPU first (render/scene/view_culling.hpp): a model wholly inside
// the frustum can lose no patch, so the frame skips the per-patch test (the control shader without
// it) and draws the same picture; aimed at its corner, whole windows outside are culled before the
// control shader, and a debug camera still sends every patch to it to be greyed.
TEST_F(RenderStats, OffscreenCullingSkipsTheTestWhereNothingCanBeCulledAndCullsWholeWindowsOnTheCpu) {
    const Document doc = makePatchGrid(8, 8);
    Offscreen off(W, H);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 4.0f, 1.0);
    o.tess.cullOffscreen = true;
    const Rendered framed = off.render(o);
    EXPECT_TRUE(framed.stats.cullTestSkipped);
    EXPECT_EQ(framed.stats.patchesCulled, 0u);
    render::RenderOptions all = o;
    all.tess.cullOffscreen = false;
    const Rendered drawn = off.render(all);
    EXPECT_FALSE(drawn.stats.cullTestSkipped);
    EXPECT_EQ(framed.stats.triangles(), drawn.stats.triangles());
    EXPECT_EQ(countDifferent(framed.image, drawn.image), 0u);
    // The camera's target moved to the grid's corner: part of it off screen. The windows wholly
    // outside are culled before the control shader (counted as culled, never reaching it), those
    // wholly inside drawn without the test, the rest tested patch by patch: the picture of drawing
    // them all.
    const Bounds b = computeBounds(doc.points);
    o.camera.target = {b.max.x, b.max.y, b.max.z};
    all.camera = o.camera;
    const Rendered corner = off.render(o), cornerAll = off.render(all);
    EXPECT_FALSE(corner.stats.cullTestSkipped);
    EXPECT_GT(corner.stats.patchesCulled, 0u);
    EXPECT_LT(corner.stats.triangles(), framed.stats.triangles());
    EXPECT_EQ(countDifferent(corner.image, cornerAll.image), 0u);
    render::RenderOptions wired = o, wiredAll = all;  // the wire overlay: one draw in window order, culled windows left out
    wired.display.showWireframe = wiredAll.display.showWireframe = true;
    EXPECT_EQ(countDifferent(off.render(wired).image, off.render(wiredAll).image), 0u);
    if (corner.stats.pipelineStatsValid) {
        EXPECT_EQ(corner.stats.tcsPatches + corner.stats.patchesCulled, 64u);
    }
    // A debug camera greys culled patches in place instead: every patch reaches the control shader.
    render::RenderOptions debug = o;
    debug.lodCamera = o.camera;
    debug.camera.distance *= 3.0;
    const Rendered greyed = off.render(debug);
    if (greyed.stats.pipelineStatsValid) {
        EXPECT_EQ(greyed.stats.tcsPatches, 64u);
    }
    EXPECT_EQ(greyed.stats.patchesCulled, corner.stats.patchesCulled);
}

TEST(Batching, PatchesPerDrawKeepsEvaluationVerticesBounded) {
    for (int l = 1; l <= 64; ++l) {
        const uint32_t n = patchesPerDraw(l);
        EXPECT_GE(n, 1u);
        if (n > 1) {
            EXPECT_LE(n * uint32_t((l + 2) * (l + 2)), 4096u);
        }
    }
    EXPECT_EQ(patchesPerDraw(16), 12u);
    EXPECT_EQ(patchesPerDraw(64), 1u);
}

TEST(Batching, RoundedSegmentsFollowDesignRules) {
    EXPECT_EQ(roundedSegments(4.2f, Spacing::Equal), 5);
    EXPECT_EQ(roundedSegments(4.2f, Spacing::FractionalOdd), 5);
    EXPECT_EQ(roundedSegments(5.5f, Spacing::FractionalOdd), 7);
    EXPECT_EQ(roundedSegments(1.0f, Spacing::FractionalEven), 2);
    EXPECT_EQ(roundedSegments(4.5f, Spacing::FractionalEven), 6);
    EXPECT_EQ(roundedSegments(5.0f, Spacing::Pow2), 8);
    EXPECT_EQ(roundedSegments(64.0f, Spacing::Pow2), 64);
    EXPECT_EQ(roundedSegments(64.0f, Spacing::FractionalOdd), 63);
}

TEST_F(RenderStats, LargeGridUsesSeveralDraws) {
    const Document doc = makePatchGrid(8, 8);
    Offscreen off(W, H);
    off.setDocument(doc);
    const Rendered r = off.render(plainOptions(doc, 16, 1.0, "top"));
    EXPECT_EQ(r.stats.triangles(), 64u * 2 * 16 * 16);
    EXPECT_EQ(r.stats.draws, (64u + 11u) / 12u);
}

}  // namespace
}  // namespace pw::test

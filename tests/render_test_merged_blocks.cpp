// Merged blocks (render/scene/merged_blocks.hpp): windows of a spline net that get one level (any
// level on lavapipe, powers of two elsewhere) are drawn several to a patch. The plan takes only what cannot change the picture, and the
// frames drawn that way have the same triangles and, but for the diagonals the tessellator picks
// inside a block, the same pixels as one window a patch, with no hole anywhere.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/construct/model_builders.hpp"
#include "core/ops/net_ops.hpp"
#include "render/scene/merged_blocks.hpp"
#include "render/scene/surface_scene.hpp"
#include "render_support.hpp"

namespace pw::test {
namespace {

constexpr uint32_t W = 480, H = 320;

Document splineNet(uint32_t points, NetShape shape, Basis basis = Basis::BSpline) {
    Document doc;
    addNetSurface(doc, points, points, shape, basis, Vec3(0.0), 2.0, true);
    for (Vec3& p : doc.points) p.z += 0.15 * std::sin(3.0 * p.x) * std::cos(2.0 * p.y);  // not flat: diagonals show in shading
    return doc;
}

ViewMatrices viewOf(const Document& doc) {
    return viewMatrices(frameBounds(doc.camera, computeBounds(doc.points), double(W) / H), double(W) / H);
}

// Every window a block draws is covered by exactly one block, and the per-window marks agree.
void expectBlocksCover(const render::SurfaceScene& s, const render::MergedBlocks& m) {
    std::vector<int> covered(s.windowCount, 0);
    for (const glm::uvec4& b : m.blocks) {
        const uint32_t bu = b.z & 255u, bv = b.z >> 8u;
        EXPECT_TRUE((bu == 4 && bv == 4) || (bu == 2 && bv == 2) || (bu == 2 && bv == 1) || (bu == 1 && bv == 2)) << bu << "x" << bv;
        for (uint32_t r = 0; r < bv; ++r)
            for (uint32_t c = 0; c < bu; ++c) ++covered[b.x + r * b.y + c];
    }
    uint32_t total = 0;
    for (uint32_t w = 0; w < s.windowCount; ++w) {
        EXPECT_LE(covered[w], 1) << w;
        EXPECT_EQ(covered[w] == 1, m.merged[w] == 1) << w;
        total += uint32_t(covered[w]);
    }
    EXPECT_EQ(total, m.windows);
}

class MergedBlocks : public RenderTest {};

TEST_F(MergedBlocks, PlanTakesOnlyOneLevelOfSplineNetWindowsInView) {
    const Document doc = splineNet(11, NetShape::Flat);  // 8 x 8 windows
    const render::SurfaceScene s = render::uploadSurfaceScene(sharedDevice(), doc);
    ASSERT_EQ(s.windowCount, 64u);
    ASSERT_EQ(s.nets.size(), 1u);
    EXPECT_EQ(s.nets[0].rows, 8u);
    EXPECT_EQ(s.nets[0].cols, 8u);
    TessSettings ts;
    const ViewMatrices vm = viewOf(doc);

    const auto both = [](uint8_t n) { return render::DirectionLevels{n, n}; };
    std::vector<render::DirectionLevels> level(64, both(2));
    render::MergedBlocks m = render::planMergedBlocks(s, level, ts, vm, 64.0f, false);
    EXPECT_EQ(m.windows, 64u);
    EXPECT_EQ(m.blocks.size(), 4u);  // four tiles of 4 x 4
    expectBlocksCover(s, m);

    // One window that may not be merged (an uncertain level): its tile falls back to quarters,
    // and its quarter to the row of two that does not hold it.
    level[0] = {};
    m = render::planMergedBlocks(s, level, ts, vm, 64.0f, false);
    EXPECT_EQ(m.windows, 62u);
    EXPECT_EQ(m.merged[0], 0);
    EXPECT_EQ(m.merged[1], 0);
    expectBlocksCover(s, m);

    // Level 1: no strips (one inner level 1 beside a larger one is rounded up to 2 by the spec).
    std::fill(level.begin(), level.end(), both(1));
    level[0] = {};
    m = render::planMergedBlocks(s, level, ts, vm, 64.0f, false);
    EXPECT_EQ(m.windows, 60u);
    expectBlocksCover(s, m);

    // Levels that are not powers of two: the tessellator places i / (B n) otherwise than i' / n.
    // A fixed-point tessellator (lavapipe) is placed as core/gpu/tess_place.h says: those merge too,
    // 4 x 4 at 3 (12), 2 x 2 at 5 (10) and 7 (14).
    std::fill(level.begin(), level.end(), both(3));
    EXPECT_EQ(render::planMergedBlocks(s, level, ts, vm, 64.0f, false).windows, 0u);
    m = render::planMergedBlocks(s, level, ts, vm, 64.0f, true);
    EXPECT_EQ(m.windows, 64u);
    EXPECT_EQ(m.blocks.size(), 4u);
    expectBlocksCover(s, m);
    for (const uint8_t n : {uint8_t(5), uint8_t(7)}) {
        std::fill(level.begin(), level.end(), both(n));
        m = render::planMergedBlocks(s, level, ts, vm, 64.0f, true);
        EXPECT_EQ(m.windows, 64u) << int(n);
        EXPECT_EQ(m.blocks.size(), 16u) << int(n);
    }
    std::fill(level.begin(), level.end(), both(9));  // 2 x 9 is past 16
    EXPECT_EQ(render::planMergedBlocks(s, level, ts, vm, 64.0f, true).windows, 0u);
    // Levels that differ between the directions: 2 along u, 3 along v make blocks at 8 and 12.
    std::fill(level.begin(), level.end(), render::DirectionLevels{2, 3});
    m = render::planMergedBlocks(s, level, ts, vm, 64.0f, true);
    EXPECT_EQ(m.windows, 64u);
    EXPECT_EQ(m.blocks.size(), 4u);
    EXPECT_EQ(m.blocks[0].w, 2u + 256u * 3u);
    // 1 along one direction only: the spec rounds that inner level up to 2 for the window alone.
    std::fill(level.begin(), level.end(), render::DirectionLevels{1, 2});
    EXPECT_EQ(render::planMergedBlocks(s, level, ts, vm, 64.0f, false).windows, 0u);
    // 4 along u, 8 along v: 4 x 4 is past 16 along v, 2 x 2 fits.
    std::fill(level.begin(), level.end(), render::DirectionLevels{4, 8});
    m = render::planMergedBlocks(s, level, ts, vm, 64.0f, false);
    EXPECT_EQ(m.windows, 64u);
    EXPECT_EQ(m.blocks.size(), 16u);
    // 4 x 8 is more than a merged patch's largest level (16): 2 x 2 blocks only; 16 a window: none.
    std::fill(level.begin(), level.end(), both(8));
    m = render::planMergedBlocks(s, level, ts, vm, 64.0f, false);
    EXPECT_EQ(m.windows, 64u);
    EXPECT_EQ(m.blocks.size(), 16u);
    std::fill(level.begin(), level.end(), both(16));
    EXPECT_EQ(render::planMergedBlocks(s, level, ts, vm, 64.0f, false).windows, 0u);
    // Fractional spacing has no uniform grid; back-face culling is the control shader's.
    std::fill(level.begin(), level.end(), both(2));
    ts.spacing = Spacing::FractionalOdd;
    EXPECT_EQ(render::planMergedBlocks(s, level, ts, vm, 64.0f, false).windows, 0u);
    ts.spacing = Spacing::Pow2;
    EXPECT_EQ(render::planMergedBlocks(s, level, ts, vm, 64.0f, false).windows, 64u);
    ts.cullBackfaces = true;
    EXPECT_EQ(render::planMergedBlocks(s, level, ts, vm, 64.0f, false).windows, 0u);
    ts.cullBackfaces = false;
    // Looking away: every window would be culled off screen, so none is merged.
    Camera away = frameBounds(doc.camera, computeBounds(doc.points), double(W) / H);
    away.target = {1000.0, 1000.0, 1000.0};
    away.distance = 1.0;
    EXPECT_EQ(render::planMergedBlocks(s, level, ts, viewMatrices(away, double(W) / H), 64.0f, false).windows, 0u);
    ts.cullOffscreen = false;
    EXPECT_EQ(render::planMergedBlocks(s, level, ts, viewMatrices(away, double(W) / H), 64.0f, false).windows, 64u);

    // A Bézier net may have creases between its windows: never merged.
    const Document bez = splineNet(13, NetShape::Flat, Basis::Bezier);
    const render::SurfaceScene sb = render::uploadSurfaceScene(sharedDevice(), bez);
    EXPECT_EQ(render::planMergedBlocks(sb, std::vector<render::DirectionLevels>(sb.windowCount, {2, 2}), TessSettings{}, viewOf(bez), 64.0f,
                                       false)
                  .windows,
              0u);
}

// Pixels of background colour whose four neighbours are all surface: a crack between patches.
size_t holes(const Image& im, const std::array<float, 3>& bg) {
    size_t n = 0;
    for (uint32_t y = 1; y + 1 < im.h; ++y)
        for (uint32_t x = 1; x + 1 < im.w; ++x) {
            if (!sameColor(im.at(int(x), int(y)), bg, 1)) continue;
            bool enclosed = true;
            for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
                enclosed = enclosed && !sameColor(im.at(int(x) + dx, int(y) + dy), bg, 1);
            n += enclosed ? 1 : 0;
        }
    return n;
}

TEST_F(MergedBlocks, DrawTheSameSurfaceAsOneWindowAPatch) {
    Offscreen off(W, H, false);
    int mergedFrames = 0;
    for (const NetShape shape : {NetShape::Flat, NetShape::Torus}) {
        const Document doc = splineNet(shape == NetShape::Torus ? 48 : 35, shape);
        off.setDocument(doc);
        for (const float px : {0.0f, -3.0f, -5.0f, -6.0f, 24.0f, 12.0f}) {  // 0: uniform level 2, -n: uniform n, else screen-adaptive at px
            render::RenderOptions o = plainOptions(doc, px < 0.0f ? -px : 2.0f, double(W) / H);
            if (px > 0.0f) {
                o.tess.adaptive = AdaptiveMode::ScreenSpace;
                o.tess.targetPixels = px;
            }
            o.mergeWindows = render::MergeWindows::Never;
            const Rendered each = off.render(o);
            o.mergeWindows = render::MergeWindows::Always;
            const Rendered merged = off.render(o);
            o.mergeWindows = render::MergeWindows::Auto;  // lavapipe is a CPU renderer: merges
            const Rendered autoOn = off.render(o);
            const std::string what = std::string(shape == NetShape::Torus ? "torus" : "flat") + " at " + std::to_string(px) + " px";
            EXPECT_EQ(each.stats.mergedWindows, 0u) << what;
            EXPECT_EQ(merged.stats.triangles(), each.stats.triangles()) << what;
            EXPECT_EQ(autoOn.stats.mergedWindows, merged.stats.mergedWindows) << what;
            if (merged.stats.mergedWindows > 0) {
                ++mergedFrames;
                EXPECT_EQ(merged.stats.tcsPatches, each.stats.tcsPatches - merged.stats.mergedWindows + merged.stats.mergedBlocks) << what;
            }
            // Only the diagonals inside a block may differ: shading by a few levels, no cracks.
            EXPECT_LE(countDifferent(each.image, merged.image, 8), size_t(W * H / 2000)) << what;
            EXPECT_EQ(holes(merged.image, o.display.background), holes(each.image, o.display.background)) << what;
            EXPECT_EQ(holes(merged.image, o.display.background), 0u) << what;
        }
    }
    EXPECT_GE(mergedFrames, 10);

    // Uniform levels are not clamped by the max level (that is adaptive's): level 4 under a max of 2
    // merges at 4, as the windows alone are drawn.
    {
        const Document doc = splineNet(35, NetShape::Flat);
        off.setDocument(doc);
        render::RenderOptions o = plainOptions(doc, 4.0f, double(W) / H);
        o.tess.maxLevel = 2.0f;
        o.mergeWindows = render::MergeWindows::Never;
        const Rendered each = off.render(o);
        o.mergeWindows = render::MergeWindows::Always;
        const Rendered merged = off.render(o);
        EXPECT_GT(merged.stats.mergedWindows, 0u);
        EXPECT_EQ(merged.stats.triangles(), each.stats.triangles());
    }

    // What shows each patch's own tessellation, or needs a window's own UV, is never merged.
    const Document doc = splineNet(35, NetShape::Flat);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 2.0f, double(W) / H);
    o.mergeWindows = render::MergeWindows::Always;
    EXPECT_GT(off.render(o).stats.mergedWindows, 0u);
    for (const ShadingMode sm : {ShadingMode::PatchId, ShadingMode::UvChecker, ShadingMode::Level}) {
        o.display.shading = sm;
        EXPECT_EQ(off.render(o).stats.mergedWindows, 0u) << int(sm);
    }
    o.display.shading = ShadingMode::Lit;
    o.display.showWireframe = true;
    EXPECT_EQ(off.render(o).stats.mergedWindows, 0u);
    // Independent patches (a grid of Bézier patches) are no net: drawn one a patch.
    const Document grid = makePatchGrid(8, 8);
    off.setDocument(grid);
    render::RenderOptions g = plainOptions(grid, 2.0f, double(W) / H);
    g.mergeWindows = render::MergeWindows::Always;
    EXPECT_EQ(off.render(g).stats.mergedWindows, 0u);
}

}  // namespace
}  // namespace pw::test

// Rendered images: the lit teapot has no black or background pixels where the collapsed lid top
// and bottom centre project; overlays change pixels; pow2 at 5 equals equal spacing at 8;
// fractional_odd 4.5 differs from 5; every shading mode renders.
#include <gtest/gtest.h>

#include <cstring>

#include "core/gpu/level_colour.h"
#include "core/io/document_io.hpp"
#include "core/select/picking.hpp"
#include "render_support.hpp"

namespace pw::test {
namespace {

constexpr uint32_t W = 480, H = 360;

class RenderImage : public RenderTest {};

// The 5x5 pixels around the projection of `p` are surface (not background) and not dark.
void expectLitSurfaceAt(const Rendered& r, const render::RenderOptions& o, const Document& doc, glm::dvec3 p, const char* what) {
    const ViewMatrices vm = viewMatrices(o.camera, double(W) / H);
    const auto px = projectToPixel(vm, p, int(W), int(H));
    ASSERT_TRUE(px.has_value()) << what;
    const int cx = int(px->x), cy = int(px->y);
    ASSERT_TRUE(cx > 3 && cy > 3 && cx < int(W) - 3 && cy < int(H) - 3) << what;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const uint8_t* c = r.image.at(cx + dx, cy + dy);
            EXPECT_FALSE(sameColor(c, doc.display.background, 3)) << what << ": background at " << cx + dx << "," << cy + dy;
            EXPECT_GT(int(c[0]) + c[1] + c[2], 150) << what << ": dark pixel at " << cx + dx << "," << cy + dy;
        }
}

TEST_F(RenderImage, LitTeapotLidTopAndBottomHaveNoBlackPixels) {
    const Document doc = builtinTeapot();
    Offscreen off(W, H);
    off.setDocument(doc);
    for (int level : {8, 16, 64}) {
        render::RenderOptions top = plainOptions(doc, float(level), double(W) / H, "top");
        const Rendered rt = off.render(top);
        expectLitSurfaceAt(rt, top, doc, {0, 0, 3.15}, "lid top");
        render::RenderOptions bottom = plainOptions(doc, float(level), double(W) / H, "bottom");
        const Rendered rb = off.render(bottom);
        expectLitSurfaceAt(rb, bottom, doc, {0, 0, 0}, "bottom centre");
    }
}

TEST_F(RenderImage, OverlaysChangePixels) {
    const Document doc = builtinTeapot();
    Offscreen off(W, H);
    off.setDocument(doc);
    const render::RenderOptions base = plainOptions(doc, 8, double(W) / H, "iso");
    const Rendered plain = off.render(base);
    auto with = [&](auto set) {
        render::RenderOptions o = base;
        set(o);
        return off.render(o);
    };
    const Rendered grid = with([](render::RenderOptions& o) { o.display.showGrid = true; });
    const Rendered wire = with([](render::RenderOptions& o) { o.display.showWireframe = true; });
    const Rendered normals = with([](render::RenderOptions& o) {
        o.display.showNormals = true;
        o.display.normalLength = 0.2f;
    });
    const Rendered bounds = with([](render::RenderOptions& o) { o.display.showBoundaries = true; });
    EXPECT_GT(countDifferent(plain.image, grid.image, 8), 500u);
    EXPECT_GT(countDifferent(plain.image, wire.image, 8), 2000u);
    EXPECT_GT(countDifferent(plain.image, normals.image, 8), 1000u);
    EXPECT_GT(countDifferent(plain.image, bounds.image, 8), 300u);
    // Overlays leave the surface statistics alone.
    EXPECT_EQ(plain.stats.triangles(), wire.stats.triangles());

    // The grid draws every control point: the pixel of pool point 0 changes, and highlighting it
    // (hovered, selected) changes it again.
    const ViewMatrices vm = viewMatrices(base.camera, double(W) / H);
    const auto p0 = projectToPixel(vm, doc.points[0], int(W), int(H));
    ASSERT_TRUE(p0);
    const int x = int(p0->x), y = int(p0->y);
    render::RenderOptions sel = base;
    sel.display.showGrid = true;
    sel.selectedPoint = 0;
    const Rendered selected = off.render(sel);
    sel.selectedPoint = -1;
    sel.hoveredPoint = 0;
    const Rendered hovered = off.render(sel);
    auto differs = [&](const Image& a, const Image& b) {
        return std::abs(int(a.at(x, y)[0]) - int(b.at(x, y)[0])) + std::abs(int(a.at(x, y)[1]) - int(b.at(x, y)[1])) +
                   std::abs(int(a.at(x, y)[2]) - int(b.at(x, y)[2])) >
               30;
    };
    EXPECT_TRUE(differs(plain.image, grid.image));
    EXPECT_TRUE(differs(grid.image, selected.image));
    EXPECT_TRUE(differs(selected.image, hovered.image));
}

// The editor's ground grid is drawn in the 3D pass: visible on the background, hidden wherever the
// surface is in front of it (depth-tested), and it leaves the surface statistics alone.
TEST_F(RenderImage, GroundGridIsHiddenBehindTheSurface) {
    const Document doc = builtinTeapot();
    Offscreen off(W, H);
    off.setDocument(doc);
    const render::RenderOptions base = plainOptions(doc, 8, double(W) / H, "iso");
    render::RenderOptions grid = base;
    grid.groundGridStep = niceGridStep(modelSize(doc));
    const Rendered plain = off.render(base), ground = off.render(grid);
    size_t onBackground = 0, onSurface = 0, surface = 0;
    for (uint32_t y = 0; y < H; ++y)
        for (uint32_t x = 0; x < W; ++x) {
            const bool bg = sameColor(plain.image.at(int(x), int(y)), doc.display.background, 0);
            const bool changed = std::memcmp(plain.image.at(int(x), int(y)), ground.image.at(int(x), int(y)), 3) != 0;
            surface += !bg;
            (bg ? onBackground : onSurface) += changed;
        }
    EXPECT_GT(onBackground, 2000u);  // the lines show around the teapot
    EXPECT_GT(surface, 10000u);
    // and not over it (the iso view looks down on the grid the teapot stands on): at most the pixels
    // where the base touches the ground plane and the depths tie; drawn on top, the lines would
    // cross thousands of surface pixels.
    EXPECT_LT(onSurface, surface / 200) << onSurface << " of " << surface << " surface pixels changed";
    EXPECT_EQ(plain.stats.triangles(), ground.stats.triangles());
}

TEST_F(RenderImage, Pow2AtFiveEqualsEqualAtEight) {
    const Document doc = builtinTeapot();
    Offscreen off(W, H);
    off.setDocument(doc);
    render::RenderOptions a = plainOptions(doc, 5, double(W) / H);
    a.tess.spacing = Spacing::Pow2;
    render::RenderOptions b = plainOptions(doc, 8, double(W) / H);
    const Rendered ra = off.render(a), rb = off.render(b);
    EXPECT_EQ(countDifferent(ra.image, rb.image, 0), 0u);
    EXPECT_EQ(ra.stats.triangles(), 32u * 2 * 8 * 8);
    EXPECT_EQ(rb.stats.triangles(), 32u * 2 * 8 * 8);
}

TEST_F(RenderImage, FractionalOddFourAndAHalfDiffersFromFive) {
    const Document doc = builtinTeapot();
    Offscreen off(W, H);
    off.setDocument(doc);
    render::RenderOptions a = plainOptions(doc, 4.5f, double(W) / H);
    a.tess.spacing = Spacing::FractionalOdd;
    render::RenderOptions b = a;
    b.tess.outer = {5, 5, 5, 5};
    b.tess.inner = {5, 5};
    const Rendered ra = off.render(a), rb = off.render(b);
    EXPECT_GT(countDifferent(ra.image, rb.image, 2), 50u);
    // Same number of segments (5), different vertex positions.
    EXPECT_EQ(ra.stats.triangles(), rb.stats.triangles());
}

TEST_F(RenderImage, EveryShadingModeRenders) {
    const Document doc = builtinTeapot();
    Offscreen off(W, H);
    off.setDocument(doc);
    const render::RenderOptions base = plainOptions(doc, 8, double(W) / H);
    const Rendered lit = off.render(base);
    for (ShadingMode m : {ShadingMode::Normal, ShadingMode::PatchId, ShadingMode::UvChecker, ShadingMode::Zebra,
                          ShadingMode::GaussCurvature, ShadingMode::MeanCurvature, ShadingMode::Level}) {
        render::RenderOptions o = base;
        o.display.shading = m;
        const Rendered r = off.render(o);
        EXPECT_GT(countDifferent(lit.image, r.image, 8), 2000u) << shadingName(m);
    }
}

// `--shading level` (issue 41): a patch takes the colour of its level (core/gpu/level_colour.h, the
// ramp the legend draws) times the light, so its hue at level 2 and at 32 is the ramp's.
TEST_F(RenderImage, LevelShadingIsTheRampsColourOfThePatchsLevel) {
    const Document doc = flatPatch();
    Offscreen off(W, H);
    off.setDocument(doc);
    const auto hue = [](const glm::vec3& c) { return c / std::max({c.r, c.g, c.b}); };
    for (float level : {2.0f, 32.0f}) {
        render::RenderOptions o = plainOptions(doc, level, double(W) / H, "top");
        o.display.shading = ShadingMode::Level;
        const Rendered r = off.render(o);
        const uint8_t* px = r.image.at(int(W) / 2, int(H) / 2);
        const glm::vec3 got = hue(glm::vec3(px[0], px[1], px[2]) / 255.0f), want = hue(gpu::levelColour(level));
        EXPECT_NEAR(got.r, want.r, 0.06) << level;
        EXPECT_NEAR(got.g, want.g, 0.06) << level;
        EXPECT_NEAR(got.b, want.b, 0.06) << level;
    }
}

TEST_F(RenderImage, EverySpacingAndAdaptiveModeRenders) {
    const Document doc = builtinTeapot();
    Offscreen off(W, H);
    off.setDocument(doc);
    for (Spacing s : {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2})
        for (AdaptiveMode a : {AdaptiveMode::None, AdaptiveMode::Distance, AdaptiveMode::ScreenSpace, AdaptiveMode::Orientation}) {
            render::RenderOptions o = plainOptions(doc, 6, double(W) / H);
            o.tess.spacing = s;
            o.tess.adaptive = a;
            o.tess.distanceNear = 5;
            o.tess.distanceFar = 40;
            const Rendered r = off.render(o);
            EXPECT_GT(r.stats.triangles(), 32u) << spacingName(s) << " " << adaptiveName(a);
            EXPECT_EQ(r.stats.patchesCulled, 0u);
        }
}

}  // namespace
}  // namespace pw::test

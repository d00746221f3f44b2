// Comparison panes of the model (render/figures/model_figure.hpp): each pane is exactly the picture a
// target of the pane's size would show with the pane's settings, later panes leave the earlier
// ones alone, and each pane's statistics are its own. Validation layer on.
#include <algorithm>

#include "core/io/document_io.hpp"
#include "render/figures/label_raster.hpp"
#include "render/figures/model_figure.hpp"
#include "render_support.hpp"

namespace pw::test {
namespace {

// The pixels of `rect` (x, y, w, h) cut out of `img`.
Image crop(const Image& img, const std::array<int, 4>& r) {
    Image out;
    out.w = uint32_t(r[2]);
    out.h = uint32_t(r[3]);
    for (int y = 0; y < r[3]; ++y) {
        const uint8_t* row = img.at(r[0], r[1] + y);
        out.rgba.insert(out.rgba.end(), row, row + size_t(r[2]) * 4);
    }
    return out;
}

class ModelPanes : public RenderTest {};

TEST_F(ModelPanes, EachPaneIsTheRenderOfItsOwnSettings) {
    const Document doc = builtinTeapot();
    constexpr uint32_t W = 320, H = 240;
    Offscreen split(W, H, false);
    split.setDocument(doc);
    render::RenderOptions base = plainOptions(doc, 4.0f, double(W / 2) / double(H / 2), "iso");
    base.display.showWireframe = true;  // the patterns differ in the wireframe
    const std::vector<render::ModelPane> panes = {
        {Spacing::Equal, 0.0f}, {Spacing::FractionalOdd, 4.5f}, {Spacing::FractionalEven, 4.5f}, {Spacing::Pow2, 5.0f}};
    const auto rects = render::splitPanes(4, {0, 0, float(W), float(H)});
    std::vector<render::FrameStats> stats;
    Image whole;
    for (size_t i = 0; i < panes.size(); ++i) {
        const Rendered r = split.render(render::paneOptions(base, panes[i], rects[i], i));
        stats.push_back(r.stats);
        whole = r.image;
    }
    for (size_t i = 0; i < panes.size(); ++i) {
        const auto px = render::pixelRect(rects[i]);
        ASSERT_EQ(px[2], int(W / 2));
        ASSERT_EQ(px[3], int(H / 2));
        // The same settings drawn alone into a target of the pane's size.
        Offscreen alone(W / 2, H / 2, false);
        alone.setDocument(doc);
        render::RenderOptions o = render::paneOptions(base, panes[i], rects[i], 0);
        o.pane = {0, 0, 0, 0};
        const Rendered ref = alone.render(o);
        const Image cut = crop(whole, px);
        // Lit shading uses the view ray through each pixel: it must be measured from the pane's corner.
        EXPECT_LE(countDifferent(cut, ref.image, 2), size_t(cut.w * cut.h / 500)) << "pane " << i;
        EXPECT_EQ(stats[i].triangles(), ref.stats.triangles()) << "pane " << i;
    }
    // 32 patches: equal 4 -> 4 segments, fractional_odd 4.5 -> 5, fractional_even 4.5 -> 6, pow2 5 -> 8.
    EXPECT_EQ(stats[0].triangles(), 32u * 2 * 16);
    EXPECT_EQ(stats[1].triangles(), 32u * 2 * 25);
    EXPECT_EQ(stats[2].triangles(), 32u * 2 * 36);
    EXPECT_EQ(stats[3].triangles(), 32u * 2 * 64);
}

TEST_F(ModelPanes, ShadingUsesThePanesOwnViewRays) {
    // Zebra stripes reflect the view ray through each pixel: a pane that measured its pixels from
    // the target's corner instead of its own would show different stripes.
    const Document doc = builtinTeapot();
    constexpr uint32_t W = 320, H = 160;
    Offscreen split(W, H, false);
    split.setDocument(doc);
    render::RenderOptions base = plainOptions(doc, 8.0f, 1.0, "iso");
    base.display.shading = ShadingMode::Zebra;
    const auto rects = render::splitPanes(2, {0, 0, float(W), float(H)});
    split.render(render::paneOptions(base, {Spacing::Equal, 0.0f}, rects[0], 0));
    const Rendered right = split.render(render::paneOptions(base, {Spacing::Equal, 0.0f}, rects[1], 1));
    Offscreen alone(W / 2, H, false);
    alone.setDocument(doc);
    const Rendered ref = alone.render(base);
    const Image cut = crop(right.image, render::pixelRect(rects[1]));
    EXPECT_LE(countDifferent(cut, ref.image, 2), size_t(cut.w * cut.h / 500));
}

TEST_F(ModelPanes, ALaterPaneClearsOnlyItsRectangle) {
    const Document doc = flatPatch();
    constexpr uint32_t W = 200, H = 100;
    Offscreen off(W, H, false);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 4.0f, 1.0, "top");
    o.display.background = {1.0f, 0.0f, 0.0f};
    o.pane = {0, 0, 100, 100};
    const Rendered left = off.render(o);
    o.display.background = {0.0f, 0.0f, 1.0f};
    o.pane = {100, 0, 100, 100};
    o.keepTarget = true;
    const Rendered both = off.render(o);
    // Corners are background: red on the left (first pane), blue on the right (second).
    EXPECT_TRUE(sameColor(both.image.at(1, 1), {1, 0, 0}));
    EXPECT_TRUE(sameColor(both.image.at(198, 1), {0, 0, 1}));
    // The left pane is untouched by the second submission.
    EXPECT_EQ(crop(both.image, {0, 0, 100, 100}).rgba, crop(left.image, {0, 0, 100, 100}).rgba);
    // The patch fills the middle of both panes.
    EXPECT_FALSE(sameColor(both.image.at(50, 50), {1, 0, 0}));
    EXPECT_FALSE(sameColor(both.image.at(150, 50), {0, 0, 1}));
}

TEST_F(ModelPanes, FigureCaptionsEachPane) {
    const Document doc = builtinTeapot();
    const render::LabelRaster labels;
    render::OffscreenTarget target(sharedDevice(), 400, 200, false);
    render::Renderer renderer(sharedDevice(), target);
    renderer.setDocument(doc);
    std::vector<uint8_t> rgba;
    const render::RenderOptions base = plainOptions(doc, 3.0f, 1.0);
    const auto panes =
        render::renderModelFigure(renderer, target, labels, base, {{Spacing::Equal, 0}, {Spacing::FractionalOdd, 3.5f}}, 14.0f, rgba);
    ASSERT_EQ(panes.size(), 2u);
    EXPECT_EQ(panes[0].stats.triangles(), 32u * 2 * 9);
    EXPECT_EQ(panes[1].stats.triangles(), 32u * 2 * 25);  // fractional_odd 3.5 -> 5
    EXPECT_EQ(panes[1].tess.outer[0], 3.5f);
    EXPECT_EQ(panes[1].rect, (std::array<int, 4>{200, 0, 200, 200}));
    // Caption boxes (near white) at each pane's top left.
    auto whiteIn = [&](uint32_t x0, uint32_t x1) {
        size_t n = 0;
        for (uint32_t y = 4; y < 20; ++y)
            for (uint32_t x = x0; x < x1; ++x) n += rgba[(size_t(y) * 400 + x) * 4] > 200;
        return n;
    };
    EXPECT_GT(whiteIn(5, 60), 200u);
    EXPECT_GT(whiteIn(205, 260), 200u);
    TessSettings ts;
    ts.spacing = Spacing::FractionalOdd;
    ts.outer = {3.5f, 3.5f, 3.5f, 3.5f};
    ts.inner = {3.5f, 3.5f};
    EXPECT_EQ(render::paneCaption(ts, 1234567), "fractional_odd \u00b7 level 3.5 \u00b7 1,234,567 triangles");
    ts.inner = {2.0f, 3.5f};
    EXPECT_EQ(render::paneCaption(ts, 7), "fractional_odd \u00b7 outer 3.5 3.5 3.5 3.5 inner 2 3.5 \u00b7 7 triangles");
}

TEST(ModelPaneRect, ClampsToTheTargetAndFallsBackToTheWhole) {
    render::RenderOptions o;
    const VkExtent2D ext{200, 100};
    auto eq = [](VkRect2D r, int x, int y, uint32_t w, uint32_t h) {
        return r.offset.x == x && r.offset.y == y && r.extent.width == w && r.extent.height == h;
    };
    EXPECT_TRUE(eq(render::paneRect(o, ext), 0, 0, 200, 100));
    o.pane = {150, 50, 100, 100};
    EXPECT_TRUE(eq(render::paneRect(o, ext), 150, 50, 50, 50));
    o.pane = {300, 0, 10, 10};  // outside: the whole target
    EXPECT_TRUE(eq(render::paneRect(o, ext), 0, 0, 200, 100));
    o.pane = {-10, -10, 20, 20};
    EXPECT_TRUE(eq(render::paneRect(o, ext), 0, 0, 10, 10));
    EXPECT_EQ(render::pixelRect({0.4f, 0.6f, 99.5f, 10.2f}), (std::array<int, 4>{0, 1, 100, 10}));
    EXPECT_EQ(render::paneSize(4, 481, 300), (std::array<uint32_t, 2>{241, 150}));
    EXPECT_EQ(render::paneSize(0, 20, 10), (std::array<uint32_t, 2>{20, 10}));
}

}  // namespace
}  // namespace pw::test

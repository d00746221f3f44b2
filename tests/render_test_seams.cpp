// No cracks with mismatched adaptive levels, and a large batched model renders like its CPU
// pre-tessellated mesh drawn as plain triangles.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/mesh_tessellate.hpp"
#include "core/model_builders.hpp"
#include "render/png_writer.hpp"
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
        if (sign == 0) sign = s;
        else if (s != sign) return false;
    }
    return true;
}

// Counts background pixels inside the projected grid, shrunk by 10 % towards its centre (the wave bends the projected boundary).
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
    size_t holes = 0;
    std::vector<uint8_t> marked = r.image.rgba;
    for (uint32_t y = 0; y < r.image.h; ++y)
        for (uint32_t x = 0; x < r.image.w; ++x)
            if (insideConvex(q, {x + 0.5, y + 0.5}) && sameColor(r.image.at(int(x), int(y)), doc.display.background, 6)) {
                ++holes;
                uint8_t* m = &marked[(size_t(y) * r.image.w + x) * 4];
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

TEST_F(RenderSeams, DistanceAdaptiveGridHasNoCracks) {
    const int rows = 6, cols = 6;
    const Document doc = makePatchGrid(rows, cols);
    Offscreen off(640, 480, false);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 16, 640.0 / 480.0, "top");
    o.camera.pitchDeg = 50;
    o.tess.adaptive = AdaptiveMode::Distance;
    o.tess.distanceNear = float(o.camera.distance * 0.7);
    o.tess.distanceFar = float(o.camera.distance * 1.5);
    o.tess.spacing = Spacing::FractionalOdd;
    const Rendered r = off.render(o);
    EXPECT_EQ(holesInside(r, o, doc, rows, cols), 0u);
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

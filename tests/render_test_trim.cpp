// Trimmed surfaces drawn by the GPU (issue 64): the fragment shader's direct trim test against the
// CPU's point-in-loop test (both core/gpu/trim_math.h) on every pixel of a plate with a circular
// hole, seen from above: no mismatch farther than 1 px from the curve; and picking through the hole.
#include <cmath>

#include "core/select/picking.hpp"
#include "core/trim/trim_loops.hpp"
#include "render_support.hpp"

using namespace pw;
using namespace pw::test;

namespace {

TrimLoop circleLoop(double cx, double cy, double r, bool hole) { return pw::circleLoop({cx, cy}, r, hole); }

struct TrimCase {
    ShadingMode shading;
    bool hole;
};

}  // namespace

class TrimRender : public RenderTest {};

TEST_F(TrimRender, TheGpuTrimMatchesTheCpuTestOnEveryPixel) {
    for (const TrimCase c :
         {TrimCase{ShadingMode::Lit, true}, TrimCase{ShadingMode::Normal, false}, TrimCase{ShadingMode::PatchId, true}}) {
        Document doc = flatPatch();  // P(u, v) = (3u, 3v, 0)
        doc.patches[0].trims.push_back(circleLoop(0.5, 0.45, 0.3, c.hole));
        doc.patches[0].trims.push_back(circleLoop(0.55, 0.5, 0.1, !c.hole));  // an island in the hole, or a hole in the disc
        const uint32_t W = 240, H = 240;
        Offscreen off(W, H, false);
        off.setDocument(doc);
        render::RenderOptions o = plainOptions(doc, 8.0f, 1.0, "top");
        o.display.shading = c.shading;
        o.camera.orthographic = true;
        o.camera = frameBounds(o.camera, computeBounds(doc.points), 1.0);
        const Rendered r = off.render(o);
        // Pixel <-> domain through the projection of three corners (an affine map in a top orthographic view).
        const ViewMatrices vm = viewMatrices(o.camera, 1.0);
        const auto p00 = projectToPixel(vm, {0, 0, 0}, int(W), int(H)), p10 = projectToPixel(vm, {3, 0, 0}, int(W), int(H)),
                   p01 = projectToPixel(vm, {0, 3, 0}, int(W), int(H));
        ASSERT_TRUE(p00 && p10 && p01);
        const glm::dvec2 eu = *p10 - *p00, ev = *p01 - *p00;
        const double det = eu.x * ev.y - eu.y * ev.x;
        ASSERT_GT(std::abs(det), 100.0);
        const double pxPerUv = std::sqrt(std::abs(det));
        const auto segs = monotoneSegments(doc.patches[0].trims);
        const bool outer = hasOuterLoop(doc.patches[0].trims);
        size_t mismatches = 0, tested = 0, kept = 0;
        for (uint32_t y = 0; y < H; ++y)
            for (uint32_t x = 0; x < W; ++x) {
                const glm::dvec2 q = glm::dvec2(x + 0.5, y + 0.5) - *p00;
                const glm::dvec2 uv((q.x * ev.y - q.y * ev.x) / det, (eu.x * q.y - eu.y * q.x) / det);
                if (uv.x < 0.02 || uv.y < 0.02 || uv.x > 0.98 || uv.y > 0.98) continue;
                const double d1 = std::abs(glm::length(uv - glm::dvec2(0.5, 0.45)) - 0.3),
                             d2 = std::abs(glm::length(uv - glm::dvec2(0.55, 0.5)) - 0.1);
                if (std::min(d1, d2) * pxPerUv < 1.5) continue;  // within about a pixel of a curve (the cubic circle is within 3e-4 of it)
                const bool cpu = trimKeeps(segs, outer, uv);
                const bool gpu = !sameColor(r.image.at(int(x), int(y)), o.display.background, 3);
                ++tested;
                kept += gpu ? 1 : 0;
                mismatches += cpu != gpu ? 1 : 0;
            }
        EXPECT_GT(tested, 15000u);
        EXPECT_GT(kept, 3000u);
        EXPECT_LT(kept, tested - 3000u);
        EXPECT_EQ(mismatches, 0u) << "shading " << shadingName(c.shading) << (c.hole ? " hole" : " keep");
    }
}

// Picking ignores what is trimmed away: a ray through the hole hits nothing; beside it, the plate.
TEST(TrimPick, ARayThroughTheHoleMissesThePlate) {
    Document doc = flatPatch();
    doc.patches[0].trims.push_back(circleLoop(0.5, 0.5, 0.3, true));
    const Ray through{{1.5, 1.5, 5.0}, {0.0, 0.0, -1.0}}, beside{{0.3, 0.3, 5.0}, {0.0, 0.0, -1.0}};
    EXPECT_FALSE(pickSurface(doc, through, 16));
    EXPECT_TRUE(pickSurface(doc, beside, 16));
}

// Cubic Bézier triangles on the GPU (validation layer on, any message fails): pipeline statistics
// match the triangle-domain rules of the Vulkan tessellator (an independent CPU formula below),
// the lit dome has no holes and no black pixels inside its silhouette, two triangles sharing an
// edge at different levels show no crack, and every spacing and shading mode renders.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include "core/construct/model_builders.hpp"
#include "render/targets/png_writer.hpp"
#include "render_support.hpp"

namespace pw::test {
namespace {

constexpr uint32_t W = 320, H = 320;

class RenderTriangles : public RenderTest {};

// Triangles the triangle domain makes for equal spacing (Vulkan spec, "Triangle Tessellation"):
// concentric triangles whose edges have inner, inner-2, ... segments down to a point (0) or one
// triangle (1); the outer ring joins the outer edges to the first inner triangle, every other ring
// joins k to k-2 segments per edge. An inner level of 1 counts as 2 unless every level is 1.
long triangleDomainTriangles(std::array<int, 3> outer, int inner) {
    if (outer == std::array<int, 3>{1, 1, 1} && inner == 1) return 1;
    if (inner == 1) inner = 2;
    long t = 0;
    int k = inner - 2;
    for (int o : outer) t += o + k;  // outer ring
    for (; k > 1; k -= 2) t += 3 * (k + (k - 2));
    return t + (k == 1 ? 1 : 0);
}

// One flat triangle with corners (3,0,0) (u = 1), (0,3,0) (v = 1), (0,0,0) (w = 1): normal +z.
Document flatTriangle() {
    Document doc;
    doc.name = "flat triangle";
    TrianglePatch t;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3 - i; ++j) {
            const int k = 3 - i - j;
            t.idx[size_t((3 - i) * (4 - i) / 2 + k)] = uint32_t(doc.points.size());
            doc.points.push_back(Vec3(i, j, 0.0));
        }
    doc.triangles.push_back(t);
    return doc;
}

// Two curved triangles splitting the unit square along the diagonal (1,0)-(0,1), sharing that
// edge's four pool points; every control point lies on the 4x4 lattice of the square.
Document twoTriangles() {
    Document doc;
    doc.name = "two triangles";
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            const double x = c / 3.0, y = r / 3.0;
            doc.points.push_back(Vec3(x, y, 0.6 * x * y + 0.25 * std::sin(3.0 * x) - 0.3 * y * y));
        }
    auto lattice = [](int c, int r) { return uint32_t(r * 4 + c); };
    TrianglePatch a, b;  // a: u corner (1,0), v corner (0,1), w corner (0,0); b: u (0,1), v (1,0), w (1,1)
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3 - i; ++j) {
            const int k = 3 - i - j;
            const size_t slot = size_t((3 - i) * (4 - i) / 2 + k);
            a.idx[slot] = lattice(i, j);
            b.idx[slot] = lattice(j + k, i + k);
        }
    // Different levels everywhere except the shared edge (edge 2 of both, 7 segments).
    a.tessOverride = std::array<float, 4>{5.0f, 9.0f, 7.0f, 3.0f};
    b.tessOverride = std::array<float, 4>{11.0f, 2.0f, 7.0f, 13.0f};
    doc.triangles = {a, b};
    return doc;
}

render::RenderOptions topView(const Document& doc, float level) { return plainOptions(doc, level, double(W) / H, "top"); }

// Background pixels inside the convex polygon `poly` (pixels), shrunk by `shrink` towards its centre.
size_t holesInside(const Rendered& r, const Document& doc, std::vector<glm::dvec2> poly, double shrink, const char* dumpTag) {
    glm::dvec2 c(0.0);
    for (const auto& p : poly) c += p / double(poly.size());
    for (auto& p : poly) p = c + (p - c) * shrink;
    auto inside = [&](glm::dvec2 q) {
        int sign = 0;
        for (size_t i = 0; i < poly.size(); ++i) {
            const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
            const int s = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x) > 0 ? 1 : -1;
            if (sign == 0)
                sign = s;
            else if (s != sign)
                return false;
        }
        return true;
    };
    size_t holes = 0;
    std::vector<uint8_t> marked = r.image.rgba;
    for (uint32_t y = 0; y < r.image.h; ++y)
        for (uint32_t x = 0; x < r.image.w; ++x) {
            if (!inside({x + 0.5, y + 0.5})) continue;
            const uint8_t* px = r.image.at(int(x), int(y));
            const bool background = sameColor(px, doc.display.background, 6);
            const bool black = int(px[0]) + px[1] + px[2] < 30;
            if (background || black) {
                ++holes;
                uint8_t* m = &marked[(size_t(y) * r.image.w + x) * 4];
                m[0] = 255, m[1] = 0, m[2] = 255;
            }
        }
    if (holes && std::getenv("PATCHWORK_TEST_DUMP"))
        render::writePng(std::string(std::getenv("PATCHWORK_TEST_DUMP")) + "-" + dumpTag + ".png", r.image.w, r.image.h, marked);
    return holes;
}

std::vector<glm::dvec2> projected(const Rendered& r, const render::RenderOptions& o, const std::vector<Vec3>& pts) {
    const ViewMatrices vm = viewMatrices(o.camera, double(r.image.w) / r.image.h);
    std::vector<glm::dvec2> out;
    for (const Vec3& p : pts) out.push_back(*projectToPixel(vm, p, int(r.image.w), int(r.image.h)));
    return out;
}

}  // namespace

TEST(TriangleDomainFormula, HandCountedCases) {
    EXPECT_EQ(triangleDomainTriangles({1, 1, 1}, 1), 1);
    EXPECT_EQ(triangleDomainTriangles({2, 2, 2}, 2), 6);   // a fan of 2 per edge around the centre
    EXPECT_EQ(triangleDomainTriangles({3, 3, 3}, 3), 13);  // ring of 3+1 per edge, 1 inside
    EXPECT_EQ(triangleDomainTriangles({4, 4, 4}, 4), 24);  // 3(4+2) + 3(2+0)
    EXPECT_EQ(triangleDomainTriangles({1, 2, 3}, 1), 6);   // inner 1 -> 2: fans of 1, 2, 3
}

TEST_F(RenderTriangles, SingleTriangleUniformLevelCountsFollowTheTriangleDomain) {
    // Uniform level n everywhere: 3n²/2 triangles for even n, (3n² - 1)/2 for odd n.
    const Document doc = flatTriangle();
    Offscreen off(W, H);
    off.setDocument(doc);
    for (int n : {1, 2, 3, 5, 8, 16, 33, 64}) {
        const Rendered r = off.render(topView(doc, float(n)));
        ASSERT_TRUE(r.stats.pipelineStatsValid);
        EXPECT_EQ(r.stats.tcsPatches, 1u);
        EXPECT_EQ(long(r.stats.triangles()), triangleDomainTriangles({n, n, n}, n)) << "level " << n;
        EXPECT_EQ(long(r.stats.triangles()), (3L * n * n - (n % 2)) / 2) << "level " << n;
        EXPECT_EQ(r.stats.patches, 1u);
    }
}

TEST_F(RenderTriangles, PerEdgeLevelsAndOverridesFollowTheTriangleDomain) {
    Document doc = flatTriangle();
    Offscreen off(W, H);
    off.setDocument(doc);
    render::RenderOptions o = topView(doc, 1);
    o.tess.outer = {2, 5, 7, 16};  // outer[3] and inner[1] are unused by triangles
    o.tess.inner = {4, 30};
    EXPECT_EQ(long(off.render(o).stats.triangles()), triangleDomainTriangles({2, 5, 7}, 4));
    doc.triangles[0].tessOverride = std::array<float, 4>{3, 1, 6, 5};
    off.setDocument(doc);
    EXPECT_EQ(long(off.render(o).stats.triangles()), triangleDomainTriangles({3, 1, 6}, 5));
}

TEST_F(RenderTriangles, DomeAndQuadsCountTogether) {
    // Six triangles at level 4 (24 each) after a flat quad at level 4 (32).
    Document doc = flatPatch();
    const Document dome = makeTriangleDome(1.0, 0.5);
    const uint32_t base = uint32_t(doc.points.size());
    for (const Vec3& p : dome.points) doc.points.push_back(p + Vec3(5.0, 1.5, 0.0));
    for (TrianglePatch t : dome.triangles) {
        for (uint32_t& i : t.idx) i += base;
        doc.triangles.push_back(t);
    }
    Offscreen off(W, H);
    off.setDocument(doc);
    const Rendered r = off.render(topView(doc, 4));
    EXPECT_EQ(r.stats.triangles(), uint64_t(32 + 6 * 24));
    EXPECT_EQ(r.stats.tcsPatches, 7u);
    EXPECT_EQ(r.stats.patches, 7u);
}

TEST_F(RenderTriangles, LitDomeHasNoHolesOrBlackPixelsInsideItsSilhouette) {
    const Document doc = makeTriangleDome(1.0, 0.5);
    Offscreen off(W, H);
    off.setDocument(doc);
    std::vector<Vec3> hexagon;
    for (int m = 0; m < 6; ++m) hexagon.push_back(doc.points[doc.triangles[size_t(m)].idx[0]]);
    for (int level : {1, 3, 8, 64}) {
        SCOPED_TRACE(level);
        const render::RenderOptions o = topView(doc, float(level));
        const Rendered r = off.render(o);
        // Level 1 draws the flat triangles, whose silhouette is the hexagon itself.
        EXPECT_EQ(holesInside(r, doc, projected(r, o, hexagon), 0.97, "dome"), 0u);
        // Normals point up: the lit shading is front-facing (no back-face tint: red > green * 1.5).
        const glm::dvec2 c = projected(r, o, {Vec3(0.0, 0.0, 0.5)})[0];
        const uint8_t* px = r.image.at(int(c.x), int(c.y));
        EXPECT_LT(int(px[0]), int(px[1]) * 3 / 2 + 10);
    }
    // A side view too: points under the dome (above its rim) are covered by the surface, seen from
    // outside or, through the open bottom, from inside.
    const render::RenderOptions side = plainOptions(doc, 16, double(W) / H, "front");
    const Rendered rs = off.render(side);
    EXPECT_EQ(holesInside(rs, doc, projected(rs, side, {Vec3(-0.6, 0, 0.2), Vec3(0.6, 0, 0.2), Vec3(0, 0, 0.45)}), 0.85, "side"), 0u);
}

TEST_F(RenderTriangles, CurvatureShadingShowsTheDomesCurvature) {
    // The paraboloid z = h (1 - r²/R²) with upward normals: Gaussian curvature 4h²/R⁴ > 0 at the
    // top (red in the diverging map), mean curvature -2h/R² < 0 (blue); the flat triangle has
    // neither (white, as lit grey).
    const Document dome = makeTriangleDome(1.0, 0.5);
    Offscreen off(W, H, false);
    off.setDocument(dome);
    render::RenderOptions o = topView(dome, 16.0f);
    auto centre = [&](const render::RenderOptions& opt) {
        const Rendered r = off.render(opt);
        const glm::dvec2 c = projected(r, opt, {Vec3(0.1, 0.05, 0.49)})[0];
        const uint8_t* px = r.image.at(int(c.x), int(c.y));
        return std::array<int, 3>{px[0], px[1], px[2]};
    };
    o.display.shading = ShadingMode::GaussCurvature;
    const auto gauss = centre(o);
    EXPECT_GT(gauss[0], gauss[1] + 25) << "Gaussian curvature > 0 is red";
    EXPECT_GT(gauss[0], gauss[2] + 25);
    o.display.shading = ShadingMode::MeanCurvature;
    const auto mean = centre(o);
    EXPECT_GT(mean[2], mean[0] + 25) << "mean curvature < 0 is blue";
    const Document flat = flatTriangle();
    off.setDocument(flat);
    render::RenderOptions f = topView(flat, 8.0f);
    f.display.shading = ShadingMode::GaussCurvature;
    const Rendered r = off.render(f);
    const glm::dvec2 c = projected(r, f, {Vec3(1.0, 1.0, 0.0)})[0];
    const uint8_t* px = r.image.at(int(c.x), int(c.y));
    EXPECT_LE(std::abs(int(px[0]) - int(px[2])), 6) << "zero curvature is neutral";
}

TEST_F(RenderTriangles, NormalVectorOverlayDrawsTheTrianglesNormals) {
    if (!sharedDevice().caps().geometryShader) GTEST_SKIP() << "no geometry shaders on this device";
    // A document of triangles only: every normal vector drawn comes from the triangle pipeline.
    const Document dome = makeTriangleDome(1.0, 0.5);
    Offscreen off(W, H, false);
    off.setDocument(dome);
    render::RenderOptions o = plainOptions(dome, 6.0f, double(W) / H, "front");
    o.display.normalLength = 0.3f;
    auto cyan = [](const Rendered& r) {
        size_t n = 0;
        for (size_t i = 0; i < r.image.rgba.size(); i += 4)
            n += r.image.rgba[i] < 110 && r.image.rgba[i + 1] > 180 && r.image.rgba[i + 2] > 200;
        return n;
    };
    EXPECT_EQ(cyan(off.render(o)), 0u);
    o.display.showNormals = true;
    const Rendered r = off.render(o);
    EXPECT_GT(cyan(r), 200u);
    // They stand on the dome and point up and out: cyan above the dome's top (z = 0.5 + 0.3).
    const glm::dvec2 top = projected(r, o, {Vec3(0.0, 0.0, 0.7)})[0];
    size_t above = 0;
    for (int dx = -3; dx <= 3; ++dx) {
        const uint8_t* px = r.image.at(int(top.x) + dx, int(top.y));
        above += px[0] < 110 && px[1] > 180 && px[2] > 200;
    }
    EXPECT_GT(above, 0u);
}

TEST_F(RenderTriangles, SharedEdgeAtDifferentLevelsHasNoCrack) {
    const Document doc = twoTriangles();
    Offscreen off(W, H, /*msaa=*/false);
    off.setDocument(doc);
    const std::vector<Vec3> square = {doc.points[0], doc.points[3], doc.points[15], doc.points[12]};
    // Per-triangle overrides (shared edge 7, everything else different), then adaptive screen-space
    // levels (each edge from its own points), under every spacing.
    for (Spacing s : {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2}) {
        SCOPED_TRACE(spacingName(s));
        render::RenderOptions o = topView(doc, 4);
        o.tess.spacing = s;
        const Rendered r = off.render(o);
        EXPECT_GT(r.stats.triangles(), 0u);
        EXPECT_EQ(holesInside(r, doc, projected(r, o, square), 0.98, "override"), 0u);
    }
    Document plain = doc;
    for (TrianglePatch& t : plain.triangles) t.tessOverride.reset();
    off.setDocument(plain);
    for (AdaptiveMode mode : {AdaptiveMode::ScreenSpace, AdaptiveMode::Distance}) {
        render::RenderOptions o = topView(plain, 4);
        o.tess.adaptive = mode;
        o.tess.targetPixels = 5.0f;
        o.tess.distanceNear = float(o.camera.distance * 0.9);
        o.tess.distanceFar = float(o.camera.distance * 1.2);
        o.tess.spacing = Spacing::FractionalOdd;
        const Rendered r = off.render(o);
        EXPECT_GT(r.stats.triangles(), 0u);
        EXPECT_EQ(holesInside(r, plain, projected(r, o, square), 0.98, "adaptive"), 0u);
    }
}

TEST_F(RenderTriangles, EverySpacingShadingAndOverlayRenders) {
    const Document doc = makeTriangleDome(1.0, 0.5);
    Offscreen off(W, H);
    off.setDocument(doc);
    for (Spacing s : {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2})
        for (ShadingMode m : {ShadingMode::Lit, ShadingMode::Normal, ShadingMode::PatchId, ShadingMode::UvChecker, ShadingMode::Zebra,
                              ShadingMode::GaussCurvature, ShadingMode::MeanCurvature}) {
            render::RenderOptions o = topView(doc, 5.5f);
            o.tess.spacing = s;
            o.display.shading = m;
            o.display.showGrid = o.display.showWireframe = o.display.showNormals = o.display.showBoundaries = true;
            const Rendered r = off.render(o);
            EXPECT_GT(r.stats.triangles(), 0u) << spacingName(s) << " " << shadingName(m);
        }
    // Culling: the dome seen from below is back-facing, from above it is kept.
    render::RenderOptions below = plainOptions(doc, 8, double(W) / H, "bottom");
    below.tess.cullBackfaces = true;
    const Rendered rb = off.render(below);
    EXPECT_EQ(rb.stats.patchesCulled, 6u);
    render::RenderOptions above = topView(doc, 8);
    above.tess.cullBackfaces = true;
    EXPECT_EQ(off.render(above).stats.patchesCulled, 0u);
}

}  // namespace pw::test

// The isoline domain on the model: Bézier curves drawn through the isoline tessellator follow their
// segments level (one segment: the chord; many: through the true curve), fractional partitioning
// changes the picture, and the isocurve overlay draws each window's isoparametric curves, the first
// and last on its boundary. The surface statistics are not changed by either. Validation on.
#include <algorithm>

#include "core/eval/bezier_curve.hpp"
#include "core/ops/patch_ops.hpp"
#include "render_support.hpp"

namespace pw::test {
namespace {

constexpr uint32_t kW = 320, kH = 240;

// The curve (0.95, 0.35, 0.25) and isocurve (0.35, 0.95, 0.45) colours, also where multisampling
// blends a one-pixel line with the grey surface or the background.
bool curveRed(const uint8_t* p) { return p[0] > p[1] + 50 && p[0] > p[2] + 50; }
bool isoGreen(const uint8_t* p) { return p[1] > p[0] + 30 && p[1] > p[2] + 30; }

// Whether a pixel of the colour lies within `r` pixels of the projection of world point q.
template <class Pred>
bool near(const Rendered& img, const render::RenderOptions& o, const Vec3& q, Pred pred, int r = 2) {
    const ViewMatrices vm = viewMatrices(o.camera, double(kW) / double(kH));
    const auto px = projectToPixel(vm, q, int(kW), int(kH));
    if (!px) return false;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            const int x = int(std::lround(px->x)) + dx, y = int(std::lround(px->y)) + dy;
            if (x >= 0 && y >= 0 && x < int(kW) && y < int(kH) && pred(img.image.at(x, y))) return true;
        }
    return false;
}

template <class Pred>
size_t count(const Rendered& img, Pred pred) {
    size_t n = 0;
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) n += pred(img.image.at(int(x), int(y)));
    return n;
}

class Curves : public RenderTest {};

TEST_F(Curves, SegmentsLevelDecidesBetweenChordAndCurve) {
    Document doc;
    addCurve(doc, Vec3(0.0), 4.0);  // an arch in z = 0: (-2,0) .. (2,0), apex at y = 1.5
    const auto p = curvePoints(doc, doc.curves[0]);
    Offscreen off(kW, kH);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 4.0f, double(kW) / kH, "top");
    const Vec3 apex = evaluateCurve(p, 0.5), chordMid = 0.5 * (p[0] + p[3]);

    o.tess.isolineLevels = {1.0f, 1.0f};
    const Rendered one = off.render(o);
    EXPECT_TRUE(near(one, o, chordMid, curveRed));  // one segment: the straight chord
    EXPECT_FALSE(near(one, o, apex, curveRed, 3));
    EXPECT_EQ(one.stats.triangles(), 0u);  // curves are not surface triangles

    o.tess.isolineLevels = {1.0f, 32.0f};
    const Rendered many = off.render(o);
    EXPECT_FALSE(near(many, o, chordMid, curveRed, 3));
    for (double t : {0.1, 0.25, 0.5, 0.75, 0.9}) EXPECT_TRUE(near(many, o, evaluateCurve(p, t), curveRed)) << "t " << t;

    // Two segments: the polyline through the apex, not through the quarter points' true positions.
    o.tess.isolineLevels = {1.0f, 2.0f};
    const Rendered two = off.render(o);
    EXPECT_TRUE(near(two, o, apex, curveRed));
    EXPECT_NE(count(two, curveRed), count(one, curveRed));

    // Fractional odd at 4.5 draws 5 unequal segments, not equal 5 nor 3.
    o.tess.isolineLevels = {1.0f, 5.0f};
    const Rendered equal5 = off.render(o);
    o.tess.spacing = Spacing::FractionalOdd;
    o.tess.isolineLevels = {1.0f, 4.5f};
    const Rendered odd45 = off.render(o);
    EXPECT_GT(countDifferent(equal5.image, odd45.image, 40), 0u);
    o.tess.isolineLevels = {1.0f, 5.0f};
    EXPECT_EQ(countDifferent(equal5.image, off.render(o).image, 0), 0u);  // odd at an odd integer = equal
}

TEST_F(Curves, IsocurveOverlayDrawsBoundariesAndInteriorLines) {
    const Document doc = flatPatch();  // [0,3]^2 in z = 0
    Offscreen off(kW, kH);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 8.0f, double(kW) / kH, "top");
    const Rendered plain = off.render(o);
    EXPECT_EQ(count(plain, isoGreen), 0u);

    o.display.showIsocurves = true;
    o.tess.isolineLevels = {2.0f, 16.0f};
    const Rendered boundary = off.render(o);
    EXPECT_EQ(boundary.stats.triangles(), plain.stats.triangles());  // an overlay: the surface counts stay
    for (const Vec3& q : {Vec3(1.5, 0.0, 0.0), Vec3(3.0, 1.5, 0.0), Vec3(1.5, 3.0, 0.0), Vec3(0.0, 1.5, 0.0)})
        EXPECT_TRUE(near(boundary, o, q, isoGreen)) << q.x << "," << q.y;
    EXPECT_FALSE(near(boundary, o, Vec3(1.5, 0.75, 0.0), isoGreen, 2));  // no interior line with 2

    o.tess.isolineLevels = {3.0f, 16.0f};  // a third line in each direction, through the middle
    const Rendered three = off.render(o);
    EXPECT_TRUE(near(three, o, Vec3(1.5, 0.75, 0.0), isoGreen));
    EXPECT_TRUE(near(three, o, Vec3(0.75, 1.5, 0.0), isoGreen));
    EXPECT_GT(count(three, isoGreen), count(boundary, isoGreen));

    o.tess.isolineLevels = {2.5f, 16.0f};  // the line count is always rounded up: 2.5 draws 3 lines
    EXPECT_EQ(countDifferent(three.image, off.render(o).image, 0), 0u);
}

}  // namespace
}  // namespace pw::test

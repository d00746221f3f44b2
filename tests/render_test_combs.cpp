// Curvature combs through the isoline tessellator (issue 21), validation on: the teeth of a
// planar Bézier curve end where an independent curvature (the circle through three nearby curve
// points) puts them, outward from the centre of curvature; the curvature graph across a join draws
// its two windows' combs; `render --comb-join` checks its argument.
#include <cmath>

#include "core/construct/model_builders.hpp"
#include "render_support.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

Vec3 bezier(const std::array<Vec3, 4>& c, double t) {
    const double s = 1.0 - t;
    return s * s * s * c[0] + 3.0 * s * s * t * c[1] + 3.0 * s * t * t * c[2] + t * t * t * c[3];
}

// Curvature and unit normal towards the centre at t from the circle through p(t − h), p(t), p(t + h)
// (one-sided at the ends): no derivative formula involved.
void circleCurvature(const std::array<Vec3, 4>& c, double t, double& kappa, Vec3& towardsCentre) {
    const double h = 1e-4;
    const double t0 = std::clamp(t - h, 0.0, 1.0 - 2 * h);
    const Vec3 a = bezier(c, t0), b = bezier(c, t0 + h), d = bezier(c, t0 + 2 * h);
    const Vec3 ab = b - a, ad = d - a;
    const Vec3 n = glm::cross(ab, ad);
    const Vec3 centre = a + (glm::dot(ad, ad) * glm::cross(n, ab) + glm::dot(ab, ab) * glm::cross(ad, n)) / (2.0 * glm::dot(n, n));
    const Vec3 p = bezier(c, t);
    kappa = 1.0 / glm::length(centre - a);
    towardsCentre = glm::normalize(centre - p);
}

class Combs : public RenderTest {};

TEST_F(Combs, TeethEndWhereTheCurvatureSays) {
    Document doc;
    const std::array<Vec3, 4> c{Vec3(0, 0, 0), Vec3(1, 2.4, 0), Vec3(3, 2.4, 0), Vec3(4, 0, 0)};
    for (const Vec3& p : c) doc.points.push_back(p);
    doc.points.push_back(Vec3(-1.5, -2.5, 0));  // room for the teeth (unused pool points frame the view)
    doc.points.push_back(Vec3(5.5, 4.5, 0));
    doc.curves.push_back(BezierCurve{{0, 1, 2, 3}, "arc", false});
    doc.display.showCombs = true;
    doc.display.combScale = 0.4f;
    doc.display.combDensity = 9;
    Offscreen off(640, 480);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 8, 640.0 / 480.0, "top");
    o.display.showCombs = true;
    const Rendered r = off.render(o);
    const ViewMatrices vm = viewMatrices(o.camera, 640.0 / 480.0);
    const double length = 0.4 * 0.02 * modelSize(doc) * modelSize(doc);  // per unit curvature, as documented
    int checked = 0;
    for (int k = 0; k < 9; ++k) {
        const double t = k / 8.0;
        double kappa = 0;
        Vec3 inward;
        circleCurvature(c, t, kappa, inward);
        const Vec3 p = bezier(c, t);
        const auto tip = projectToPixel(vm, p - length * kappa * inward, 640, 480);
        const auto inside = projectToPixel(vm, p + length * kappa * inward, 640, 480);
        const auto base = projectToPixel(vm, p, 640, 480);
        ASSERT_TRUE(tip && inside && base);
        if (glm::length(*tip - *base) < 12.0) continue;  // too short to tell apart
        ++checked;
        EXPECT_TRUE(combColoured(r.image, *tip)) << "tooth " << k << " at pixel " << tip->x << ", " << tip->y;
        EXPECT_FALSE(combColoured(r.image, *inside)) << "tooth " << k << " drawn towards the centre";
    }
    EXPECT_GE(checked, 5);
    // Without combs nothing is there.
    o.display.showCombs = false;
    const Rendered plain = off.render(o);
    EXPECT_GT(countDifferent(r.image, plain.image, 8), 200u);
}

TEST_F(Combs, CurvatureGraphAcrossAJoinDrawsBothWindows) {
    Document doc = makePatchGrid(1, 2, Continuity::C2);
    Offscreen off(320, 240);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 8, 320.0 / 240.0, "iso");
    o.display.showCombs = true;
    const Rendered without = off.render(o);
    o.combJoin = 0;
    const Rendered with = off.render(o);
    EXPECT_EQ(with.stats.draws, without.stats.draws + 4);  // two windows, teeth and envelope
    EXPECT_GT(countDifferent(with.image, without.image, 8), 50u);
}

TEST(CombsCli, CombJoinIsChecked) {
    const auto dir = freshTempDir("combs_cli");
    const RunResult r = runCommand(patchworkBinary().string() + " render '" + (dataDir() / "teapot.bpt").string() + "' -o '" +
                                   (dir / "x.png").string() + "' --comb-join 100000 2>&1");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--comb-join"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
}  // namespace pw::test

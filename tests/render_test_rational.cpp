// Rational patches on the GPU (issue 21), validation on: the tessellated exact sphere (captured
// from the evaluation shader) lies on the sphere to float precision with outward unit normals and
// closes up; weights change the picture; the comb of a rational quarter circle has every tooth the
// same length, so its envelope is the circle of radius R + L/R (L the documented tooth length per
// unit curvature): an independent statement about a circle, no derivative formula involved.
#include <cmath>
#include <map>

#include "core/construct/primitives.hpp"
#include "render_support.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

class Rational : public RenderTest {};

TEST_F(Rational, TheSphereOnTheGpuIsASphere) {
    Document doc;
    addSphere(doc, Vec3(0.0), 1.0, true);
    Offscreen off(320, 240, false);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 16, 320.0 / 240.0, "iso");
    o.tess.cullOffscreen = false;
    const render::CapturedSurface c = off.capture(o);
    EXPECT_EQ(c.gpuTriangles, 8u * 2 * 16 * 16);
    EXPECT_EQ(c.degenerate, 8u * 16);  // the pole rows
    double worstR = 0, worstN = 0;
    for (size_t i = 0; i < c.mesh.positions.size(); ++i) {
        const Vec3 p(c.mesh.positions[i][0], c.mesh.positions[i][1], c.mesh.positions[i][2]);
        const Vec3 n(c.mesh.normals[i][0], c.mesh.normals[i][1], c.mesh.normals[i][2]);
        worstR = std::max(worstR, std::abs(glm::length(p) - 1.0));
        worstN = std::max(worstN, glm::length(n - p / glm::length(p)));
    }
    EXPECT_LT(worstR, 2e-6);  // float evaluation on the GPU
    EXPECT_LT(worstN, 1e-4);
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t t = 0; t + 2 < c.mesh.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = c.mesh.indices[t + size_t(k)], b = c.mesh.indices[t + size_t((k + 1) % 3)];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    size_t unpaired = 0;
    for (const auto& [e, n] : uses) unpaired += n != 2;
    EXPECT_EQ(unpaired, 0u);  // closed
}

TEST_F(Rational, AWeightPullsTheSurface) {
    Document doc;
    addSphere(doc, Vec3(0.0), 1.0, true);
    Offscreen off(200, 150);
    off.setDocument(doc);
    const render::RenderOptions o = plainOptions(doc, 12, 200.0 / 150.0, "front");
    const Rendered round = off.render(o);
    Document heavy = doc;
    setPointWeight(heavy, doc.patches[2].idx[5], 20.0);  // an inner point of the upper front patch
    off.setDocument(heavy);
    const Rendered pulled = off.render(o);
    EXPECT_GT(countDifferent(round.image, pulled.image, 8), 100u);
}

TEST_F(Rational, TheCombOfAQuarterCircleIsAConcentricCircle) {
    const double R = 2.0, k = std::sqrt(2.0), d = 1.0 + k, w = (1.0 + k) / 3.0;
    Document doc;
    // The quadratic arc (R, 0), (R, R), (0, R) of weights 1, 1/√2, 1 raised to a cubic.
    doc.points = {Vec3(R, 0, 0), Vec3(R, k * R / d, 0), Vec3(k * R / d, R, 0), Vec3(0, R, 0), Vec3(-0.5, -0.5, 0), Vec3(3.5, 3.5, 0)};
    doc.weights = {1.0, w, w, 1.0};
    doc.curves.push_back(BezierCurve{{0, 1, 2, 3}, "quarter", false});
    doc.display.showCombs = true;
    doc.display.combScale = 0.5f;
    doc.display.combDensity = 21;
    Offscreen off(480, 480);
    off.setDocument(doc);
    render::RenderOptions o = plainOptions(doc, 8, 1.0, "top");
    o.display.showCombs = true;
    const Rendered r = off.render(o);
    const ViewMatrices vm = viewMatrices(o.camera, 1.0);
    const double L = 0.5 * 0.02 * modelSize(doc) * modelSize(doc), tipRadius = R + L / R;
    int hits = 0, inside = 0;
    for (int a = 10; a <= 80; a += 5) {
        const double t = a * M_PI / 180.0;
        const auto tip = projectToPixel(vm, Vec3(tipRadius * std::cos(t), tipRadius * std::sin(t), 0), 480, 480);
        const auto mid = projectToPixel(vm, Vec3((R + 0.5 * L / R) * std::cos(t), (R + 0.5 * L / R) * std::sin(t), 0), 480, 480);
        ASSERT_TRUE(tip && mid);
        hits += combColoured(r.image, *tip, 1);  // the envelope runs along the circle of the tips
        inside += combColoured(r.image, *mid, 1) ? 1 : 0;
    }
    EXPECT_EQ(hits, 15);
    EXPECT_LT(inside, 8);  // between the curve and the envelope only the teeth themselves
    ASSERT_GT(glm::length(*projectToPixel(vm, Vec3(tipRadius, 0, 0), 480, 480) - *projectToPixel(vm, Vec3(R, 0, 0), 480, 480)), 10.0);
}

}  // namespace
}  // namespace pw::test

// Cubic Bézier curves (isoline domain): evaluation against the explicit Bernstein sum and finite
// differences, exact ends; the .patchwork `curves` field and isoline levels round trip (and files
// without them are written as before); the curve operations share, keep and drop pool points as
// they say; undo restores a deleted curve.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/base/errors.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/model/edit_history.hpp"
#include "core/ops/patch_ops.hpp"
#include "support.hpp"

namespace pw {
namespace {

std::array<Vec3, 4> randomCurve(std::mt19937& rng) {
    std::uniform_real_distribution<double> d(-10.0, 10.0);
    std::array<Vec3, 4> p;
    for (auto& q : p) q = Vec3(d(rng), d(rng), d(rng));
    return p;
}

TEST(BezierCurve, MatchesTheBernsteinSumAndItsDerivative) {
    std::mt19937 rng(7);
    for (int n = 0; n < 50; ++n) {
        const auto p = randomCurve(rng);
        for (int i = 0; i <= 100; ++i) {
            const double t = i / 100.0, s = 1.0 - t;
            const Vec3 want = s * s * s * p[0] + 3.0 * s * s * t * p[1] + 3.0 * s * t * t * p[2] + t * t * t * p[3];
            const Vec3 got = evaluateCurve(p, t);
            for (int a = 0; a < 3; ++a) EXPECT_NEAR(got[a], want[a], 1e-12) << "t " << t;
            if (i > 0 && i < 100) {
                const double h = 1e-6;
                const Vec3 fd = (evaluateCurve(p, t + h) - evaluateCurve(p, t - h)) / (2.0 * h);
                const Vec3 tan = curveTangent(p, t);
                for (int a = 0; a < 3; ++a) EXPECT_NEAR(tan[a], fd[a], 1e-5);
            }
        }
        // The ends are the end points bit for bit (neighbouring curves and patch edges meet).
        EXPECT_EQ(evaluateCurve(p, 0.0), p[0]);
        EXPECT_EQ(evaluateCurve(p, 1.0), p[3]);
        const auto samples = sampleCurve(p, 7);
        ASSERT_EQ(samples.size(), 8u);
        EXPECT_EQ(samples.front(), p[0]);
        EXPECT_EQ(samples.back(), p[3]);
    }
}

TEST(BezierCurve, PatchworkFilesRoundTripCurvesAndIsolineLevels) {
    Document doc = loadBpt(test::dataDir() / "teapot.bpt");
    const std::string before = serializeDocument(doc);
    EXPECT_EQ(before.find("\"curves\""), std::string::npos);  // documents without curves are written as before
    EXPECT_EQ(before.find("\"isoline\""), std::string::npos);
    EXPECT_EQ(before.find("showIsocurves"), std::string::npos);

    addCurve(doc, Vec3(1.0, 2.0, 3.0), 2.0);
    curveFromEdge(doc, 3, Edge::U1);
    doc.tess.isolineLevels = {5.0f, 7.5f};
    doc.display.showIsocurves = true;
    const std::string text = serializeDocument(doc);
    const Document back = parseDocument(text, "curves.patchwork");
    EXPECT_TRUE(back == doc);
    ASSERT_EQ(back.curves.size(), 2u);
    EXPECT_EQ(back.curves[1].name, "patch 3 edge u1");
    EXPECT_EQ(serializeDocument(back), text);
}

TEST(BezierCurve, OperationsShareKeepAndDropPoints) {
    Document doc = loadBpt(test::dataDir() / "teapot.bpt");
    const size_t pool = doc.points.size();
    // A curve on a patch edge uses that edge's points: no new points, and it follows the patch.
    const uint32_t c = curveFromEdge(doc, 0, Edge::V1);
    EXPECT_EQ(doc.points.size(), pool);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(doc.curves[c].idx[size_t(k)], doc.patches[0].idx[size_t(edgeSlot(Edge::V1, k, 0))]);
    const uint32_t a = addCurve(doc, Vec3(0.0), 1.0);
    EXPECT_EQ(doc.points.size(), pool + 4);
    const auto arch = curvePoints(doc, doc.curves[a]);
    EXPECT_NEAR(glm::length(arch[3] - arch[0]), 1.0, 1e-12);  // `size` wide, in the ground plane
    EXPECT_EQ(arch[1].z, 0.0);

    // Deleting the free curve drops its 4 points; deleting the edge curve keeps the patch's.
    EditHistory history;
    Document edited = doc;
    deleteCurve(edited, a);
    EXPECT_EQ(edited.points.size(), pool);
    deleteCurve(edited, 0);
    EXPECT_EQ(edited.points.size(), pool);
    EXPECT_TRUE(edited.curves.empty());
    EXPECT_TRUE(edited.patches == doc.patches);
    EXPECT_THROW(deleteCurve(edited, 0), EditError);
    history.commit(doc, edited, "Delete curves");
    ASSERT_TRUE(history.canUndo());
    history.undo(edited);
    EXPECT_TRUE(edited == doc);

    // Only Bézier patches have boundary curves of their own 4 points.
    EXPECT_THROW(curveFromEdge(doc, 9999, Edge::U0), EditError);
    EXPECT_THROW(formatBpt(doc), InputError);  // .bpt holds rectangular patches only
}

}  // namespace
}  // namespace pw

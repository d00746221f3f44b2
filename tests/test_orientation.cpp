// Whole-model orientation: the tea set imports with outward normals (the teacup's data is inside
// out), and a model turned inside out is turned back with its joins intact.
#include <gtest/gtest.h>

#include "core/eval/patch_eval.hpp"
#include "core/io/bpt_format.hpp"
#include "core/ops/orientation.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"
#include "support.hpp"

using namespace pw;

TEST(Orientation, TeaSetImportsWithOutwardNormals) {
    for (const char* name : {"teapot.bpt", "teacup.bpt", "teaspoon.bpt"}) {
        const Document doc = loadBpt(test::dataDir() / name);
        EXPECT_GT(positionFlux(doc), 0.0) << name;
    }
}

TEST(Orientation, TeacupWallNormalPointsAwayFromItsAxis) {
    // The cup's outer wall (+y up, axis x = z = 0): at the point of largest radius among the
    // samples at mid height, the normal must point away from the axis.
    const Document doc = loadBpt(test::dataDir() / "teacup.bpt");
    double bestR = -1;
    Vec3 bestP{0.0}, bestN{0.0};
    for (const PatchInstance& inst : expandPatches(doc)) {
        const Net16 net = gatherNet(doc, inst.idx);
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                const SurfacePoint sp = evaluateNet(net, inst.basis, inst.tension, j / 8.0, i / 8.0);
                const double r = std::hypot(sp.p.x, sp.p.z);
                if (std::abs(sp.p.y - 0.5) < 0.1 && r > bestR) bestR = r, bestP = sp.p, bestN = sp.n;
            }
    }
    ASSERT_GT(bestR, 0.5);
    EXPECT_GT(bestN.x * bestP.x + bestN.z * bestP.z, 0.5 * bestR);
}

TEST(Orientation, InsideOutModelIsTurnedBackWithJoinsIntact) {
    const Document original = loadBpt(test::dataDir() / "teapot.bpt");
    Document doc = original;
    for (uint32_t p = 0; p < doc.patches.size(); ++p) flipPatch(doc, p);
    ASSERT_LT(positionFlux(doc), 0.0);
    EXPECT_TRUE(orientOutward(doc));
    EXPECT_GT(positionFlux(doc), 0.0);
    EXPECT_FALSE(orientOutward(doc));  // already outward: nothing changes
    EXPECT_EQ(doc.joins.size(), original.joins.size());
    for (const JoinContinuity& jc : continuityReport(doc)) {
        EXPECT_LE(jc.c1Residual, 1e-9) << "join " << jc.join;
        EXPECT_LE(jc.normalAngleDeg, 1e-6) << "join " << jc.join;
    }
    EXPECT_LE(maxConstraintResidual(doc), 1e-9 * modelSize(doc));
}

// Soft selection (issue 40, item 6; core/select/soft_selection, DragController and the transform
// commands): the points around the moved ones follow by the falloff of their distance along the
// control nets and across joins, never through space to an unconnected part, and the joins hold.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/construct/model_builders.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/edit/edit_session.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/soft_selection.hpp"
#include "core/solve/constraint_solver.hpp"
#include "support.hpp"

using namespace pw;

namespace {

// Point (r, c) of makePatchGrid's (3 rows + 1) x (3 cols + 1) lattice.
uint32_t lat(int cols, int r, int c) { return uint32_t(r * (3 * cols + 1) + c); }

}  // namespace

TEST(SoftSelection, FalloffsRunFromOneToZeroAtTheRadius) {
    for (Falloff f : {Falloff::Smooth, Falloff::Linear, Falloff::Sharp, Falloff::Constant}) {
        const SoftSelection s{true, 2.0, f};
        EXPECT_DOUBLE_EQ(falloffWeight(s, 0.0), 1.0) << falloffName(f);
        EXPECT_EQ(falloffWeight(s, 2.0), 0.0) << falloffName(f);
        EXPECT_EQ(falloffWeight(s, 3.0), 0.0) << falloffName(f);
        double last = 1.0;
        for (double d = 0.1; d < 2.0; d += 0.1) {
            const double w = falloffWeight(s, d);
            EXPECT_LE(w, last + 1e-15) << falloffName(f);  // never rises with distance
            EXPECT_GT(w, 0.0) << falloffName(f);
            last = w;
        }
        EXPECT_EQ(parseFalloff(falloffName(f)), f);
    }
    EXPECT_NEAR(falloffWeight({true, 2.0, Falloff::Linear}, 0.5), 0.75, 1e-15);
    EXPECT_NEAR(falloffWeight({true, 2.0, Falloff::Sharp}, 1.0), 0.25, 1e-15);
    EXPECT_NEAR(falloffWeight({true, 2.0, Falloff::Smooth}, 1.0), 0.5, 1e-15);
}

TEST(SoftSelection, AMoveCarriesThePointsAroundAcrossJoinsAndHoldsThem) {
    EditSession s;
    s.doc = makePatchGrid(6, 6, Continuity::C1);
    const Document before = s.doc;
    const uint32_t corner = lat(6, 9, 9);  // a point where four patches meet
    test::runEditScript(s, "soft 2 smooth; select point " + std::to_string(corner) + "; move 0 0 1");
    EXPECT_NEAR(s.doc.points[corner].z - before.points[corner].z, 1.0, 1e-9);
    size_t partly = 0, far = 0;
    for (int r = 0; r <= 18; ++r)
        for (int c = 0; c <= 18; ++c) {
            const uint32_t i = lat(6, r, c);
            const double dz = s.doc.points[i].z - before.points[i].z;
            const double away = std::hypot(r - 9, c - 9) / 3.0;  // model units from the moved point
            if (i != corner && away < 1.5 && dz > 1e-3 && dz < 1.0) ++partly;
            if (away > 3.5 && std::abs(dz) > 1e-12) ++far;
        }
    EXPECT_GT(partly, 20u);  // the neighbourhood rose with it, in four patches and across their joins
    EXPECT_EQ(far, 0u);      // nothing beyond the radius (and the solver's reach) moved
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc));
    // Off again: the same move carries the point alone (and what the joins force).
    EditSession plain;
    plain.doc = before;
    test::runEditScript(plain, "soft 2; soft off; select point " + std::to_string(corner) + "; move 0 0 1");
    EXPECT_LT(std::abs(plain.doc.points[lat(6, 9, 12)].z - before.points[lat(6, 9, 12)].z), 1e-9);
}

TEST(SoftSelection, DistanceRunsAlongTheNetsNotThroughSpace) {
    EditSession s;
    // Two patches 0.2 apart, neither joined nor sharing a point.
    test::runEditScript(s, "cursor 0 0 0; add-patch; cursor 1.2 0 0; add-patch");
    ASSERT_EQ(s.doc.patches.size(), 2u);
    const Document before = s.doc;
    const uint32_t edgePoint = s.doc.patches[0].idx[size_t(edgeSlot(Edge::U1, 1))];
    test::runEditScript(s, "soft 5 linear; select point " + std::to_string(edgePoint) + "; move 0 0 0.5");
    for (uint32_t i : s.doc.patches[1].idx) EXPECT_EQ(s.doc.points[i], before.points[i]);
    size_t moved = 0;
    for (uint32_t i : s.doc.patches[0].idx) moved += s.doc.points[i] != before.points[i] ? 1 : 0;
    EXPECT_EQ(moved, 16u);
}

TEST(SoftSelection, ADragFollowsTheRadiusAndSaysHowFarItReached) {
    Document doc = makePatchGrid(8, 8, Continuity::C1);
    DragView view;
    view.width = 800, view.height = 600;
    view.camera = frameBounds(view.camera, computeBounds(doc.points), 800.0 / 600.0);
    const uint32_t corner = lat(8, 12, 12);
    DragController drag;
    TransformStart start{{corner}, doc.points[corner], TransformKind::Move, true};
    start.soft = SoftSelection{true, 1.0, Falloff::Smooth};
    ASSERT_TRUE(drag.begin(doc, start, view, 400, 300));
    const size_t small = drag.softCount();
    EXPECT_GT(small, 8u);
    drag.setAxis(2);
    ASSERT_TRUE(drag.update(doc, view, 400, 280, false));
    EXPECT_TRUE(drag.projection().ok());
    EXPECT_LE(maxConstraintResidual(doc), 1e-6 * modelSize(doc));
    EXPECT_GT(drag.lastMovedCount(), small / 2);
    EXPECT_NE(drag.status().find("points moved"), std::string::npos) << drag.status();
    EXPECT_NE(drag.status().find("soft 1 smooth"), std::string::npos) << drag.status();
    // The wheel: a larger radius takes more points, and the joins still hold.
    drag.setSoftRadius(doc, 2.5);
    EXPECT_GT(drag.softCount(), 3 * small);
    ASSERT_TRUE(drag.update(doc, view, 400, 270, false));
    EXPECT_TRUE(drag.projection().ok());
    EXPECT_LE(maxConstraintResidual(doc), 1e-6 * modelSize(doc));
    drag.cancel(doc);
}

TEST(SoftSelection, BadSettingsAreRefused) {
    EditSession s;
    for (const char* bad : {"soft", "soft -1", "soft 0", "soft 1 wobbly", "soft nan", "soft 1 smooth extra"}) {
        EXPECT_THROW(test::runEditScript(s, bad), std::exception) << bad;
        EXPECT_FALSE(s.soft.on) << bad;
    }
    test::runEditScript(s, "soft 0.5 sharp");
    EXPECT_EQ(s.soft, (SoftSelection{true, 0.5, Falloff::Sharp}));
    test::runEditScript(s, "soft toggle");
    EXPECT_FALSE(s.soft.on);
}

TEST(SoftSelection, LiveSymmetryMirrorsTheSoftShareToo) {
    EditSession s;
    s.doc = makePatchGrid(2, 6, Continuity::C1);  // x over [0, 6]: the plane x = 3 halves it
    for (Vec3& p : s.doc.points) p.z = 0.0;       // flat, so each point has its mirror image
    const Document before = s.doc;
    const uint32_t left = lat(6, 3, 6);  // x = 2, y = 1
    test::runEditScript(s, "cursor 3 0 0; symmetry X; soft 1.5 linear; select point " + std::to_string(left) + "; move 0 0 0.6");
    // Every point and its mirror image across x = 3 rose alike.
    for (int r = 0; r <= 6; ++r)
        for (int c = 0; c <= 18; ++c) {
            const uint32_t i = lat(6, r, c), m = lat(6, r, 18 - c);
            EXPECT_NEAR(s.doc.points[i].z - before.points[i].z, s.doc.points[m].z - before.points[m].z, 1e-9) << r << " " << c;
        }
    EXPECT_GT(s.doc.points[lat(6, 3, 5)].z - before.points[lat(6, 3, 5)].z, 0.1);  // a soft neighbour rose
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc));
}

TEST(Slide, PointsSlideAlongTheirOwnPolygonOrNormalAndJoinsHold) {
    EditSession s;
    test::runEditScript(s, "add-patch");
    const Vec3 p5 = s.doc.points[5], p10 = s.doc.points[10];
    // Each point along its own u polygon (+x on a flat patch), v polygon (+y) and normal (+z).
    test::runEditScript(s, "select point 5,10; slide u 0.1");
    EXPECT_NEAR(glm::length(s.doc.points[5] - (p5 + Vec3(0.1, 0, 0))), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(s.doc.points[10] - (p10 + Vec3(0.1, 0, 0))), 0.0, 1e-12);
    test::runEditScript(s, "slide n 0.2; slide v -0.05");
    EXPECT_NEAR(glm::length(s.doc.points[5] - (p5 + Vec3(0.1, -0.05, 0.2))), 0.0, 1e-9);
    // On a bent patch the directions differ point by point: a slide is not one translation.
    EditSession bent;
    test::runEditScript(bent, "add-patch; select point 5; move 0 0 0.3");
    const Vec3 b6 = bent.doc.points[6], b9 = bent.doc.points[9];
    test::runEditScript(bent, "select point 6,9; slide n 0.1");
    const Vec3 d6 = bent.doc.points[6] - b6, d9 = bent.doc.points[9] - b9;
    EXPECT_NEAR(glm::length(d6), 0.1, 1e-12);
    EXPECT_NEAR(glm::length(d9), 0.1, 1e-12);
    EXPECT_GT(glm::length(d6 - d9), 1e-3);
    // Across a C1 join the partner follows: the join holds.
    EditSession joined;
    test::runEditScript(joined, "add-patch; extrude u1");
    ASSERT_EQ(joined.doc.joins.size(), 1u);
    const uint32_t tangent = joined.doc.patches[0].idx[size_t(edgeSlot(Edge::U1, 1, 1))];
    const Vec3 before = joined.doc.points[tangent];
    test::runEditScript(joined, "select point " + std::to_string(tangent) + "; slide n 0.25");
    EXPECT_NEAR(joined.doc.points[tangent].z - before.z, 0.25, 1e-9);
    EXPECT_LE(maxConstraintResidual(joined.doc), 1e-9 * modelSize(joined.doc));
    // A curve's point has no polygon in u and v to slide along; bad axes are refused.
    EditSession curve;
    test::runEditScript(curve, "add-curve");
    EXPECT_THROW(test::runEditScript(curve, "select point 1; slide u 0.1"), std::exception);
    EXPECT_THROW(test::runEditScript(s, "select point 5; slide w 0.1"), std::exception);
    EXPECT_THROW(test::runEditScript(s, "select none; slide u 0.1"), std::exception);
}

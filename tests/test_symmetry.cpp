// Live symmetry: with `symmetry X|Y|Z` on, transforms (script commands, G / R / S drags, the
// Inspector's typed point) move each point's mirror partner to its mirror image, points on the
// plane stay on it, the joins hold; with it off the other side stays where it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/edit/drag_controller.hpp"
#include "core/edit/edit_session.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/symmetry.hpp"
#include "core/solve/constraint_solver.hpp"
#include "support.hpp"

using namespace pw;

namespace {

// A flat patch mirrored across x = 0.5 (its right edge) and joined C1 there; symmetry X on.
EditSession mirroredPair() {
    EditSession s;
    test::runEditScript(s, "add-patch; cursor 0.5 0 0; select patch 0; mirror X; symmetry X");
    return s;
}

// Every used point has its mirror image in the pool.
void expectSymmetric(const Document& doc, double offset) {
    for (const Vec3& p : doc.points) {
        Vec3 m = p;
        m.x = 2.0 * offset - p.x;
        double best = 1e9;
        for (const Vec3& q : doc.points) best = std::min(best, glm::length(q - m));
        EXPECT_LT(best, 1e-9) << p.x << " " << p.y << " " << p.z;
    }
}

uint32_t interiorPoint(const EditSession& s) { return s.doc.patches[0].idx[5]; }
uint32_t planePoint(const EditSession& s) { return s.doc.patches[0].idx[7]; }  // on patch 0's u1 edge, x = 0.5

}  // namespace

TEST(Symmetry, PairsFindMirrorPartnersAndPlanePoints) {
    EditSession s = mirroredPair();
    ASSERT_EQ(s.doc.patches.size(), 2u);
    ASSERT_EQ(s.doc.joins.size(), 1u);
    EXPECT_EQ(s.symmetry, (Symmetry{0, 0.5}));
    const SymmetryPairs pairs = symmetryPairs(s.doc, {interiorPoint(s), planePoint(s)}, s.symmetry);
    ASSERT_EQ(pairs.partners.size(), 1u);
    EXPECT_EQ(pairs.onPlane, std::vector<uint32_t>{planePoint(s)});
    const Vec3 p = s.doc.points[interiorPoint(s)], q = s.doc.points[pairs.partners[0].second];
    EXPECT_DOUBLE_EQ(q.x, 1.0 - p.x);
    EXPECT_EQ(pairs.driven({interiorPoint(s)}).size(), 2u);
    EXPECT_TRUE(symmetryPairs(s.doc, {interiorPoint(s)}, Symmetry{}).partners.empty());
}

TEST(Symmetry, ScriptTransformsMirrorToTheOtherSide) {
    EditSession s = mirroredPair();
    test::runEditScript(s, "select point " + std::to_string(interiorPoint(s)) + "; move 0.1 0.2 0.3; rotate Z 20; scale 1.3");
    expectSymmetric(s.doc, 0.5);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9);
    // A point on the plane moved across it stays on it.
    test::runEditScript(s, "select point " + std::to_string(planePoint(s)) + "; move 0.4 0 0.2");
    EXPECT_NEAR(s.doc.points[planePoint(s)].x, 0.5, 1e-12);
    EXPECT_NEAR(s.doc.points[planePoint(s)].z, 0.2, 1e-12);
    expectSymmetric(s.doc, 0.5);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9);
    // Off: the other side stays.
    const std::vector<Vec3> before = s.doc.points;
    test::runEditScript(s, "symmetry off; select point " + std::to_string(interiorPoint(s)) + "; move 0 0 0.5");
    size_t changed = 0;
    for (size_t i = 0; i < before.size(); ++i) changed += before[i] != s.doc.points[i];
    EXPECT_EQ(changed, 1u);  // only the point: it is in no join's rows
}

TEST(Symmetry, DragsAndTypedPointsMirrorToo) {
    EditSession s = mirroredPair();
    DragView view;
    view.camera.target = {0.5, 0.0, 0.0};
    view.camera.distance = 6.0;
    view.camera.pitchDeg = 89.0;
    view.width = 800, view.height = 600;
    const uint32_t p = interiorPoint(s);
    TransformStart start{{p}, s.doc.points[p], TransformKind::Move, true, SnapTarget::Grid, s.symmetry};
    const auto px = *projectToPixel(viewMatrices(view.camera, 800.0 / 600.0), s.doc.points[p], 800, 600);
    DragController drag;
    ASSERT_TRUE(drag.begin(s.doc, start, view, px.x, px.y));
    drag.setAxis(1);
    ASSERT_TRUE(drag.update(s.doc, view, px.x + 10.0, px.y - 40.0, false));
    EXPECT_GT(glm::length(drag.lastOffset()), 0.01);
    expectSymmetric(s.doc, 0.5);
    drag.finish(s);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9);

    HeldPointEdit edit;
    EXPECT_EQ(edit.set(s, p, s.doc.points[p] + Vec3(0.0, 0.0, 0.7)), "");
    expectSymmetric(s.doc, 0.5);
}

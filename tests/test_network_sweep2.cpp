// Curve networks (Gordon surfaces), sweeps along two rails and lofts that leave a patch edge G1
// (issue 39, core/construct/network_net.cpp, sweep_nets.cpp, construction_nets.cpp): each curve
// reproduced, liveness through the commands, the file round trip and refused bad inputs.
#include <gtest/gtest.h>

#include <cmath>

#include "core/construct/constructions.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/solve/constraint_solver.hpp"
#include "support.hpp"

using namespace pw;

namespace {

Vec3 surfaceAt(const Document& d, uint32_t p, double u, double v) { return test::patchPointAt(d, p, u, v); }
Vec3 curveAt(const Document& d, const BezierCurve& c, size_t s, double t) { return test::curvePointAt(d, c, s, t); }

// 3 U curves along X (at y = 0, 2, 4) and 3 V curves along Y (x = 0, 2, 4), the V curves drawn
// backwards and the middle one through a raised point: a 2 x 2 network.
const char* const kNetwork =
    "curve-through 0,0,0 2,0,0.5 4,0,0; curve-through 0,2,0.5 2,2,1.5 4,2,0.5; curve-through 0,4,0 2,4,0.5 4,4,0; "
    "curve-through 0,4,0 0,2,0.5 0,0,0; curve-through 2,4,0.5 2,2,1.5 2,0,0.5; curve-through 4,4,0 4,2,0.5 4,0,0";

}  // namespace

TEST(Network, InterpolatesEveryCurveOneCellAPatch) {
    EditSession s;
    test::runEditScript(s, std::string(kNetwork) + "; network c0 c1 c2 / c3 c4 c5");
    const Document& d = s.doc;
    ASSERT_EQ(d.constructions.size(), 1u);
    const Construction& k = d.constructions[0];
    ASSERT_EQ(k.patches.size(), 4u);
    EXPECT_EQ(d.joins.size(), 4u);
    // U curve r at v = 0 of patch row r (v = 1 of the row below for the last); V curve l along u.
    for (size_t r = 0; r < 3; ++r)
        for (size_t seg = 0; seg < 2; ++seg)
            for (double t : {0.0, 0.25, 0.6, 1.0}) {
                const uint32_t p = k.patches[std::min<size_t>(r, 1) * 2 + seg];
                EXPECT_LT(glm::length(surfaceAt(d, p, t, r < 2 ? 0.0 : 1.0) - curveAt(d, d.curves[r], seg, t)), 1e-12) << r;
            }
    for (size_t l = 0; l < 3; ++l)  // V curves run backwards (from y = 4): segment 1 - row, parameter 1 - t
        for (size_t row = 0; row < 2; ++row)
            for (double t : {0.0, 0.3, 1.0}) {
                const uint32_t p = k.patches[row * 2 + std::min<size_t>(l, 1)];
                EXPECT_LT(glm::length(surfaceAt(d, p, l < 2 ? 0.0 : 1.0, t) - curveAt(d, d.curves[3 + l], 1 - row, 1.0 - t)), 1e-12) << l;
            }
    // The meeting points became one point each: the V curves use the U curves' points there.
    EXPECT_EQ(d.curves[4].idx[3], d.curves[1].idx[3]);
    EXPECT_EQ(d.points.size(), 6u * 7u - 9u + 4u * 4u);  // the curves' points, less the 9 merged, and 4 inner a cell
}

TEST(Network, FollowsAMeetingPointDraggedThroughBothCurves) {
    EditSession s;
    test::runEditScript(s, std::string(kNetwork) + "; network c0 c1 c2 / c3 c4 c5");
    const uint32_t centre = s.doc.curves[1].idx[3];
    test::runEditScript(s, "select point " + std::to_string(centre) + "; move 0 0 1");
    const Document& d = s.doc;
    EXPECT_TRUE(d.constructions[0].error.empty()) << d.constructions[0].error;
    EXPECT_LT(glm::length(d.points[centre] - Vec3(2, 2, 2.5)), 1e-12);
    EXPECT_LT(glm::length(surfaceAt(d, d.constructions[0].patches[0], 1.0, 1.0) - Vec3(2, 2, 2.5)), 1e-12);
    // Both curves through it keep passing through the surface.
    for (double t : {0.2, 0.7}) {
        EXPECT_LT(glm::length(surfaceAt(d, d.constructions[0].patches[2], t, 0.0) - curveAt(d, d.curves[1], 0, t)), 1e-12);
        EXPECT_LT(glm::length(surfaceAt(d, d.constructions[0].patches[1], 0.0, t) - curveAt(d, d.curves[4], 1, 1.0 - t)), 1e-12);
    }
    EXPECT_LE(maxConstraintResidual(d), 1e-9 * modelSize(d));
    // And it survives the file round trip, live.
    const Document back = parseDocument(serializeDocument(d), "n.patchwork");
    EXPECT_EQ(back, d);
}

TEST(Network, IncompatibleNetworksAreRefusedAndChangeNothing) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"network c0 c1 c2 c3 c4 c5", "/"},
        {"network c0 / c3 c4 c5", "at least 2"},
        {"network c0 c1 / c3 c4 c6", "segments"},        // c6 has 1 segment, the U curves ask 2
        {"network c0 c1 c2 / c3 c4 c7", "do not meet"},  // c7 runs beside the network
    };
    for (const auto& [line, why] : cases) {
        EditSession s;
        test::runEditScript(s, std::string(kNetwork) + "; curve-through 0,0,0 0,4,0; curve-through 5,4,0 5,2,0.5 5,0,0");
        const Document before = s.doc;
        try {
            test::runEditScript(s, line);
            ADD_FAILURE() << line << " was accepted";
        } catch (const std::exception& e) {
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << line << ": " << e.what();
        }
        EXPECT_EQ(s.doc, before) << line;
    }
}

TEST(Sweep2, HoldsBothRailsAndSpansThemWithTheProfile) {
    EditSession s;
    // Two rails of two segments and an arch between their starts.
    test::runEditScript(s,
                        "curve-through 0,0,0 2,0,0.4 4,0,0; curve-through 0,3,0 2,4,0 4,3,0.5; curve-through 0,0,0 0,1.5,1 0,3,0; "
                        "sweep2 c0 c1 c2");
    const Document& d = s.doc;
    ASSERT_EQ(d.constructions.size(), 1u);
    const Construction& k = d.constructions[0];
    ASSERT_EQ(k.patches.size(), 2u * 2u);  // 2 rail segments x 2 profile segments
    for (size_t seg = 0; seg < 2; ++seg)
        for (double t : {0.0, 0.4, 1.0}) {
            EXPECT_LT(glm::length(surfaceAt(d, k.patches[seg * 2], 0.0, t) - curveAt(d, d.curves[0], seg, t)), 1e-12);
            EXPECT_LT(glm::length(surfaceAt(d, k.patches[seg * 2 + 1], 1.0, t) - curveAt(d, d.curves[1], seg, t)), 1e-12);
        }
    // At the rails' start the section is the profile itself; at their middle it spans them, scaled
    // by the distance between the rails and keeping the profile's height relative to its width.
    for (double u : {0.0, 0.5, 1.0}) EXPECT_LT(glm::length(surfaceAt(d, k.patches[0], u, 0.0) - curveAt(d, d.curves[2], 0, u)), 1e-12);
    const Vec3 a = d.points[d.curves[0].idx[3]], b = d.points[d.curves[1].idx[3]];
    const Vec3 top = surfaceAt(d, k.patches[2], 1.0, 0.0);  // profile's middle point at the rails' middle
    const double scale = glm::length(b - a) / 3.0;
    EXPECT_NEAR(glm::length(top - a), scale * glm::length(Vec3(0, 1.5, 1)), 1e-9);
    // Live: a rail point moves, the surface keeps the rail.
    test::runEditScript(s, "select point " + std::to_string(s.doc.curves[1].idx[2]) + "; move 0 0.5 0.5");
    EXPECT_LT(glm::length(surfaceAt(s.doc, s.doc.constructions[0].patches[1], 1.0, 0.5) - curveAt(s.doc, s.doc.curves[1], 0, 0.5)), 1e-12);
    // Rails of different segment counts, a closed profile: refused with the reason.
    EditSession bad;
    test::runEditScript(bad, "curve-through 0,0,0 4,0,0; curve-through 0,3,0 2,4,0 4,3,0; add-circle 1; curve-through 0,3,0 4,3,0");
    EXPECT_THROW(test::runEditScript(bad, "sweep2 c0 c1 c2"), std::exception);
    EXPECT_THROW(test::runEditScript(bad, "sweep2 c0 c3 c2"), std::exception);
}

TEST(Loft, G1EndsLeaveAPatchEdgeAlongItsTangent) {
    EditSession s;
    // A patch, then two open arcs above its far edge: the loft starts at the edge, G1.
    test::runEditScript(s, "add-patch");
    const Vec3 e0 = s.doc.points[s.doc.patches[0].idx[size_t(edgeSlot(Edge::V1, 0))]];
    const Vec3 e3 = s.doc.points[s.doc.patches[0].idx[size_t(edgeSlot(Edge::V1, 3))]];
    const auto pt = [](const Vec3& p) { return std::to_string(p.x) + "," + std::to_string(p.y) + "," + std::to_string(p.z); };
    const Vec3 up(0, 0, 1), ahead = glm::normalize(glm::cross(up, e3 - e0));  // outward, past the edge
    test::runEditScript(s, "curve-control " + pt(e0 + ahead + up) + " " + pt(glm::mix(e0, e3, 1 / 3.0) + ahead + 1.3 * up) + " " +
                               pt(glm::mix(e0, e3, 2 / 3.0) + ahead + 1.3 * up) + " " + pt(e3 + ahead + up));
    test::runEditScript(s, "loft 0:v1 c0 start=G1");
    const Document& d = s.doc;
    ASSERT_EQ(d.constructions.size(), 1u);
    ASSERT_EQ(d.joins.size(), 1u);
    EXPECT_EQ(d.joins[0].continuity, Continuity::G1);
    EXPECT_LE(maxConstraintResidual(d), 1e-9 * modelSize(d));
    // The patch is moved: the loft still leaves its edge G1 (the made points are fixed, so the solver
    // could not have made up for it).
    test::runEditScript(s, "select patch 0; rotate X 15");
    EXPECT_TRUE(s.doc.constructions[0].error.empty()) << s.doc.constructions[0].error;
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc));
    // G2: a third section; the join holds curvature too, also after the patch moves.
    EditSession g2;
    test::runEditScript(g2, "add-patch");
    const auto across = [&](double lift, double ahead2) {
        std::string w = "curve-control";
        for (double f : {0.0, 1 / 3.0, 2 / 3.0, 1.0})
            w += " " + pt(glm::mix(e0, e3, f) + ahead2 * ahead + (lift + (f > 0 && f < 1 ? 0.3 : 0.0)) * up);
        return w;
    };
    test::runEditScript(g2, across(1.0, 1.0) + "; " + across(1.5, 2.0));
    EXPECT_THROW(test::runEditScript(g2, "loft 0:v1 c0 start=G2"), std::exception);  // 2 sections: the end span is all there is
    test::runEditScript(g2, "loft 0:v1 c0 c1 start=G2");
    ASSERT_EQ(g2.doc.joins.size(), 2u);  // to the patch, and between the loft's two rows
    EXPECT_EQ(g2.doc.joins[1].patchA, 0u);
    EXPECT_EQ(g2.doc.joins[1].continuity, Continuity::G2);
    EXPECT_LE(maxConstraintResidual(g2.doc), 1e-9 * modelSize(g2.doc));
    test::runEditScript(g2, "select patch 0; rotate X 10");
    EXPECT_TRUE(g2.doc.constructions[0].error.empty()) << g2.doc.constructions[0].error;
    EXPECT_LE(maxConstraintResidual(g2.doc), 1e-9 * modelSize(g2.doc));
    // The file keeps the ends.
    EXPECT_EQ(parseDocument(serializeDocument(g2.doc), "l.patchwork"), g2.doc);
    // start=G1 on a curve section is refused.
    EditSession bad;
    test::runEditScript(bad, "add-circle 1; cursor 0 0 1; add-circle 1");
    EXPECT_THROW(test::runEditScript(bad, "loft c0 c1 start=G1"), std::exception);
    EXPECT_THROW(test::runEditScript(bad, "loft c0 c1 end=G3"), std::exception);
}

TEST(CurvePoints, InsertKeepsTheShapeAndRemoveUndoesIt) {
    EditSession s;
    test::runEditScript(s, "curve-through 0,0,0 1,1,0 3,0,1 4,2,0; add-arc 1 135");
    const Document before = s.doc;
    const auto at = [](const Document& d, size_t c, size_t seg, double t) { return curveAt(d, d.curves[c], seg, t); };
    test::runEditScript(s, "curve-insert c0 1.4; curve-insert c1 0.3");
    ASSERT_EQ(curveSegmentCount(s.doc.curves[0]), 4u);
    ASSERT_EQ(curveSegmentCount(s.doc.curves[1]), 3u);
    for (double t : {0.0, 0.1, 0.25, 0.4}) {  // the split segment's halves trace the old one
        EXPECT_LT(glm::length(at(s.doc, 0, 1, t / 0.4) - at(before, 0, 1, t)), 1e-12) << t;
        EXPECT_LT(glm::length(at(s.doc, 1, 0, t / 0.3 > 1 ? 1 : t / 0.3) - at(before, 1, 0, std::min(t, 0.3))), 1e-12) << t;
    }
    for (double t : {0.5, 0.8, 1.0}) {
        EXPECT_LT(glm::length(at(s.doc, 0, 2, (t - 0.4) / 0.6) - at(before, 0, 1, t)), 1e-12) << t;
        EXPECT_NEAR(glm::length(at(s.doc, 1, 1, (t - 0.3) / 0.7) - Vec3(0.0)), 1.0, 1e-12) << t;  // still the exact arc
    }
    // Removing the inserted points gives the curves back.
    test::runEditScript(s, "curve-remove c0 2; curve-remove c1 1");
    ASSERT_EQ(curveSegmentCount(s.doc.curves[0]), 3u);
    for (size_t c = 0; c < 2; ++c)
        for (size_t seg = 0; seg < curveSegmentCount(before.curves[c]); ++seg)
            for (double t : {0.2, 0.5, 0.9}) EXPECT_LT(glm::length(at(s.doc, c, seg, t) - at(before, c, seg, t)), 1e-9) << c << " " << seg;
    EXPECT_EQ(s.doc.points.size(), before.points.size());
    // Bad positions are refused, changing nothing.
    const Document now = s.doc;
    for (const char* bad : {"curve-insert c0 1", "curve-insert c0 3.5", "curve-remove c0 0", "curve-remove c0 3", "curve-remove c5 1",
                            "curve-remove 0:u0 1"}) {
        EXPECT_THROW(test::runEditScript(s, bad), std::exception) << bad;
        EXPECT_EQ(s.doc, now) << bad;
    }
}

TEST(CurvePoints, AnAnchorCarriesItsHandles) {
    EditSession s;
    test::runEditScript(s, "curve-through 0,0,0 1,1,0 3,0,1 4,2,0; add-circle 1; add-patch; select patch 0; curve-from-edge");
    const std::vector<uint32_t>& c = s.doc.curves[0].idx;
    EXPECT_EQ(withCurveHandles(s.doc, {c[3]}), (std::vector<uint32_t>{c[2], c[3], c[4]}));
    EXPECT_EQ(withCurveHandles(s.doc, {c[0]}), (std::vector<uint32_t>{c[0], c[1]}));
    EXPECT_EQ(withCurveHandles(s.doc, {c[4]}), (std::vector<uint32_t>{c[4]}));  // a handle moves alone
    const std::vector<uint32_t>& ring = s.doc.curves[1].idx;                    // closed: the start has a handle on each side
    EXPECT_EQ(withCurveHandles(s.doc, {ring[0]}), (std::vector<uint32_t>{ring[0], ring[1], ring[11]}));
    // A curve on a patch's edge shares the patch's points: its corners move alone.
    ASSERT_EQ(s.doc.curves.size(), 3u);
    const uint32_t corner = s.doc.curves[2].idx[0];
    EXPECT_EQ(withCurveHandles(s.doc, {corner}), (std::vector<uint32_t>{corner}));
}

TEST(CurvePoints, InsertingIntoACurveOnAPatchEdgeLeavesThePatch) {
    EditSession s;
    test::runEditScript(s, "add-patch; select patch 0; curve-from-edge");
    const Net16 before = gatherNet(s.doc, s.doc.patches[0].idx);
    test::runEditScript(s, "curve-insert c0 0.5");
    EXPECT_EQ(curveSegmentCount(s.doc.curves[0]), 2u);
    EXPECT_EQ(gatherNet(s.doc, s.doc.patches[0].idx), before);
    // A merge of a point whose handles are retracted: a finite cubic, not a refusal.
    EditSession r;
    test::runEditScript(r, "curve-control 0,0,0 1,0,0 2,1,0 3,0,0 4,0,0");
    const uint32_t joint = r.doc.curves[0].idx[3];
    const Vec3 at = r.doc.points[joint];
    r.doc.points[r.doc.curves[0].idx[2]] = at;  // both legs of the joint retracted onto it
    r.doc.points[r.doc.curves[0].idx[4]] = at;
    test::runEditScript(r, "curve-remove c0 1");
    for (const uint32_t i : r.doc.curves[0].idx)
        for (int a = 0; a < 3; ++a) EXPECT_TRUE(std::isfinite(r.doc.points[i][a]));
}

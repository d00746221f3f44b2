// Issue 40's corners and fills (core/solve/sheared_joins, core/ops/corner_ops, core/ops/fill_hole):
// three patches at a corner end G1 on every seam (the seams lean along their edges near it), a
// 3-, 5- or 6-sided hole fills G1 to its surroundings (sides may be curves), and both stay within 0.1° (and the solver's
// residual) while their points and neighbours are dragged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>

#include "core/commands/command_table.hpp"
#include "core/construct/model_builders.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/eval/fold_check.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/model/camera_math.hpp"
#include "core/model/topology.hpp"
#include "core/ops/fill_hole.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"
#include "core/solve/sheared_joins.hpp"
#include "ring_fixtures.hpp"
#include "support.hpp"

using namespace pw;
using namespace pw::rings;

namespace {

// n patches around the pole of the unit sphere, each a quad (pole, middle, corner, middle) pushed
// onto the sphere: the corner a modeller meets at the top of a dome. n = 3 with these angles is the
// newcomer's rounded box corner (a third of a sphere octant). The .bpt reader joins the seams C0.
Document fanDome(int n) {
    std::string text = std::to_string(n) + "\n";
    const double a = 2 * std::numbers::pi / n;
    for (int k = 0; k < n; ++k) {
        const Vec3 q[4] = {Vec3(0, 0, 1), onSphere(0.6, k * a), onSphere(0.9, (k + 0.5) * a), onSphere(0.6, ((k + 1) % n) * a)};
        text += bptPatch([&](double u, double v) { return glm::normalize(bilinear(q, u, v)); }, bilinear(q, 0.5, 0.5));
    }
    return parseBpt(text, "dome.bpt");
}

}  // namespace

TEST(ShearedJoins, FitRecoversTheShearOfAnExactlyLeaningSeam) {
    // Two flat patches whose cross tangents lean along the seam by β(t) = 0.3 (1−t)²: the plain
    // rows fail, the fit finds α = 1 and the shear, and the rows then hold to rounding.
    Document d = parseBpt("2\n" + bptPatch([](double u, double v) { return Vec3(-1 + u, v, 0); }, Vec3(0, 0, 1)) +
                              bptPatch([](double u, double v) { return Vec3(u, v, 0); }, Vec3(0, 0, 1)),
                          "two.bpt");
    ASSERT_EQ(d.joins.size(), 1u);
    Join& j = d.joins[0];
    // Lean the seam by β(t) = 0.3 (1−t)²: the solver moves the points onto the sheared rows.
    j.continuity = Continuity::G1;
    j.shear = {0.3, 0.0, 0.0};
    ASSERT_TRUE(projectConstraints(d, {}).ok());
    EXPECT_LE(maxConstraintResidual(d), 1e-9);
    const auto fit = fitShear(d, j);
    ASSERT_TRUE(fit.has_value());
    EXPECT_NEAR(fit->alpha, j.alpha, 1e-9);
    EXPECT_NEAR(fit->shear[0], 0.3, 1e-9);
    EXPECT_NEAR(fit->shear[1], 0.0, 1e-9);
    EXPECT_NEAR(fit->shear[2], 0.0, 1e-9);
    // Saved and read back with the join.
    const Document back = parseDocument(serializeDocument(d), "back.patchwork");
    EXPECT_EQ(back.joins[0].shear, j.shear);
}

TEST(Corners, TheNewcomersThreePatchCornerEndsG1OnAllThreeSeams) {
    EditSession s;
    s.doc = fanDome(3);
    ASSERT_EQ(s.doc.joins.size(), 3u);
    const std::string said = joinAllG1(s);
    EXPECT_NE(said.find("corner of 3 patches"), std::string::npos) << said;
    EXPECT_NE(said.find("held G1, its 3 seams"), std::string::npos) << said;
    ASSERT_EQ(s.doc.joins.size(), 3u);  // three patches need no split
    for (const Join& j : s.doc.joins) {
        EXPECT_EQ(j.continuity, Continuity::G1);
        EXPECT_TRUE(hasShear(j));
    }
    expectG1(s.doc, "after joining");
    // Drag the corner point, a point next to it and a far corner: every seam holds.
    const uint32_t centre = s.doc.patches[0].idx[0], near = s.doc.patches[1].idx[5], far = s.doc.patches[2].idx[15];
    for (const auto& [pt, move] : {std::pair{centre, "0.05 0.02 -0.03"}, {near, "0.02 -0.04 0.03"}, {far, "-0.1 0.05 0.02"}}) {
        test::runEditScript(s, "select point " + std::to_string(pt) + "; move " + move);
        expectG1(s.doc, "after moving point " + std::to_string(pt));
    }
    // Saved and reopened, the corner is the same joins.
    const Document back = parseDocument(serializeDocument(s.doc), "corner.patchwork");
    EXPECT_EQ(back.joins, s.doc.joins);
}

TEST(Corners, FiveAndSixPatchCornersAreSplitAndHeldG1) {
    for (int n : {5, 6}) {
        SCOPED_TRACE("n = " + std::to_string(n));
        EditSession s;
        s.doc = fanDome(n);
        const std::string said = joinAllG1(s);
        EXPECT_NE(said.find("corner of " + std::to_string(n) + " patches"), std::string::npos) << said;
        EXPECT_NE(said.find("split its " + std::to_string(n) + " patches 2×2"), std::string::npos) << said;
        EXPECT_EQ(s.doc.patches.size(), size_t(4 * n));
        expectG1(s.doc, "after joining");
        const uint32_t pole = s.doc.patches[0].idx[0], rim = s.doc.patches[1].idx[15];
        test::runEditScript(s, "select point " + std::to_string(pole) + "; move 0.03 -0.02 0.05");
        expectG1(s.doc, "after moving the corner");
        test::runEditScript(s, "select point " + std::to_string(rim) + "; move 0 0 -0.1");
        expectG1(s.doc, "after moving a rim point");
        // Flipping a patch whose edge a leaning seam runs along turns the seam's α and β round
        // with it (β(t) → −β(1 − t)): no point moves, and the rows still hold.
        size_t flips = 0;
        for (const Join& j : s.doc.joins) {
            if (!hasShear(j) || (j.edgeA != Edge::V0 && j.edgeA != Edge::V1)) continue;
            Document flipped = s.doc;
            flipPatch(flipped, j.patchA);
            EXPECT_LE(maxConstraintResidual(flipped), 1e-9 * modelSize(s.doc)) << "patch " << j.patchA;
            ++flips;
        }
        EXPECT_GT(flips, 0u);
    }
}

// data/rounded_box.pwscript up to (not including) its last `fill-hole`, and that command.
std::pair<std::string, std::string> roundedBoxScript() {
    const std::string text = test::readBytes(test::dataDir() / "rounded_box.pwscript");
    const size_t last = text.rfind("fill-hole");
    const size_t end = text.find('\n', last);
    return {text.substr(0, last), text.substr(last, end - last)};
}

TEST(FillHole, ABoxCornerFillsG1AndHoldsWhileItsPointsAndNeighboursMove) {
    EditSession s;
    const auto [before, fill] = roundedBoxScript();
    test::runEditScript(s, before);
    const Document open = s.doc;
    Recorder host;
    runCommandLine(s, host, fill);
    EXPECT_NE(host.last.find("filled a 3-sided hole with 3 patches"), std::string::npos) << host.last;
    EXPECT_NE(host.last.find("corner of 3 patches"), std::string::npos) << host.last;
    ASSERT_EQ(s.doc.patches.size(), open.patches.size() + 3);
    expectG1(s.doc, "after filling");
    // The fill's centre, a point beside it, a point of the blend it meets and a face corner.
    const uint32_t fillFirst = uint32_t(open.patches.size());
    const uint32_t centre = s.doc.patches[fillFirst].idx[15], inner = s.doc.patches[fillFirst + 1].idx[10];
    const uint32_t blend = s.doc.patches[6].idx[5], face = s.doc.patches[0].idx[0];
    for (const auto& [pt, move] :
         {std::pair{centre, "0.04 0.03 -0.05"}, {inner, "-0.03 0.02 0.04"}, {blend, "0.05 0 0.05"}, {face, "0 0 0.1"}}) {
        test::runEditScript(s, "select point " + std::to_string(pt) + "; move " + move);
        expectG1(s.doc, "after moving point " + std::to_string(pt));
    }
    // Undo takes the moves and the fill back: the hole is open again, exactly as it was.
    test::runEditScript(s, "undo; undo; undo; undo; undo");
    EXPECT_EQ(s.doc, open);
}

// A 5-sided hole in a ring bent 0.6 of widths 1 : 1.4 whose seams were made G1 one by one: each
// side's two ends ask ratios up to 1.5 times apart, more than a fitted side bends within 0.1°, so
// the fill is refused naming the sides, their ratios and the seam past 0.1°, and nothing changes
// (DESIGN §14: what a fill needs).
TEST(FillHole, AHoleWhoseSidesRatiosDisagreeIsRefusedSayingWhatToMatch) {
    EditSession s;
    s.doc = planarRing(5, 0.6, 1.4);
    joinAllG1(s);
    const Document before = s.doc;
    try {
        test::runEditScript(s, "fill-hole" + ringHoleSides(s.doc, 5));
        FAIL() << "a fill past 0.1° was accepted";
    } catch (const std::exception& e) {
        const std::string why = e.what();
        // Which sides, numbered as given, and the ratios their two ends ask for.
        EXPECT_NE(why.find("side 1 (0:"), std::string::npos) << why;
        EXPECT_NE(why.find(" at its corner with side "), std::string::npos) << why;
        EXPECT_NE(why.find("beyond the 0.1° a fitted seam keeps; make those seams match, or fill a smaller hole"), std::string::npos)
            << why;
    }
    EXPECT_EQ(s.doc, before);
}

TEST(FillHole, BadHolesAreRefusedAndChangeNothing) {
    EditSession s;
    s.doc = planarRing(3);
    const Document before = s.doc;
    for (const char* bad : {"fill-hole 0:v0 2:v0", "fill-hole 0:v0 2:v0 0:v1", "fill-hole 0:v0 2:v0 1:u0", "fill-hole 0:v0 2:v0 c0",
                            "fill-hole 0:v0 2:v0 9:v0"}) {
        SCOPED_TRACE(bad);
        EXPECT_THROW(test::runEditScript(s, bad), std::exception);
        EXPECT_EQ(s.doc, before);
    }
}

namespace {

std::string xyz(const Vec3& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", p.x, p.y, p.z);
    return buf;
}

// Every fill patch edge that lies on curve c (its points the curve's own, by index) is the curve.
size_t fillEdgesOnCurve(const Document& d, uint32_t firstFill, uint32_t c) {
    const BezierCurve& curve = d.curves[c];
    size_t n = 0;
    for (uint32_t p = firstFill; p < d.patches.size(); ++p)
        for (Edge e : {Edge::U0, Edge::V0, Edge::U1, Edge::V1})
            for (size_t s = 0; s < curveSegmentCount(curve); ++s) {
                const auto seg = curveSegment(curve, s);
                bool forward = true, backward = true;
                for (int k = 0; k < 4; ++k) {
                    const uint32_t q = d.patches[p].idx[size_t(edgeSlot(e, k))];
                    forward = forward && q == seg[size_t(k)];
                    backward = backward && q == seg[size_t(3 - k)];
                }
                n += forward || backward ? 1 : 0;
            }
    return n;
}

}  // namespace

// Issue 40, item 2: a side may be a curve (cN). Four curves bound a hole: the fill is four patches
// G1 to each other, whose outer edges are the curves' own points (each curve split at its middle),
// so moving a curve point moves the fill's edge with it, and the seams hold.
TEST(FillHole, FourCurvesBoundAFillThatSharesTheirPoints) {
    EditSession s;
    Recorder host;
    runCommandLine(s, host, "curve-control 0,0,0 0.33,0,0.2 0.67,0,0.2 1,0,0");
    runCommandLine(s, host, "curve-control 1,0,0 1,0.33,-0.1 1,0.67,-0.1 1,1,0");
    runCommandLine(s, host, "curve-control 1,1,0 0.67,1,0.2 0.33,1,0.2 0,1,0");
    runCommandLine(s, host, "curve-control 0,1,0 0,0.67,-0.1 0,0.33,-0.1 0,0,0");
    const std::array<Vec3, 4> before{s.doc.points[s.doc.curves[0].idx[0]], s.doc.points[s.doc.curves[0].idx[1]],
                                     s.doc.points[s.doc.curves[0].idx[2]], s.doc.points[s.doc.curves[0].idx[3]]};
    runCommandLine(s, host, "fill-hole c0 c1 c2 c3");
    EXPECT_NE(host.last.find("filled a 4-sided hole with 4 patches"), std::string::npos) << host.last;
    EXPECT_NE(host.last.find("through the points of its 4 curves"), std::string::npos) << host.last;
    ASSERT_EQ(s.doc.patches.size(), 4u);
    expectG1(s.doc, "after filling");
    for (uint32_t c = 0; c < 4; ++c) {
        ASSERT_EQ(curveSegmentCount(s.doc.curves[c]), 2u) << c;
        EXPECT_EQ(fillEdgesOnCurve(s.doc, 0, c), 2u) << "curve " << c;
    }
    // Split, not reshaped: the first curve's halves are its old segment's.
    const BezierCurve& c0 = s.doc.curves[0];
    for (double t : {0.1, 0.3, 0.45}) {
        std::array<Vec3, 4> half;
        for (int k = 0; k < 4; ++k) half[size_t(k)] = s.doc.points[c0.idx[size_t(k)]];
        EXPECT_LT(glm::length(evaluateCurve(half, t) - evaluateCurve(before, t / 2)), 1e-12) << t;
    }
    // The curves meet in shared points now, so dragging a corner moves both curves and the fill.
    EXPECT_EQ(s.doc.curves[0].idx.front(), s.doc.curves[3].idx.back());
    const uint32_t corner = s.doc.curves[1].idx.front(), middle = s.doc.curves[2].idx[3], centre = s.doc.patches[0].idx[15];
    for (const auto& [pt, move] : {std::pair{corner, "0.05 -0.05 0.1"}, {middle, "0 0.1 0.15"}, {centre, "0.02 0.03 0.05"}}) {
        test::runEditScript(s, "select point " + std::to_string(pt) + "; move " + move);
        expectG1(s.doc, "after moving point " + std::to_string(pt));
        for (uint32_t c = 0; c < 4; ++c) EXPECT_EQ(fillEdgesOnCurve(s.doc, 0, c), 2u) << "curve " << c;
    }
}

// A hole of one patch edge and three curves: G1 to the patch (its edge split through its ring),
// through the curves' points elsewhere, and held while the patch is dragged.
TEST(FillHole, APatchEdgeAndCurvesMakeOneFillG1ToThePatch) {
    EditSession s;
    s.doc = makePatchGrid(1, 1);
    const Patch& P = s.doc.patches[0];
    const Vec3 a = s.doc.points[P.idx[size_t(edgeSlot(Edge::V0, 0))]], b = s.doc.points[P.idx[size_t(edgeSlot(Edge::V0, 3))]];
    const Vec3 out = a - s.doc.points[P.idx[size_t(edgeSlot(Edge::V0, 0, 1))]];
    const Vec3 up = 0.5 * glm::length(out) * glm::normalize(glm::cross(b - a, out));
    const Vec3 a2 = a + 3.0 * out + up, b2 = b + 3.0 * out + up;
    Recorder host;
    runCommandLine(s, host, "curve-control " + xyz(b) + " " + xyz(b + out) + " " + xyz(b2 - out) + " " + xyz(b2));
    runCommandLine(
        s, host, "curve-control " + xyz(b2) + " " + xyz(b2 + (a2 - b2) / 3.0 + up) + " " + xyz(a2 + (b2 - a2) / 3.0 + up) + " " + xyz(a2));
    runCommandLine(s, host, "curve-control " + xyz(a2) + " " + xyz(a2 - out) + " " + xyz(a + out) + " " + xyz(a));
    runCommandLine(s, host, "fill-hole 0:v0 c0 c1 c2");
    EXPECT_NE(host.last.find("G1 to its 2 edges and through the points of its 3 curves"), std::string::npos) << host.last;
    EXPECT_NE(host.last.find("split 1 patches"), std::string::npos) << host.last;
    ASSERT_EQ(s.doc.patches.size(), 2u + 4u);
    expectG1(s.doc, "after filling");
    size_t toSurroundings = 0;
    for (const Join& j : s.doc.joins) toSurroundings += (j.patchA < 2) != (j.patchB < 2) ? 1 : 0;
    EXPECT_EQ(toSurroundings, 2u);
    for (uint32_t c = 0; c < 3; ++c) EXPECT_EQ(fillEdgesOnCurve(s.doc, 2, c), 2u) << "curve " << c;
    const uint32_t far = s.doc.patches[0].idx[15], inner = s.doc.patches[2].idx[5];
    for (const auto& [pt, move] : {std::pair{far, "0 0 0.2"}, {inner, "0.02 0.01 -0.05"}}) {
        test::runEditScript(s, "select point " + std::to_string(pt) + "; move " + move);
        expectG1(s.doc, "after moving point " + std::to_string(pt));
    }
}

// Curves round a regular polygon, bulging up and down in turn: 3, 5 and 6 of them fill G1 too (one
// patch per corner, held G1 at the centre without splitting it), and hold while the curves move.
TEST(FillHole, ThreeFiveAndSixCurvesFillG1) {
    for (int n : {3, 5, 6}) {
        SCOPED_TRACE(n);
        EditSession s;
        Recorder host;
        std::string cmd = "fill-hole";
        const auto corner = [&](int k) {
            const double a = 2 * std::numbers::pi * k / n;
            return Vec3(std::cos(a), std::sin(a), 0.0);
        };
        for (int k = 0; k < n; ++k) {
            const Vec3 a = corner(k), b = corner(k + 1), lift(0.0, 0.0, k % 2 ? -0.3 : 0.3);
            runCommandLine(
                s, host,
                "curve-control " + xyz(a) + " " + xyz(a + (b - a) / 3.0 + lift) + " " + xyz(a + 2.0 * (b - a) / 3.0 + lift) + " " + xyz(b));
            cmd += " c" + std::to_string(k);
        }
        runCommandLine(s, host, cmd);
        EXPECT_NE(host.last.find("through the points of its " + std::to_string(n) + " curves"), std::string::npos) << host.last;
        for (const Join& j : s.doc.joins) EXPECT_NE(j.continuity, Continuity::C0);
        expectG1(s.doc, "after filling");
        EXPECT_EQ(s.doc.patches.size(), size_t(n)) << host.last;
        // Every segment of every curve (each split at its middle) is a fill edge.
        for (uint32_t c = 0; c < uint32_t(n); ++c) {
            EXPECT_EQ(curveSegmentCount(s.doc.curves[c]), 2u) << "curve " << c;
            EXPECT_EQ(fillEdgesOnCurve(s.doc, 0, c), curveSegmentCount(s.doc.curves[c])) << "curve " << c;
        }
        const uint32_t middle = s.doc.curves[1].idx[3], end = s.doc.curves[0].idx[0];
        for (const auto& [pt, move] : {std::pair{middle, "0 0 0.1"}, {end, "0.05 0.05 -0.1"}}) {
            test::runEditScript(s, "select point " + std::to_string(pt) + "; move " + move);
            expectG1(s.doc, "after moving point " + std::to_string(pt));
        }
    }
}

// A curve side is split by the fill: refused where that would cut it loose from what shares its
// points, and a side given twice is refused; nothing changes either way.
TEST(FillHole, CurveSidesThatCannotBeSplitAreRefused) {
    EditSession s;
    s.doc = makePatchGrid(1, 1);
    Recorder host;
    runCommandLine(s, host, "select patch 0");
    runCommandLine(s, host, "curve-from-edge v0");  // c0 shares the patch's edge points
    runCommandLine(s, host, "curve-control 0,0,0 0.3,0,0.2 0.6,0,0.2 1,0,0");
    runCommandLine(s, host, "curve-control 1,0,0 1,0.3,-0.1 1,0.6,-0.1 1,1,0");
    const Document before = s.doc;
    for (const auto& [cmd, says] : {std::pair{"fill-hole c0 c1 c2", "shares its points with patch 0"},
                                    {"fill-hole c1 c1 c2", "are the same curve"},
                                    {"fill-hole 0:u0 c1 0:u0", "are the same edge"}}) {
        SCOPED_TRACE(cmd);
        try {
            test::runEditScript(s, cmd);
            ADD_FAILURE() << "accepted";
        } catch (const std::exception& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
        }
        EXPECT_EQ(s.doc, before);
    }
}

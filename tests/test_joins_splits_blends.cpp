// Issue 40's whole-network edits and invariants (core/ops/join_ops, split_ops, core/construct/
// blend_net, core/edit/edit_invariants): no edit leaves a join out of tolerance, joins are never
// held by folding a patch, a join's continuity changes in place, a split runs through its ring and
// keeps every join, and blends stay G1/G2 while either side moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/errors.hpp"
#include "core/construct/constructions.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/edit/edit_invariants.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/fold_check.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/model/topology.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"
#include "support.hpp"

using namespace pw;

namespace {

// Three flat faces of the unit cube meeting at the origin (a box corner), as a .bpt; the reader
// joins their shared edges C0.
Document boxCorner() {
    std::string text = "3\n";
    for (int face = 0; face < 3; ++face) {
        text += "3 3\n";
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) {
                const double u = i / 3.0, v = j / 3.0;
                const Vec3 p = face == 0 ? Vec3(u, v, 0) : face == 1 ? Vec3(u, 0, v) : Vec3(0, u, v);
                text += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
            }
    }
    return parseBpt(text, "corner.bpt");
}

bool refused(EditSession& s, const std::string& script, const std::string& expect = "") {
    try {
        test::runEditScript(s, script);
    } catch (const std::exception& e) {
        if (!expect.empty()) {
            EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
        }
        return true;
    }
    return false;
}

// Patch edges that no join uses, leaving out collapsed ones (a cap's centre).
size_t openEdges(const Document& d) {
    size_t open = 0;
    for (uint32_t p = 0; p < d.patches.size(); ++p)
        for (Edge e : {Edge::U0, Edge::U1, Edge::V0, Edge::V1}) {
            double length = 0.0;
            for (int k = 0; k < 3; ++k)
                length += glm::length(d.points[d.patches[p].idx[size_t(edgeSlot(e, k + 1))]] -
                                      d.points[d.patches[p].idx[size_t(edgeSlot(e, k))]]);
            open += findJoin(d, p, e) < 0 && length > 1e-9 ? 1 : 0;
        }
    return open;
}

double worstNormalAngle(const Document& d) {
    double worst = 0.0;
    for (const JoinContinuity& c : continuityReport(d, 16)) worst = std::max(worst, c.normalAngleDeg);
    return worst;
}

}  // namespace

TEST(EditInvariants, BoxCornerOfFlatFacesIsRefusedRatherThanFolded) {
    EditSession s;
    s.doc = boxCorner();
    ASSERT_EQ(s.doc.joins.size(), 3u);
    // Two G1 seams bend the faces into rounded seams, each one lining up the edges beside it; the
    // third closes the corner, where the corner construction finds those edges on one line: no
    // tangent plane to turn round. Refused, nothing changed (before the corner construction the
    // solver held it by folding a face).
    test::runEditScript(s, "unjoin 0:u0; unjoin 0:v0; unjoin 1:u0; join 0:v0 1:v0 G1; join 1:u0 2:u0 G1");
    const Document before = s.doc;
    EXPECT_TRUE(refused(s, "join 0:u0 2:v0 G1", "lie on one line"));
    EXPECT_EQ(s.doc, before);
    for (uint32_t p = 0; p < s.doc.patches.size(); ++p) EXPECT_EQ(patchShape(s.doc, p).invertedTriangles, 0);
}

TEST(EditInvariants, AnEditThatLeavesAJoinOffIsRefusedNamingIt) {
    EditSession s;
    test::runEditScript(s, "add-patch; extrude u1; join 0:u1 1:u0 G1");
    const Document before = s.doc;
    const uint32_t tangent = s.doc.patches[1].idx[size_t(edgeSlot(Edge::U0, 1, 1))];
    try {
        s.apply("Nudge", [&](Document& d) { d.points[tangent].z += 0.3; });
        FAIL() << "an edit that breaks a join was accepted";
    } catch (const EditError& e) {
        EXPECT_NE(std::string(e.what()).find("join 0 (patch 0 u1"), std::string::npos) << e.what();
    }
    EXPECT_EQ(s.doc, before);
    EXPECT_NE(s.history().undoLabel(), "Nudge");
}

// The one place every edit passes (edit_invariants): an edit that brings in or changes a join and
// folds a patch is refused, whatever operation made it, naming the folded patch; the same fold
// without a join change is the user's own shaping and is kept.
TEST(EditInvariants, AnEditThatHoldsAJoinByFoldingIsRefusedWhateverMadeIt) {
    EditSession s;
    test::runEditScript(s, "add-patch; add-patch");
    ASSERT_TRUE(s.doc.joins.empty());
    // Patch 1 moved so that its u0 edge lies on patch 0's u1 edge.
    const Vec3 shift = s.doc.points[s.doc.patches[0].idx[size_t(edgeSlot(Edge::U1, 0))]] -
                       s.doc.points[s.doc.patches[1].idx[size_t(edgeSlot(Edge::U0, 0))]];
    s.apply("Place", [&](Document& d) {
        for (uint32_t i : d.patches[1].idx) d.points[i] += shift;
    });
    const Document before = s.doc;
    // Patch 1's tangent at its far corner collapsed (point 14 onto corner 15): no tangent plane there.
    auto fold = [](Document& d) { d.points[d.patches[1].idx[14]] = d.points[d.patches[1].idx[15]]; };
    try {
        s.apply("Raw join", [&](Document& d) {
            fold(d);
            d.joins.push_back(Join{0, Edge::U1, 1, Edge::U0, false, Continuity::C0});
        });
        FAIL() << "a join held by folding was accepted";
    } catch (const EditError& e) {
        EXPECT_NE(std::string(e.what()).find("only by folding patch 1"), std::string::npos) << e.what();
    }
    EXPECT_EQ(s.doc, before);
    s.apply("Shape", fold);  // no join changed: the user's own shaping, accepted
    EXPECT_EQ(s.history().undoLabel(), "Shape");
    EXPECT_GT(patchShape(s.doc, 1).collapsedCorners, 0);
}

TEST(Joins, ContinuityChangesInPlaceAndARefusedChangeKeepsTheJoin) {
    EditSession s;
    test::runEditScript(s, "add-patch; extrude u1; select patch 1; move 0 0 0.2");
    ASSERT_EQ(s.doc.joins.size(), 1u);
    ASSERT_EQ(s.doc.joins[0].continuity, Continuity::C1);
    test::runEditScript(s, "join 1:u0 0:u1 G2");  // either order names the same join
    ASSERT_EQ(s.doc.joins.size(), 1u);
    EXPECT_EQ(s.doc.joins[0].continuity, Continuity::G2);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc));
    test::runEditScript(s, "undo");
    EXPECT_EQ(s.doc.joins[0].continuity, Continuity::C1);

    // At the box corner (its faces' normals do not all face out), turning one of the reader's C0
    // seams G1 closes a corner whose sides would lie over each other: refused, the join stays C0
    // and nothing moves.
    EditSession c;
    c.doc = boxCorner();
    const Document before = c.doc;
    EXPECT_TRUE(refused(c, "join 0:v0 1:v0 G1", "does not turn one way around the corner"));
    EXPECT_EQ(c.doc, before);
    // An edge joined to another patch is not re-joined silently.
    EXPECT_TRUE(refused(c, "join 0:v0 2:v0 G1", "already joined"));
}

TEST(Splits, ASplitRunsThroughItsRingAndKeepsEveryJoin) {
    for (const char* split : {"select patch 0; split v 0.3", "split-ring 0 u 0.3", "split-ring 2 v 0.5"}) {
        EditSession s;
        test::runEditScript(s, "add-cylinder");
        const Document before = s.doc;
        ASSERT_EQ(openEdges(before), 0u);  // a closed cylinder with caps: every edge joined
        test::runEditScript(s, split);
        EXPECT_GT(s.doc.patches.size(), before.patches.size() + 1) << split;  // more than one patch was cut
        EXPECT_EQ(openEdges(s.doc), 0u) << split;                             // no join dropped, no T-junction
        EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc)) << split;
        EXPECT_LT(worstNormalAngle(s.doc), worstNormalAngle(before) + 1e-6) << split;
        // Exact: every side patch still lies on the cylinder of radius 0.5 (the side is z-up).
        for (uint32_t p = 0; p < s.doc.patches.size(); ++p)
            for (double u : {0.1, 0.5, 0.9})
                for (double v : {0.2, 0.7}) {
                    const Vec3 q = test::patchPointAt(s.doc, p, u, v);
                    const double r = std::hypot(q.x, q.y);
                    const bool cap = std::abs(q.z) < 1e-9 || std::abs(q.z - 1.0) < 1e-9;
                    if (cap) {
                        EXPECT_LE(r, 0.5 + 1e-12) << split << " patch " << p;
                    } else {
                        EXPECT_NEAR(r, 0.5, 1e-12) << split << " patch " << p;
                    }
                }
    }
}

TEST(Splits, BadRingRequestsAreRefusedAndChangeNothing) {
    EditSession s;
    test::runEditScript(s, "add-cylinder");
    const Document before = s.doc;
    for (const char* bad : {"split-ring 99 u 0.5", "split-ring 0 w 0.5", "split-ring 0 u 1", "split-ring 0 u 0", "split-ring 0 u x"}) {
        EXPECT_TRUE(refused(s, bad)) << bad;
        EXPECT_EQ(s.doc, before) << bad;
    }
}

// Each construction's patches carry its own name (issue 40: baked blends were all "blend 0").
TEST(Blends, TwoBlendsAreToldApartByName) {
    EditSession s;
    test::runEditScript(s, "add-patch; cursor 3 0 1; add-patch; cursor 0 3 1; add-patch; blend 0:u1 1:u0 G1; blend 0:v1 2:v0 G1");
    ASSERT_EQ(s.doc.constructions.size(), 2u);
    const std::string first = s.doc.patches[s.doc.constructions[0].patches[0]].name;
    const std::string second = s.doc.patches[s.doc.constructions[1].patches[0]].name;
    EXPECT_EQ(first, "blend 0");
    EXPECT_EQ(second, "blend 2 0");
}

TEST(Blends, G1AndG2BlendsHoldWhileEitherSideMoves) {
    for (const char* cont : {"G1", "G2"}) {
        EditSession s;
        test::runEditScript(s, std::string("add-patch; cursor 3 0 1; add-patch; select patch 1; rotate Y 40; blend 0:u1 1:u0 ") + cont);
        const bool g2 = std::string(cont) == "G2";
        ASSERT_EQ(s.doc.constructions.size(), 1u);
        const Construction& k = s.doc.constructions[0];
        EXPECT_EQ(k.patches.size(), g2 ? 3u : 1u);
        EXPECT_EQ(s.doc.joins.size(), g2 ? 4u : 2u);  // both ends, and C2 between the spans
        const auto hold = [&](const char* when) {
            EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc)) << cont << " " << when;
            EXPECT_LT(worstNormalAngle(s.doc), 1e-6) << cont << " " << when;
            for (const JoinContinuity& c : continuityReport(s.doc, 16)) {
                if (g2) {
                    EXPECT_LT(c.curvatureDeviationPct, 1e-3) << cont << " " << when << " join " << c.join;
                }
            }
            for (uint32_t p : s.doc.constructions[0].patches) EXPECT_EQ(patchShape(s.doc, p).invertedTriangles, 0) << when;
        };
        hold("made");
        // Moving and turning either side re-makes the blend; it stays G1/G2 and local.
        test::runEditScript(s, "select patch 1; move 0 0 0.6; select patch 0; rotate X 20");
        hold("after the sides moved");
        const Bounds b = computeBounds(s.doc.points);
        EXPECT_LT(glm::length(b.max - b.min), 8.0);
        // A drag of a tangent point of the first patch: the blend follows on every move.
        DragController drag;
        DragView view;
        view.camera = s.camera;
        view.width = 800, view.height = 600;
        const uint32_t tangent = s.doc.patches[0].idx[size_t(edgeSlot(Edge::U1, 1, 1))];
        TransformStart start{{tangent}, s.doc.points[tangent], TransformKind::Move};
        ASSERT_TRUE(drag.begin(s.doc, start, view, 400, 300)) << drag.refusal();
        drag.setAxis(2);
        for (int step = 1; step <= 4; ++step) {
            ASSERT_TRUE(drag.update(s.doc, view, 400, 300 - 6 * step, false));
            hold("while dragging");
        }
        drag.finish(s);
        // Its joins' continuity is the blend's: changing one by hand is refused, the blend kept.
        EXPECT_TRUE(refused(s, "join 0:u1 " + std::to_string(s.doc.constructions[0].patches[0]) + ":v0 C1", "bake it first"));
        ASSERT_EQ(s.doc.constructions.size(), 1u);
        // The file keeps the blend live.
        const Document back = parseDocument(serializeDocument(s.doc), "blend.patchwork");
        EXPECT_EQ(back.constructions, s.doc.constructions);
    }
}

TEST(Blends, BadBlendsAreRefusedAndChangeNothing) {
    EditSession s;
    test::runEditScript(s, "add-patch; cursor 3 0 1; add-patch; add-curve; select patch 0; extrude u0");
    const Document before = s.doc;
    for (const char* bad : {"blend 0:u1 1:u0 G3", "blend 0:u1 1:u0 C1", "blend 0:u1 0:u1 G1", "blend 0:u1 c0 G1", "blend 0:u1 9:u0 G1",
                            "blend 0:u1", "blend 0:u0 1:u0 G1", "blend 1:u1 1:v0 G1", "blend 1:v1 1:v1 G2"}) {
        EXPECT_TRUE(refused(s, bad)) << bad;
        EXPECT_EQ(s.doc, before) << bad;
    }
}

TEST(Joins, LiveSymmetryJoinsTheMirrorImagesToo) {
    EditSession s;
    test::runEditScript(s, "cursor 1.5 0 0; add-patch; cursor 3.5 0 0; add-patch; select all; cursor 0 0 0; mirror X; symmetry X");
    ASSERT_EQ(s.doc.patches.size(), 4u);
    ASSERT_TRUE(s.doc.joins.empty());
    test::runEditScript(s, "join 0:u1 1:u0 C1");
    ASSERT_EQ(s.doc.joins.size(), 2u);
    const Join& mirrored = s.doc.joins[1];
    EXPECT_TRUE(mirrored.patchA >= 2 && mirrored.patchB >= 2) << mirrored.patchA << " " << mirrored.patchB;
    EXPECT_EQ(mirrored.continuity, Continuity::C1);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc));
    // The two sides stay each other's mirror image.
    for (uint32_t i = 0; i < 16; ++i) {
        const Vec3 p = s.doc.points[s.doc.patches[0].idx[i]];
        bool found = false;
        for (const Vec3& q : s.doc.points) found = found || glm::length(q - Vec3(-p.x, p.y, p.z)) < 1e-9;
        EXPECT_TRUE(found) << i;
    }
}

TEST(Blends, FarSidesStayWithinTheFileAndWeightedSidesAreRefused) {
    EditSession s;
    test::runEditScript(s, "add-patch; cursor 5000 0 0; add-patch; blend 0:u1 1:u0 G1");
    for (double a : s.doc.constructions.at(0).endAlpha) EXPECT_LE(a, 1e3);
    EXPECT_NO_THROW(parseDocument(serializeDocument(s.doc), "far.patchwork"));  // the file reopens
    EditSession w;
    test::runEditScript(w, "add-patch; cursor 3 0 0; add-patch; select point 5; weight 2");
    const Document before = w.doc;
    EXPECT_TRUE(refused(w, "blend 0:u0 1:u0 G1", "rational"));
    EXPECT_EQ(w.doc, before);
}

TEST(EditInvariants, ImportKeepsTheJoinsItsFileHasAsDetected) {
    // The teaspoon's seams are joined by detection within 1e-4 of its size, not 1e-6: importing it
    // is taken like opening it.
    EditSession s;
    test::runEditScript(s, "add-patch");
    ASSERT_NO_THROW(s.import((test::dataDir() / "teaspoon.bpt").string()));
    EXPECT_GT(s.doc.joins.size(), 0u);
}

TEST(Splits, ASplitThroughALiveSurfacesInputIsRefusedAndItsFarEdgeFollows) {
    EditSession s;
    test::runEditScript(s, "add-patch; curve-through 2,-0.5,0 2,0.5,0.5; edge-surface 0:u1 c0");
    const Document before = s.doc;
    EXPECT_TRUE(refused(s, "split-ring 0 v 0.5", "bake that surface first"));  // the cut crosses edge u1
    EXPECT_EQ(s.doc, before);
    test::runEditScript(s, "split-ring 0 u 0.4");  // u1 goes to the second half, whole
    const Construction& k = s.doc.constructions.at(0);
    EXPECT_NE(k.inputs[0].patch, 0u);
    EXPECT_TRUE(k.error.empty()) << k.error;
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc));
}

// A split of a live G2 blend's input patch (the blend's far edge moves to the second half): the
// document, saved and reopened, is the same (issue 73). The joins the split makes move the rows
// beside the input edge that the blend reads, so the surfaces are made again until they stay.
TEST(Splits, ASplitBesideALiveBlendReopensToTheSameDocument) {
    EditSession s;
    test::runEditScript(s, "add-patch; cursor 3 0 1; add-patch; blend 0:u1 1:u0 G2; select patch 0; split u 0.609");
    ASSERT_EQ(s.doc.constructions.size(), 1u);
    EXPECT_TRUE(s.doc.constructions[0].error.empty()) << s.doc.constructions[0].error;
    const std::string saved = serializeDocument(s.documentToSave());
    EditSession again;
    again.reset(parseDocument(saved, "reopened.patchwork"), "");
    EXPECT_EQ(serializeDocument(again.documentToSave()), saved);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc));
}

// Turning a live blend's input patch (issue 73): its u0 and u1 trade names with it, so the blend is
// made from the same edges and the document reopens the same; a v edge would run backwards, so
// turning its patch is refused until the blend is baked.
TEST(Blends, FlippingAnInputPatchKeepsTheBlendOnItsEdges) {
    // Two patches apart, a blend between their facing u edges; patch 0 turned: its u1 is now u0.
    EditSession s;
    test::runEditScript(s, "add-patch; cursor 3 0 1; add-patch; blend 0:u1 1:u0 G1");
    const Document blended = s.doc;
    test::runEditScript(s, "select patch 0; flip");
    ASSERT_EQ(s.doc.constructions.size(), 1u);
    EXPECT_EQ(s.doc.constructions[0].inputs[0].edge, Edge::U0);
    EXPECT_EQ(s.doc.constructions[0].inputs[1].edge, Edge::U0);
    const std::string saved = serializeDocument(s.documentToSave());
    EditSession again;
    again.reset(parseDocument(saved, "reopened.patchwork"), "");
    EXPECT_EQ(serializeDocument(again.documentToSave()), saved);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9 * modelSize(s.doc));

    EditSession v;
    test::runEditScript(v, "add-patch; cursor 0 3 1; add-patch; blend 0:v1 1:v0 G1");
    const Document before = v.doc;
    EXPECT_TRUE(refused(v, "select patch 0; flip", "bake that surface first (bake k0)"));
    EXPECT_EQ(v.doc.patches, before.patches);
    test::runEditScript(v, "bake k0; select patch 0; flip");
}

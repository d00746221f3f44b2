// Continuity report and the live readout: a C1 grid measures ~0 on every join; breaking one tangent point shows up on
// that join only; reversed and mirrored parameterisations, G1 ratios and C0 gaps are measured right.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/construct/model_builders.hpp"
#include "core/io/document_io.hpp"
#include "core/model/document.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"
#include "core/solve/continuity_watch.hpp"
#include "tests/support.hpp"

using namespace pw;

namespace {

uint32_t lat(int cols, int r, int c) { return static_cast<uint32_t>(r * (3 * cols + 1) + c); }

void expectSmooth(const JoinContinuity& jc) {
    EXPECT_LE(jc.c0Gap, 1e-12) << "join " << jc.join;
    EXPECT_LE(jc.c1Residual, 1e-12) << "join " << jc.join;
    EXPECT_LE(jc.normalAngleDeg, 1e-6) << "join " << jc.join;
}

// Index of the join between patches a and b.
size_t findJoin(const Document& doc, uint32_t a, uint32_t b) {
    for (size_t j = 0; j < doc.joins.size(); ++j)
        if (doc.joins[j].patchA == a && doc.joins[j].patchB == b) return j;
    ADD_FAILURE() << "no join " << a << "-" << b;
    return 0;
}

}  // namespace

TEST(Continuity, GridJoinsAreSmooth) {
    const Document doc = makePatchGrid(4, 4);
    const auto report = continuityReport(doc);
    ASSERT_EQ(report.size(), doc.joins.size());
    for (size_t j = 0; j < report.size(); ++j) {
        EXPECT_EQ(report[j].join, j);
        expectSmooth(report[j]);
    }
}

TEST(Continuity, BrokenTangentShowsOnItsJoinOnly) {
    Document doc = makePatchGrid(4, 4);
    // Lattice (1,5): the tangent point of patch (0,1) next to the seam with patch (0,2), row k=1.
    // Lattice row 1 is far from every v seam, so no other join involves it.
    const uint32_t p = lat(4, 1, 5);
    ASSERT_EQ(doc.patches[1].idx[edgeSlot(Edge::U1, 1, 1)], p);
    doc.points[p].z += 0.2;
    const size_t broken = findJoin(doc, 1, 2);
    const auto report = continuityReport(doc, 32);
    for (const JoinContinuity& jc : report) {
        if (jc.join == broken) {
            EXPECT_LE(jc.c0Gap, 1e-12);  // still C0: the boundary is untouched
            EXPECT_NEAR(jc.c1Residual, 0.2, 1e-12);
            // The tangent across the seam tilts by roughly atan(0.2 / (1/3)) at k=1; the seam
            // samples between see a good part of it.
            EXPECT_GT(jc.normalAngleDeg, 5.0);
            EXPECT_LT(jc.normalAngleDeg, 60.0);
        } else {
            expectSmooth(jc);
        }
    }
    EXPECT_NEAR(maxConstraintResidual(doc), 0.2, 1e-12);

    // Projecting with the broken point held mends the join (the partner mirrors).
    projectConstraints(doc, {p});
    for (const JoinContinuity& jc : continuityReport(doc)) {
        EXPECT_LE(jc.c1Residual, 1e-9);
        EXPECT_LE(jc.normalAngleDeg, 1e-5);
    }
}

TEST(Continuity, ReversedAndMirroredParameterisations) {
    // Patch 1 of a 1x2 grid with its rows flipped: its u0 edge runs backwards (reversed join) and
    // its normal points the other way; the report must still see a smooth seam.
    Document doc = makePatchGrid(1, 2);
    Patch& b = doc.patches[1];
    const auto orig = b.idx;
    for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 4; ++c) b.idx[a * 4 + c] = orig[(3 - a) * 4 + c];
    doc.joins[0].reversed = true;
    EXPECT_LE(maxConstraintResidual(doc), 1e-14);
    expectSmooth(continuityReport(doc)[0]);

    // The same seam recorded without `reversed` is wrong: a C0 gap and a residual appear.
    doc.joins[0].reversed = false;
    const JoinContinuity wrong = continuityReport(doc)[0];
    EXPECT_GT(wrong.c0Gap, 0.5);
    EXPECT_GT(wrong.c1Residual, 0.005);  // the tangents are compared at the wrong points

    // Columns mirrored instead: B's u1 edge meets A's u1 edge.
    doc = makePatchGrid(1, 2);
    for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 4; ++c) doc.patches[1].idx[a * 4 + c] = makePatchGrid(1, 2).patches[1].idx[a * 4 + 3 - c];
    doc.joins[0].edgeB = Edge::U1;
    EXPECT_LE(maxConstraintResidual(doc), 1e-14);
    expectSmooth(continuityReport(doc)[0]);

    // A v-seam: patch (0,0) over (1,0) of a 2x1 grid, B flipped in v so that v1 meets v1.
    doc = makePatchGrid(2, 1);
    const Patch copy = doc.patches[1];
    for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 4; ++c) doc.patches[1].idx[a * 4 + c] = copy.idx[(3 - a) * 4 + c];
    doc.joins[0].edgeB = Edge::V1;
    EXPECT_LE(maxConstraintResidual(doc), 1e-14);
    expectSmooth(continuityReport(doc)[0]);
}

TEST(Continuity, CreaseAndGap) {
    // A C0 join with a real crease: fold patch 1 of a flat-ish 1x2 grid up along the seam.
    Document doc = makePatchGrid(1, 2, Continuity::C0);
    for (int k = 0; k < 4; ++k)
        for (int c = 4; c <= 6; ++c) doc.points[lat(2, k, c)].z += (c - 3) * 1.0 / 3.0;  // slope 1 more
    const JoinContinuity jc = continuityReport(doc)[0];
    EXPECT_LE(jc.c0Gap, 1e-12);
    EXPECT_GT(jc.c1Residual, 0.3);
    EXPECT_GT(jc.normalAngleDeg, 30.0);
    EXPECT_LT(jc.normalAngleDeg, 60.0);

    // Unshared edge points pulled apart: the gap is the largest seam distance.
    doc = makePatchGrid(1, 2);
    Patch& b = doc.patches[1];
    for (int k = 0; k < 4; ++k) {
        const int slot = edgeSlot(Edge::U0, k);
        doc.points.push_back(doc.points[b.idx[slot]] + Vec3(0, 0, 0.25));
        b.idx[slot] = static_cast<uint32_t>(doc.points.size() - 1);
    }
    const JoinContinuity gap = continuityReport(doc)[0];
    EXPECT_NEAR(gap.c0Gap, 0.25, 1e-12);
    EXPECT_NEAR(gap.c1Residual, 0.25, 1e-12);  // B1 − B0 changed by −0.25 in z
}

TEST(Continuity, G1RatioIsMeasuredWithAlpha) {
    Document doc = makePatchGrid(1, 2, Continuity::G1);
    doc.joins[0].alpha = 2.0;
    EXPECT_GT(continuityReport(doc)[0].c1Residual, 0.01);
    projectConstraints(doc, {});
    const JoinContinuity jc = continuityReport(doc)[0];
    EXPECT_LE(jc.c1Residual, 1e-12);
    EXPECT_LE(jc.c0Gap, 1e-12);
    EXPECT_LE(jc.normalAngleDeg, 1e-6);  // G1: tangent planes agree
}

// The editor's live readout (core/solve/continuity_watch.hpp): everything when settled, only the joins
// next to the dragged points while a drag is under way, tolerances applied.
TEST(ContinuityWatch, LiveNextToTheDragAndFullWhenSettled) {
    Document doc = makePatchGrid(4, 4, Continuity::C2);
    ContinuityWatch watch;
    watch.update(doc, 1, false, {});
    ASSERT_EQ(watch.report().size(), doc.joins.size());
    EXPECT_EQ(watch.lastMeasured().size(), doc.joins.size());
    EXPECT_EQ(watch.outOfTolerance(), 0u);
    // Lattice (0, 1) of the 4x4 grid: the third row of patch 0 from its u1 seam, on the grid's
    // border (no v seam uses it). Moving it alone breaks that join's curvature (no solver here).
    const uint32_t p = lat(4, 0, 1);
    doc.points[p].z += 0.05;
    watch.update(doc, 2, true, {p});
    EXPECT_LT(watch.lastMeasured().size(), doc.joins.size());  // only the neighbourhood
    EXPECT_EQ(watch.lastMeasured(), joinsTouching(doc, {p}));
    EXPECT_EQ(watch.outOfTolerance(), 1u);
    const size_t broken = findJoin(doc, 0, 1);
    EXPECT_EQ(watch.failures(broken), kCurvatureOut);
    watch.update(doc, 2, true, {p});  // a drag changes no version: measured again, same verdict
    EXPECT_EQ(watch.failures(broken), kCurvatureOut);
    // Orbiting (interacting, no point moving) measures nothing and keeps the last verdicts.
    watch.update(doc, 2, true, {});
    EXPECT_TRUE(watch.lastMeasured().empty());
    EXPECT_EQ(watch.failures(broken), kCurvatureOut);
    doc.tolerances.curvaturePct = 1e6;
    watch.update(doc, 2, false, {});  // the tolerances changed: everything again
    EXPECT_EQ(watch.lastMeasured().size(), doc.joins.size());
    EXPECT_EQ(watch.outOfTolerance(), 0u);
}

// `patchwork info --json` reports the same numbers and tolerance verdicts.
TEST(ContinuityWatch, InfoJsonReportsTolerances) {
    Document doc = makePatchGrid(2, 2, Continuity::C2);
    doc.points[lat(2, 0, 1)].z += 0.05;
    const std::filesystem::path dir = test::freshTempDir("info_tol");
    saveDocument(doc, dir / "broken.patchwork");
    const test::RunResult r =
        test::runCommand(test::patchworkBinary().string() + " info --json '" + (dir / "broken.patchwork").string() + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j["joins"]["C2"], 4);
    EXPECT_EQ(j["joinsOutOfTolerance"], 1);
    EXPECT_GT(j["largest"]["curvatureDeviationPct"].get<double>(), 5.0);
    EXPECT_DOUBLE_EQ(j["tolerances"]["curvaturePct"].get<double>(), 5.0);
    const auto report = continuityReport(doc, 32);
    size_t flagged = 0;
    for (size_t k = 0; k < j["joinReport"].size(); ++k) {
        const nlohmann::json& e = j["joinReport"][k];
        EXPECT_NEAR(e["curvatureDeviationPct"].get<double>(), report[k].curvatureDeviationPct, 1e-9);
        if (!e["outOfTolerance"].empty()) {
            ++flagged;
            EXPECT_EQ(e["outOfTolerance"], nlohmann::json::array({"curvature"}));
        }
    }
    EXPECT_EQ(flagged, 1u);
}

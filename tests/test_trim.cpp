// Trimmed surfaces (issue 64): trim loops in the model, their checks, areas, the commands
// (project, trim, intersect, split-by, untrim, bake), live re-trims after drags, undo and the file
// round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/edit/edit_session.hpp"
#include "core/edit/live_trims.hpp"
#include "core/gpu/trim_math.h"
#include "core/io/document_io.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/trim/curve_on_surface.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_cells.hpp"
#include "core/trim/trim_loops.hpp"
#include "support.hpp"

using namespace pw;

namespace {

constexpr double kPi = std::numbers::pi;

// A flat square patch of side `side` in the plane z = 0, P(u, v) = (side u, side v, 0).
Document flatPlate(double side = 2.0) {
    Document d;
    d.name = "plate";
    Patch p;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            p.idx[size_t(i * 4 + j)] = uint32_t(d.points.size());
            d.points.emplace_back(side * j / 3.0, side * i / 3.0, 0.0);
        }
    d.patches.push_back(p);
    return d;
}

// A closed uniform B-spline tube round the z axis through (cx, cy): 8 columns round, 5 rows from
// z = -1 to z = 1, closed along u.
void addTube(Document& d, double cx, double cy, double r) {
    Surface s;
    s.rows = 5;
    s.cols = 8;
    s.closedU = true;
    s.basis = Basis::BSpline;
    for (uint32_t i = 0; i < s.rows; ++i)
        for (uint32_t j = 0; j < s.cols; ++j) {
            const double a = 2.0 * kPi * j / s.cols;
            s.idx.push_back(uint32_t(d.points.size()));
            d.points.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a), -1.0 + 2.0 * i / (s.rows - 1));
        }
    d.surfaces.push_back(s);
}

EditSession sessionOf(Document d) {
    EditSession s;
    s.reset(std::move(d), "");
    return s;
}

void expectRefused(EditSession& s, const std::string& script, const std::string& says) {
    const Document held = s.doc;
    try {
        test::runEditScript(s, script);
        ADD_FAILURE() << "accepted: " << script;
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
    EXPECT_EQ(s.doc, held) << script;
}

double areaOf(const Document& d, const SurfaceRef& r) { return trimmedArea(DomainSurface(d, r), trimsOf(d, r)); }

}  // namespace

// A plate with a circular hole: the hole's area is the circle's to within a millionth, keep gives
// the disc, and the keep test agrees with the circle's inside on a grid.
TEST(Trim, APlateWithACircularHoleHasTheAnalyticArea) {
    EditSession s = sessionOf(flatPlate());
    test::runEditScript(s, "cursor 1 1 0; add-circle 0.5; trim 0 c0 remove");
    ASSERT_EQ(s.doc.patches[0].trims.size(), 1u);
    EXPECT_TRUE(s.doc.patches[0].trims[0].hole);
    EXPECT_LT(signedUvArea(s.doc.patches[0].trims[0]), 0.0);  // holes turn clockwise
    const double area = areaOf(s.doc, {false, 0});
    EXPECT_NEAR(area, 4.0 - kPi * 0.25, 1e-6 * 4.0);
    const auto segs = monotoneSegments(s.doc.patches[0].trims);
    const bool outer = hasOuterLoop(s.doc.patches[0].trims);
    int mismatches = 0;
    for (int i = 0; i <= 64; ++i)
        for (int j = 0; j <= 64; ++j) {
            const glm::dvec2 uv(j / 64.0, i / 64.0);
            const double r = glm::length(2.0 * uv - glm::dvec2(1.0));
            if (std::abs(r - 0.5) < 1e-3) continue;
            mismatches += trimKeeps(segs, outer, uv) != (r > 0.5) ? 1 : 0;
        }
    EXPECT_EQ(mismatches, 0);

    test::runEditScript(s, "untrim 0; trim 0 c0 keep");
    EXPECT_NEAR(areaOf(s.doc, {false, 0}), kPi * 0.25, 1e-6);
    EXPECT_GT(signedUvArea(s.doc.patches[0].trims[0]), 0.0);
    // Undo brings back the hole, and then the untrimmed plate.
    test::runEditScript(s, "undo; undo");
    ASSERT_EQ(s.doc.patches[0].trims.size(), 1u);
    EXPECT_TRUE(s.doc.patches[0].trims[0].hole);
    test::runEditScript(s, "undo");
    EXPECT_TRUE(s.doc.patches[0].trims.empty());
}

// Trims live in parameter space: moving, scaling or rotating the surface keeps its loops, and the
// area scales with it.
TEST(Trim, TransformsKeepTheLoops) {
    EditSession s = sessionOf(flatPlate());
    test::runEditScript(s, "cursor 1 1 0; add-circle 0.5; trim 0 c0 remove; bake c0");
    const std::vector<TrimLoop> loops = s.doc.patches[0].trims;
    test::runEditScript(s, "select patch 0; scale 2; rotate X 30; move 1 2 3");
    EXPECT_EQ(s.doc.patches[0].trims, loops);
    EXPECT_NEAR(areaOf(s.doc, {false, 0}), 4.0 * (4.0 - kPi * 0.25), 1e-4);
}

TEST(Trim, TheFileKeepsLoopsAndLinks) {
    EditSession s = sessionOf(flatPlate());
    addTube(s.doc, 1.0, 1.0, 0.4);
    s.reset(s.doc, "");
    test::runEditScript(s, "intersect 0 n0; trim 0 c0 remove");
    const std::string text = serializeDocument(s.doc);
    const Document back = parseDocument(text, "t.patchwork");
    EXPECT_EQ(back, s.doc);
    EXPECT_EQ(serializeDocument(back), text);
}

// An open curve, a loop that leaves the domain and a loop that crosses itself are refused, and the
// document stays as it was.
TEST(Trim, BadLoopsAreRefusedAndTheDocumentKept) {
    EditSession s = sessionOf(flatPlate());
    test::runEditScript(s, "curve-through 0.5,0.5,0 1.5,0.5,0 1.5,1.5,0");
    expectRefused(s, "trim 0 c0 remove", "open");
    test::runEditScript(s, "cursor 2 1 0; add-circle 0.5");
    expectRefused(s, "trim 0 c1 remove", "runs off the surface");
    test::runEditScript(s, "curve-through 0.5,0.5,0 1.5,1.5,0 1.5,0.5,0 0.5,1.5,0 closed");
    expectRefused(s, "trim 0 c2 keep", "crosses itself");
    expectRefused(s, "trim 7 c0 keep", "patch 7 does not exist");
    // A loop read from a file is checked the same way.
    Document d = flatPlate();
    TrimLoop open;
    open.uv = {{0.2, 0.2}, {0.4, 0.2}, {0.6, 0.2}, {0.8, 0.8}};
    d.patches[0].trims.push_back(open);
    EXPECT_THROW(parseDocument(serializeDocument(d), "bad.patchwork"), InputError);
    d.patches[0].trims[0].uv = {{0.2, 0.2}, {1.4, 0.2}, {1.4, 0.8}, {0.2, 0.2}};
    EXPECT_THROW(parseDocument(serializeDocument(d), "bad.patchwork"), InputError);
}

// A tube through a plate: `intersect` makes one closed curve on both; the plate's hole and the
// tube's cut follow when the tube is dragged, and the two sides of the trim edge stay together.
TEST(Trim, IntersectionTrimsFollowADrag) {
    Document d = flatPlate();
    addTube(d, 1.0, 1.0, 0.4);
    EditSession s = sessionOf(d);
    test::runEditScript(s, "intersect 0 n0");
    ASSERT_EQ(s.doc.curves.size(), 1u);
    ASSERT_TRUE(curveClosed(s.doc.curves[0]));
    ASSERT_TRUE(s.doc.curves[0].link);
    test::runEditScript(s, "trim 0 c0 remove; trim n0 c0 keep");
    const double hole = 4.0 - areaOf(s.doc, {false, 0});
    EXPECT_GT(hole, 0.3);
    for (const TrimEdgeGap& g : trimEdgeGaps(s.doc)) EXPECT_LT(g.gap, 1e-5) << "curve c" << g.curve;
    // The tube's lower half is what `keep` keeps (the smaller part below the plate).
    EXPECT_NEAR(areaOf(s.doc, {true, 0}) / DomainSurface(s.doc, {true, 0}).area(), 0.5, 0.05);
    const UV before = s.doc.patches[0].trims[0].uv[0];
    test::runEditScript(s, "select net 0; move 0.3 0.2 0");
    const UV after = s.doc.patches[0].trims[0].uv[0];
    EXPECT_GT(std::abs(after[0] - before[0]) + std::abs(after[1] - before[1]), 0.05);
    EXPECT_NEAR(4.0 - areaOf(s.doc, {false, 0}), hole, 1e-4);  // the same hole, moved
    for (const TrimEdgeGap& g : trimEdgeGaps(s.doc)) EXPECT_LT(g.gap, 1e-5);
    // Points of a live curve are made by it; bake fixes it and its trims.
    expectRefused(s, "select point " + std::to_string(s.doc.curves[0].idx[1]) + "; move 0 0 1", "bake c0");
    test::runEditScript(s, "bake c0");
    EXPECT_FALSE(s.doc.curves[0].link);
    EXPECT_EQ(s.doc.patches[0].trims[0].curve, -1);
}

TEST(Trim, SplitByMakesTwoSurfacesThatShareTheCut) {
    EditSession s = sessionOf(flatPlate());
    test::runEditScript(s, "cursor 1 1 0; add-circle 0.5; split-by 0 c0");
    ASSERT_EQ(s.doc.patches.size(), 2u);
    EXPECT_EQ(s.doc.patches[0].idx, s.doc.patches[1].idx);
    EXPECT_NEAR(areaOf(s.doc, {false, 0}) + areaOf(s.doc, {false, 1}), 4.0, 1e-6);
    EXPECT_NEAR(areaOf(s.doc, {false, 1}), kPi * 0.25, 1e-6);
}

TEST(Trim, ProjectLaysACurveOnASurfaceAndFollowsIt) {
    EditSession s = sessionOf(flatPlate());
    test::runEditScript(s, "cursor 1 1 1; add-circle 0.5; project c0 0 Z");
    ASSERT_EQ(s.doc.curves.size(), 2u);
    for (uint32_t i : s.doc.curves[1].idx) EXPECT_NEAR(s.doc.points[i].z, 0.0, 1e-9);
    test::runEditScript(s, "select curve 0; move 0.2 0 0");
    EXPECT_NEAR(s.doc.points[s.doc.curves[1].idx[0]].x, s.doc.points[s.doc.curves[0].idx[0]].x, 1e-5);
}

// Deleting a curve that a live trim follows detaches the trim instead of pointing it elsewhere.
TEST(Trim, DeletingTheCurveDetachesTheTrim) {
    EditSession s = sessionOf(flatPlate());
    test::runEditScript(s, "cursor 0.5 0.5 0; add-circle 0.2; cursor 1.5 1.5 0; add-circle 0.2; trim 0 c1 remove; select curve 0; delete");
    ASSERT_EQ(s.doc.patches[0].trims.size(), 1u);
    EXPECT_EQ(s.doc.patches[0].trims[0].curve, 0);  // c1 is c0 now
    test::runEditScript(s, "select curve 0; delete");
    EXPECT_EQ(s.doc.patches[0].trims[0].curve, -1);
}

// Loops nest with their turns alternating: an island in a hole is kept, a hole in a hole refused.
TEST(Trim, LoopsNestAsHolesAndIslands) {
    EditSession s = sessionOf(flatPlate());
    test::runEditScript(s, "cursor 1 1 0; add-circle 0.5; add-circle 0.2; trim 0 c0 remove");
    expectRefused(s, "trim 0 c1 remove", "hole inside hole 0");
    test::runEditScript(s, "trim 0 c1 keep");
    EXPECT_NEAR(areaOf(s.doc, {false, 0}), 4.0 - kPi * 0.25 + kPi * 0.04, 1e-5);
    EXPECT_TRUE(trimKeeps(s.doc.patches[0].trims, {0.5, 0.5}));    // the island
    EXPECT_FALSE(trimKeeps(s.doc.patches[0].trims, {0.5, 0.68}));  // the ring of the hole round it
    EXPECT_TRUE(trimKeeps(s.doc.patches[0].trims, {0.05, 0.05}));  // the plate
}

// The fragment shader's cells (core/trim/trim_cells.hpp) give every point of every tested window the
// answer of the whole window's segments: the kettle's windows (holes through seams, cuts across
// tubes), a plate with two holes and an island, on a 97 x 97 grid of points per window that lands
// on cell edges and curves alike.
TEST(Trim, CellsKeepWhatTheWholeWindowKeeps) {
    std::vector<Document> docs{loadDocument(test::dataDir() / "kettle.patchwork"),
                               loadDocument(test::dataDir() / "trimmed_plate.patchwork")};
    {
        EditSession s;
        s.reset(Document{}, "");
        test::runEditScript(s, "add-net 4 4");
        Document d = s.doc;
        d.surfaces[0].trims = {circleLoop({0.5, 0.5}, 0.4, false), circleLoop({0.5, 0.5}, 0.25, true), circleLoop({0.5, 0.5}, 0.1, false)};
        docs.push_back(d);
    }
    size_t tested = 0, listed = 0, cellsWithNone = 0;
    for (const Document& doc : docs) {
        WindowTrims trims(doc);
        for (const PatchInstance& w : expandPatches(doc)) {
            const std::optional<WindowTrim> t = trims.of(w);
            if (!t || !(t->flags & gpu::kTrimTest)) continue;
            ++tested;
            const std::vector<TrimCell> cells = trimCells(*t);
            ASSERT_EQ(cells.size(), size_t(gpu::kTrimCells * gpu::kTrimCells));
            for (const TrimCell& c : cells) {
                listed += c.segments.size();
                cellsWithNone += c.segments.empty() ? 1 : 0;
            }
            const std::vector<TrimSegment> all = t->segments;
            const bool outer = !(t->flags & gpu::kTrimBaseKept);
            for (int i = 0; i <= 96; ++i)
                for (int j = 0; j <= 96; ++j) {
                    const glm::dvec2 uv(j / 96.0, i / 96.0);
                    ASSERT_EQ(cellKeeps(*t, cells, uv), trimKeeps(all, outer, uv)) << "at (" << uv.x << ", " << uv.y << ")";
                }
        }
    }
    EXPECT_GT(tested, 10u);
    EXPECT_GT(cellsWithNone, tested * 16);  // most cells settle by their parity alone
    EXPECT_GT(listed, 0u);
}

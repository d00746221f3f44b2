// The teaching presets: the notes' factor sets with their ids, the notes' Bézier patch and their
// distance formula.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "core/eval/patch_eval.hpp"
#include "core/gpu/patch_math.h"
#include "core/model/camera_math.hpp"
#include "core/tess/tess_domain.hpp"
#include "core/tess/tess_presets.hpp"
#include "support.hpp"

using namespace pw;

TEST(TessPresets, EveryFactorSetOfTheNotesWithAUniqueId) {
    const auto& ps = tessPresets();
    EXPECT_EQ(ps.size(), 19u);  // 5 quad, 9 triangle, the AMD tutorial's 3, the fractional example twice
    std::set<std::string> ids;
    for (const TessPreset& p : ps) {
        EXPECT_TRUE(ids.insert(p.name).second) << p.name;
        EXPECT_EQ(findTessPreset(p.name), &p);
        EXPECT_EQ(p.name.find(' '), std::string::npos) << "ids are used unquoted on the command line: " << p.name;
    }
    const TessPreset* q = findTessPreset("quad-2_2_4_4-2_4");
    ASSERT_NE(q, nullptr);
    EXPECT_EQ(q->label, "quad {2,2,4,4 | 2,4}");
    EXPECT_EQ(q->levels.inner, (std::array<float, 2>{2, 4}));
    const TessPreset* f = findTessPreset("tri-4.9_4.5_4.1-4.4-fractional_odd");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->spacing, Spacing::FractionalOdd);
    EXPECT_EQ(f->levels.outer[1], 4.5f);
    EXPECT_EQ(findTessPreset("quad-9"), nullptr);
    // The notes' uniform quad: 25 vertices, 32 triangles.
    const DomainCounts c = expectedDomainCounts(ps[0].kind, ps[0].levels, ps[0].spacing);
    EXPECT_EQ(c.vertices, 25u);
    EXPECT_EQ(c.primitives, 32u);
}

TEST(TessPresets, NotesBezierPatchAndDistanceFormula) {
    const Document d = notesBezierPatch();
    ASSERT_EQ(d.points.size(), 16u);
    ASSERT_EQ(d.patches.size(), 1u);
    EXPECT_EQ(d.points[6], Vec3(5, 20, 5));      // the raised inner point
    EXPECT_EQ(d.points[15], Vec3(25, 10, -15));  // the pulled corner
    EXPECT_EQ(d.tess.outer[0], 25.0f);
    // A Bézier patch interpolates its corners.
    const Net16 net = gatherNet(d, d.patches[0].idx);
    EXPECT_NEAR(evaluateNet(net, Basis::Bezier, 0.5, 0.0, 0.0).p.x, -10.0, 1e-12);
    EXPECT_FLOAT_EQ(notesDistanceLevel(20.0f), 64.0f);
    EXPECT_FLOAT_EQ(notesDistanceLevel(100.0f), 0.0f);
    EXPECT_FLOAT_EQ(notesDistanceLevel(60.0f), 32.0f);
    EXPECT_FLOAT_EQ(notesDistanceLevel(5.0f), 64.0f);
    TessSettings t;
    applyNotesDistanceFormula(t);
    EXPECT_EQ(t.adaptive, AdaptiveMode::Distance);
    EXPECT_EQ(t.distanceNear, 20.0f);
    EXPECT_EQ(t.distanceFar, 100.0f);
    EXPECT_TRUE(t.cullFar);  // level 0 beyond d1 culls, as the notes say
}

// The terrain notes' formula: 2^lerp(20, 4, saturate((d - 10) / 190)), the tessellator clamping it
// to 64 up to d = 10 + 190 * 14 / 16 = 176.25, 16 at 200 and beyond; edges from their midpoints,
// inner from the centre, fractional_even; the first notes' formula from the centre or per edge.
TEST(TessPresets, TerrainNotesFormula) {
    TessSettings t;
    applyNotesTerrainFormula(t);
    EXPECT_EQ(t.distanceCurve, DistanceCurve::Pow2);
    EXPECT_EQ(t.distanceFrom, DistanceFrom::EdgesInnerCentre);
    EXPECT_EQ(t.spacing, Spacing::FractionalEven);
    EXPECT_FALSE(t.cullFar);
    EXPECT_FALSE(t.heightDetail);
    const auto level = [&](float d) {
        return gpu::distanceLevel(d, t.maxLevel, t.distanceNear, t.distanceFar, uint32_t(t.distanceCurve),
                                  glm::vec2(t.distanceExponents[0], t.distanceExponents[1]));
    };
    EXPECT_FLOAT_EQ(level(10.0f), std::pow(2.0f, 20.0f));
    EXPECT_FLOAT_EQ(level(176.25f), 64.0f);
    EXPECT_FLOAT_EQ(level(200.0f), 16.0f);
    EXPECT_FLOAT_EQ(level(500.0f), 16.0f);
    EXPECT_NEAR(level(105.0f), std::pow(2.0f, 12.0f), 1e-2f);
    applyNotesDistanceFormula(t);
    EXPECT_EQ(t.distanceCurve, DistanceCurve::Linear);
    EXPECT_EQ(t.distanceFrom, DistanceFrom::Centre);
    applyNotesDistanceFormula(t, false);
    EXPECT_EQ(t.distanceFrom, DistanceFrom::Edges);
}

// The notes' rounding table (second notes, "partitioning"): integer 3.0→3, 3.25→4, 3.75→4, 4.25→5,
// 4.75→5; fractional_odd 3, 5, 5, 5, 5, 5 sliding by (f − 3) / (5 − 3) · 100; fractional_even 4, 4,
// 4, 6, 6, 6 by (f − 4) / (6 − 4) · 100; pow2 4, 4, 4, 8, 8, 8. `patchwork rounding` prints it and
// draws it as a slide; bad levels are exit 2 with nothing written.
TEST(TessPresets, RoundingTableIsTheNotes) {
    const std::vector<RoundingRow> rows = roundingTable(notesRoundingLevels());
    ASSERT_EQ(rows.size(), 4u);
    const std::vector<std::vector<int>> notes{{3, 4, 4, 5, 5, 5}, {3, 5, 5, 5, 5, 5}, {4, 4, 4, 6, 6, 6}, {4, 4, 4, 8, 8, 8}};
    for (size_t r = 0; r < 4; ++r)
        for (size_t c = 0; c < 6; ++c) EXPECT_EQ(rows[r].cells[c].segments, notes[r][c]) << spacingName(rows[r].spacing) << " " << c;
    const float levels[6] = {3.0f, 3.25f, 3.75f, 4.25f, 4.75f, 5.0f};
    for (size_t c = 0; c < 6; ++c) {
        const float f = levels[c];
        const float odd = (f - 3.0f) / (5.0f - 3.0f) * 100.0f, even = f < 4.0f ? (f - 2.0f) * 50.0f : (f - 4.0f) / (6.0f - 4.0f) * 100.0f;
        EXPECT_FLOAT_EQ(rows[1].cells[c].slide, odd > 0.0f && odd < 100.0f ? odd : -1.0f) << f;
        EXPECT_FLOAT_EQ(rows[2].cells[c].slide, even > 0.0f && even < 100.0f ? even : -1.0f) << f;
        EXPECT_LT(rows[0].cells[c].slide, 0.0f);
        EXPECT_LT(rows[3].cells[c].slide, 0.0f);
    }
    const auto dir = test::freshTempDir("rounding");
    const test::RunResult r = test::runCommand(test::patchworkBinary().string() + " rounding -o " + (dir / "t.svg").string() + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("fractional_odd [1, 3, ..., 63]    3          5 (12.5 %)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("pow2 [1, 2, 4, ..., 64]           4          4            4            8"), std::string::npos) << r.output;
    EXPECT_GT(std::filesystem::file_size(dir / "t.svg"), 1000u);
    for (const std::string bad : {"--levels 0.5", "--levels 3,x", "--levels 65", "--size 0x10"}) {
        const test::RunResult b =
            test::runCommand(test::patchworkBinary().string() + " rounding " + bad + " -o " + (dir / "x.png").string() + " 2>&1");
        EXPECT_EQ(b.exitCode, 2) << bad << ": " << b.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << bad;
    }
}

// The second notes' version of the patch: its raised points and level 15 under integer
// partitioning, y-up like the first; versions other than 1 and 2 are refused.
TEST(TessPresets, SecondNotesPatchVersion) {
    const Document d = notesBezierPatch(2);
    ASSERT_EQ(d.points.size(), 16u);
    EXPECT_EQ(d.points[0], Vec3(-10, -20, 15));
    EXPECT_EQ(d.points[6], Vec3(5, 30, 5));
    EXPECT_EQ(d.points[15], Vec3(25, 20, -15));
    EXPECT_EQ(d.tess.outer[2], 15.0f);
    EXPECT_EQ(d.tess.inner[1], 15.0f);
    EXPECT_EQ(d.tess.spacing, Spacing::Equal);
    EXPECT_FALSE(d.camera.zUp);
    EXPECT_NE(d.name, notesBezierPatch(1).name);
    EXPECT_THROW(notesBezierPatch(3), std::invalid_argument);
    EXPECT_THROW(notesBezierPatch(0), std::invalid_argument);
}

// The notes' patch is y-up data: it is shown upright (issue 41), +y up on screen, the whole net in
// the frame and the surface's front (du x dv) towards the camera.
TEST(TessPresets, NotesBezierPatchStandsUpright) {
    const Document d = notesBezierPatch();
    EXPECT_FALSE(d.camera.zUp);
    const ViewMatrices vm = viewMatrices(d.camera, 16.0 / 9.0);
    std::vector<glm::dvec2> px;
    for (const Vec3& p : d.points) {
        const auto q = projectToPixel(vm, glm::dvec3(p.x, p.y, p.z), 1600, 900);
        ASSERT_TRUE(q.has_value());
        EXPECT_GE(q->x, 0.0);
        EXPECT_LE(q->x, 1600.0);
        EXPECT_GE(q->y, 0.0);
        EXPECT_LE(q->y, 900.0);
        px.push_back(*q);
    }
    // The data's up (+y) is up on screen, straight above the patch's middle.
    const auto mid = projectToPixel(vm, glm::dvec3(0, 0, 0), 1600, 900), above = projectToPixel(vm, glm::dvec3(0, 10, 0), 1600, 900);
    ASSERT_TRUE(mid && above);
    EXPECT_LT(above->y, mid->y - 100.0);
    EXPECT_NEAR(above->x, mid->x, 10.0);  // upright: vertical up to perspective
    EXPECT_LT(px[6].y, px[5].y);          // the raised point above its row neighbours
    EXPECT_LT(px[6].y, px[7].y);
    const Net16 net = gatherNet(d, d.patches[0].idx);
    const auto c = evaluateNet(net, Basis::Bezier, 0.5, 0.5, 0.5);
    const Vec3 eye = Vec3(vm.eye.x, vm.eye.y, vm.eye.z);
    EXPECT_GT(glm::dot(c.n, eye - c.p), 0.0);
}

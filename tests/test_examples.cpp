// The examples in data/ that README names (issue 21): each .patchwork is exactly what its
// .pwscript makes through `patchwork edit` (regenerate with PATCHWORK_REGENERATE_DATA=1), opens, and
// is what it says: the G2 pair holds G2 within the default tolerances, the tube is a closed C2
// B-spline net, the Catmull-Rom net interpolates its points, the exact sphere is rational
// (its export is checked in tests/test_rational_export.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/vec2.hpp>
#include <map>

#include <nlohmann/json.hpp>
#include "core/edit/edit_session.hpp"
#include "core/edit/live_trims.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/io/document_io.hpp"
#include "core/io/step_export.hpp"
#include "core/solve/continuity_report.hpp"
#include "core/trim/curve_on_surface.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"
#include "core/trim/trim_mesh.hpp"
#include "tests/support.hpp"

using namespace pw;
using namespace pw::test;

namespace {

// Runs data/NAME.pwscript and returns the document it wrote; checks data/NAME.patchwork holds the
// same bytes (or rewrites it when PATCHWORK_REGENERATE_DATA is set).
Document made(const std::string& name) {
    const std::filesystem::path dir = freshTempDir("examples_" + name);
    const std::filesystem::path out = dir / (name + ".patchwork"), script = dataDir() / (name + ".pwscript");
    const RunResult r = runCommand(patchworkBinary().string() + " edit -q -o '" + out.string() + "' --run '" + script.string() + "' 2>&1");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const std::filesystem::path stored = dataDir() / (name + ".patchwork");
    if (std::getenv("PATCHWORK_REGENERATE_DATA"))
        std::filesystem::copy_file(out, stored, std::filesystem::copy_options::overwrite_existing);
    EXPECT_EQ(readBytes(out), readBytes(stored)) << stored << " is not what " << script << " makes";
    return loadDocument(stored);
}

}  // namespace

TEST(Examples, G2PairHoldsG2) {
    const Document doc = made("g2_pair");
    ASSERT_EQ(doc.patches.size(), 2u);
    ASSERT_EQ(doc.joins.size(), 1u);
    EXPECT_EQ(doc.joins[0].continuity, Continuity::G2);
    const auto report = continuityReport(doc);
    EXPECT_EQ(toleranceFailures(report[0], Continuity::G2, doc.tolerances), kWithinTolerance);
    EXPECT_LE(report[0].curvatureDeviationPct, 1e-6);
    EXPECT_GT(report[0].maxCurvature, 0.05);  // really bent across the seam
    EXPECT_TRUE(doc.display.showCombs);
}

TEST(Examples, BSplineTubeIsAClosedC2Net) {
    const Document doc = made("bspline_tube");
    ASSERT_EQ(doc.surfaces.size(), 1u);
    EXPECT_EQ(doc.surfaces[0].basis, Basis::BSpline);
    EXPECT_TRUE(doc.surfaces[0].closedU || doc.surfaces[0].closedV);
    // It does not fold: the normal points away from the axis (z) everywhere, and one way. (A bump
    // moved along the axis past its neighbouring rows once turned 526 triangles inside out.)
    size_t outward = 0, inward = 0;
    for (const PatchInstance& w : expandPatches(doc)) {
        const Net16 net = gatherNet(doc, w.idx);
        for (int i = 0; i <= 16; ++i)
            for (int j = 0; j <= 16; ++j) {
                const SurfacePoint sp = evaluateNet(net, w.basis, w.tension, j / 16.0, i / 16.0);
                (glm::dot(sp.n, Vec3(sp.p.x, sp.p.y, 0.0)) > 0.0 ? outward : inward) += 1;
            }
    }
    EXPECT_TRUE(outward == 0 || inward == 0) << outward << " samples face out, " << inward << " in";
}

TEST(Examples, CatmullRomNetInterpolates) {
    const Document doc = made("catmull_rom_net");
    ASSERT_EQ(doc.surfaces.size(), 1u);
    const Surface& s = doc.surfaces[0];
    EXPECT_EQ(s.basis, Basis::CatmullRom);
    // The first window passes through its inner control points at its corners.
    const std::vector<PatchInstance> w = expandPatches(doc);
    ASSERT_FALSE(w.empty());
    const Net16 net = gatherNet(doc, w[0].idx);
    const SurfacePoint p = evaluateNet(net, Basis::CatmullRom, s.tension, 0.0, 0.0);
    EXPECT_LT(glm::length(p.p - net[5]), 1e-12);
}

TEST(Examples, ExactSphereIsEightRationalPatchesOnTheUnitSphere) {
    const Document doc = made("exact_sphere");
    ASSERT_EQ(doc.patches.size(), 8u);
    EXPECT_TRUE(isRational(doc));
    for (const Vec3& p : doc.points) EXPECT_LE(glm::length(p), std::sqrt(2.0) + 1e-12);  // the control points hug it
    EXPECT_EQ(doc.display.shading, ShadingMode::MeanCurvature);
    EXPECT_TRUE(doc.display.showCombs);
}

// The vase (issue 39): one live revolve of a curve through points; every vertex of its OBJ export
// (float coordinates, +Y up) lies on the surface of revolution of the profile, that is its
// (radius, height) lies on the profile curve, within float precision.
TEST(Examples, VaseIsExactlyItsRevolvedProfile) {
    const Document doc = made("vase");
    ASSERT_EQ(doc.constructions.size(), 1u);
    EXPECT_EQ(doc.constructions[0].kind, ConstructionKind::Revolve);
    ASSERT_EQ(doc.patches.size(), 20u);
    const BezierCurve& prof = doc.curves[0];
    // The profile in its plane (x = radius, z = height), densely sampled.
    std::vector<glm::dvec2> samples;
    for (const Vec3& p : sampleCurve(doc, prof, 4000)) samples.emplace_back(p.x, p.z);
    const std::filesystem::path dir = freshTempDir("vase_obj");
    saveDocument(doc, dir / "vase.obj");
    std::ifstream in(dir / "vase.obj");
    std::string line;
    double worst = 0.0;
    size_t vertices = 0;
    const double step = 3.2 / 4000.0;  // the samples' spacing is below this
    while (std::getline(in, line)) {
        if (line.rfind("v ", 0) != 0) continue;
        double x = 0, y = 0, z = 0;
        ASSERT_EQ(std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z), 3);
        const glm::dvec2 q(std::hypot(x, z), y);
        // Distance to the sampled polyline: the nearest sample and its two segments.
        size_t best = 0;
        for (size_t i = 1; i < samples.size(); ++i)
            if (glm::length(samples[i] - q) < glm::length(samples[best] - q)) best = i;
        double d = glm::length(samples[best] - q);
        for (size_t j : {best, best + 1})
            if (j > 0 && j < samples.size()) {
                const glm::dvec2 a = samples[j - 1], b = samples[j];
                const double t = std::clamp(glm::dot(q - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
                d = std::min(d, glm::length(a + t * (b - a) - q));
            }
        worst = std::max(worst, d);
        ++vertices;
    }
    EXPECT_GT(vertices, 1000u);
    // Float coordinates of a 3-unit model (~2e-7) and the chord of the sampled profile (~step² κ).
    EXPECT_LT(worst, 1e-6) << "the farthest of " << vertices << " vertices, with samples every " << step;
    std::filesystem::remove_all(dir);
}

TEST(Examples, BottleLoftPassesThroughItsCircles) {
    const Document doc = made("bottle");
    ASSERT_EQ(doc.constructions.size(), 1u);
    const Construction& k = doc.constructions[0];
    EXPECT_EQ(k.kind, ConstructionKind::Loft);
    ASSERT_EQ(k.patches.size(), 20u);
    for (size_t sec = 0; sec < 6; ++sec)
        for (size_t q = 0; q < 4; ++q) {
            const uint32_t patch = k.patches[std::min<size_t>(sec, 4) * 4 + q];
            const double v = sec < 5 ? 0.0 : 1.0;
            const Vec3 a = evaluateWindow(gatherWindow(doc, doc.patches[patch].idx), Basis::Bezier, 0.5, 0.5, v).p;
            const std::array<uint32_t, 4> i = curveSegment(doc.curves[sec], q);
            const Vec3 b =
                evaluateRationalCurve(curvePoints(doc, doc.curves[sec], q),
                                      {pointWeight(doc, i[0]), pointWeight(doc, i[1]), pointWeight(doc, i[2]), pointWeight(doc, i[3])}, 0.5)
                    .p;
            EXPECT_LT(glm::length(a - b), 1e-12) << "section " << sec;
        }
}

TEST(Examples, PipeIsACircleSweptAlongARail) {
    const Document doc = made("pipe");
    ASSERT_EQ(doc.constructions.size(), 1u);
    const Construction& k = doc.constructions[0];
    EXPECT_EQ(k.kind, ConstructionKind::Sweep1);
    const size_t pieces = std::max<size_t>(1, k.split);  // each rail segment split until within tolerance
    ASSERT_EQ(k.patches.size(), 4u * pieces * 4u);
    // At each segment end of the rail, the section is the circle of radius 0.3 about the rail.
    for (size_t s = 0; s < 4; ++s) {
        const Vec3 centre = doc.points[doc.curves[0].idx[3 * s]];
        for (double u : {0.0, 0.5}) {
            const Vec3 p = evaluateWindow(gatherWindow(doc, doc.patches[k.patches[s * pieces * 4]].idx), Basis::Bezier, 0.5, u, 0.0).p;
            EXPECT_NEAR(glm::length(p - centre), 0.3, 1e-12);
        }
    }
}

// The 3 x 3 network shell: every one of its eight curves is an isocurve of the surface.
TEST(Examples, NetworkShellPassesThroughEveryCurve) {
    const Document doc = made("network");
    ASSERT_EQ(doc.constructions.size(), 1u);
    const Construction& k = doc.constructions[0];
    EXPECT_EQ(k.kind, ConstructionKind::Network);
    ASSERT_EQ(k.patches.size(), 9u);
    const auto at = [&](size_t row, size_t col, double u, double v) { return test::patchPointAt(doc, k.patches[row * 3 + col], u, v); };
    const auto curve = [&](size_t c, size_t seg, double t) { return test::curvePointAt(doc, doc.curves[c], seg, t); };
    for (size_t r = 0; r < 4; ++r)
        for (size_t seg = 0; seg < 3; ++seg)
            for (double t : {0.0, 0.35, 0.8}) {
                EXPECT_LT(glm::length(at(std::min<size_t>(r, 2), seg, t, r < 3 ? 0.0 : 1.0) - curve(r, seg, t)), 1e-12);
                EXPECT_LT(glm::length(at(seg, std::min<size_t>(r, 2), r < 3 ? 0.0 : 1.0, t) - curve(4 + r, seg, t)), 1e-12);
            }
}

namespace {

// The largest normal angle over the seams, and the seam count, that `patchwork info --json` reports.
std::pair<double, size_t> infoWorstAngle(const std::filesystem::path& file) {
    const RunResult r = runCommand(patchworkBinary().string() + " info --json '" + file.string() + "' 2>&1");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output, nullptr, false);
    double worst = 0.0;
    size_t seams = 0;
    if (!j.is_object() || !j.contains("joinReport")) {
        ADD_FAILURE() << r.output;
        return {0.0, 0};
    }
    for (const auto& join : j["joinReport"]) {
        worst = std::max(worst, join["normalAngleDeg"].get<double>());
        ++seams;
    }
    return {worst, seams};
}

}  // namespace

TEST(Examples, RoundedBoxIsG1OnEverySeamBeforeAndAfterScriptedDrags) {
    const Document doc = made("rounded_box");
    ASSERT_EQ(doc.patches.size(), 54u);  // 6 faces, 12 blends split along their length, 8 corners of 3
    ASSERT_EQ(doc.joins.size(), 108u);
    for (const Join& j : doc.joins) EXPECT_TRUE(holdsTangent(j.continuity));
    const auto [worst, seams] = infoWorstAngle(dataDir() / "rounded_box.patchwork");
    EXPECT_EQ(seams, 108u);
    EXPECT_LE(worst, 0.1);
    // Drag points of every kind (a corner's centre, a point beside it, a blend's, a face's corner)
    // through `patchwork edit`; info --json must still find every seam within 0.1°.
    const std::filesystem::path dir = freshTempDir("rounded_box_drag");
    const uint32_t centre = doc.patches[30].idx[15], beside = doc.patches[31].idx[5], blend = doc.patches[8].idx[6];
    const uint32_t face = doc.patches[0].idx[0];
    int n = 0;
    for (const auto& [pt, move] :
         {std::pair{centre, "0.05 -0.03 0.04"}, {beside, "0.02 0.05 -0.03"}, {blend, "-0.06 0.02 0.03"}, {face, "0 0 0.15"}}) {
        const std::filesystem::path out = dir / ("drag" + std::to_string(n++) + ".patchwork");
        const RunResult r = runCommand(patchworkBinary().string() + " edit -q '" + (dataDir() / "rounded_box.patchwork").string() +
                                       "' -o '" + out.string() + "' -c 'select point " + std::to_string(pt) + "; move " + move + "' 2>&1");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const auto [after, count] = infoWorstAngle(out);
        EXPECT_EQ(count, 108u);
        EXPECT_LE(after, 0.1) << "after moving point " << pt;
        EXPECT_NE(readBytes(out), readBytes(dataDir() / "rounded_box.patchwork"));  // the drag moved something
    }
}

// `info` gives the surface's box beside the control points' (issue 42): the teapot's spout tip is
// at x = 3.43 while its control points reach 3.525; both stand on z = 0 and reach z = 3.15.
TEST(InfoCli, SurfaceBoundsAreTheSurfacesNotTheControlBox) {
    const RunResult r = runCommand(patchworkBinary().string() + " info --json '" + (dataDir() / "teapot.bpt").string() + "' 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output, nullptr, false);
    ASSERT_TRUE(j.is_object() && j["surfaceBounds"].is_object()) << r.output;
    const double controlX = j["bounds"]["max"][0].get<double>(), surfaceX = j["surfaceBounds"]["max"][0].get<double>();
    EXPECT_NEAR(controlX, 3.525, 1e-9);
    EXPECT_GT(surfaceX, 3.4);
    EXPECT_LT(surfaceX, controlX - 0.05);
    EXPECT_NEAR(j["surfaceBounds"]["min"][2].get<double>(), 0.0, 1e-6);
    EXPECT_NEAR(j["surfaceBounds"]["max"][2].get<double>(), j["bounds"]["max"][2].get<double>(), 1e-6);
    const RunResult text = runCommand(patchworkBinary().string() + " info '" + (dataDir() / "teapot.bpt").string() + "' 2>&1");
    EXPECT_NE(text.output.find("(the surface at level 8)"), std::string::npos) << text.output;
}

// The trimmed examples (issue 64). The kettle: three nets cut by three live intersections; every
// trim edge closed to a few millionths, and after its spout is dragged the curves and all six trims
// have followed, the edges as close. Its mesh has open edges only at the tubes' open rims, none
// along a cut.
TEST(Examples, KettleSpoutAndHandleAreCutInByLiveIntersections) {
    const Document doc = made("kettle");
    ASSERT_EQ(doc.surfaces.size(), 3u);
    ASSERT_EQ(doc.curves.size(), 3u);
    for (const BezierCurve& c : doc.curves) {
        ASSERT_TRUE(c.link);
        EXPECT_TRUE(curveClosed(c));
    }
    EXPECT_EQ(doc.surfaces[0].trims.size(), 3u);
    EXPECT_EQ(doc.surfaces[1].trims.size(), 1u);
    EXPECT_EQ(doc.surfaces[2].trims.size(), 2u);
    const double size = modelSize(doc);
    for (const TrimEdgeGap& g : trimEdgeGaps(doc)) EXPECT_LT(g.gap, 1e-5 * size) << "c" << g.curve;
    EditSession s;
    s.reset(doc, "");
    test::runEditScript(s, "select net 1; move 0 0.08 0.06");
    EXPECT_NE(s.doc.surfaces[0].trims[0].uv, doc.surfaces[0].trims[0].uv);  // the body's hole moved with the spout
    EXPECT_NE(s.doc.surfaces[1].trims[0].uv, doc.surfaces[1].trims[0].uv);
    for (const BezierCurve& c : s.doc.curves) EXPECT_EQ(c.link->error, "");
    for (const TrimEdgeGap& g : trimEdgeGaps(s.doc)) EXPECT_LT(g.gap, 1e-5 * size) << "c" << g.curve << " after the drag";
    // Watertight along every cut: no open edge near a trim curve.
    const TriangleMesh mesh = tessellateTrimmed(s.doc, 8);
    std::vector<Vec3> cuts;
    for (const BezierCurve& c : s.doc.curves)
        for (const Vec3& p : sampleCurve(s.doc, c)) cuts.push_back(p);
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = mesh.indices[t + size_t(k)], b = mesh.indices[t + size_t((k + 1) % 3)];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    size_t open = 0, alongCut = 0, overused = 0;
    for (const auto& [e, n] : uses) {
        overused += n > 2 ? 1 : 0;
        if (n != 1) continue;
        ++open;
        const auto& p = mesh.positions[e.first];
        double nearest = 1e300;
        for (const Vec3& q : cuts) nearest = std::min(nearest, glm::length(Vec3(p[0], p[1], p[2]) - q));
        alongCut += nearest < 1e-4 * size ? 1 : 0;
    }
    EXPECT_GT(open, 0u);  // the body's top and bottom, the spout's and the handle's open rims: none cut
    EXPECT_EQ(alongCut, 0u);
    EXPECT_EQ(overused, 0u);  // no edge laid twice, not even where a seam of one surface meets a window line of the other
}

// The plate's two holes and the L: areas as the curves say, and the L's STEP face the L.
TEST(Examples, APlateWithHolesAndAnLOutline) {
    const Document plate = made("trimmed_plate");
    ASSERT_EQ(plate.patches.size(), 1u);
    ASSERT_EQ(plate.patches[0].trims.size(), 2u);
    const double plateArea = trimmedArea(DomainSurface(plate, {false, 0}), plate.patches[0].trims);
    EXPECT_LT(plateArea, 12.0 - 3.14159265358979 * 0.25);
    EXPECT_GT(plateArea, 9.0);
    const Document l = made("l_part");
    ASSERT_EQ(l.patches[0].trims.size(), 1u);
    EXPECT_NEAR(trimmedArea(DomainSurface(l, {false, 0}), l.patches[0].trims), 3.8, 1e-9);
    EXPECT_NE(exportStepText(l, {}).find("ADVANCED_FACE"), std::string::npos);
}

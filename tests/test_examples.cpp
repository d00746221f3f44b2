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

#include "core/eval/patch_eval.hpp"
#include "core/io/document_io.hpp"
#include "core/solve/continuity_report.hpp"
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

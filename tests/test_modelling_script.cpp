// `patchwork edit` models a 4-patch C1 cushion from an empty document without a window (issue 19):
// a quarter whose rows meet the symmetry planes at right angles, mirrored across X and Y through the
// 3D cursor, then rotated and moved as a whole; `info --json` on the saved file reads the joins.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support.hpp"

using namespace pw::test;

TEST(ModellingScript, CushionFromAnEmptyDocumentByMirroring) {
    const auto dir = freshTempDir("cushion");
    const auto out = dir / "cushion.patchwork";
    const std::string script =
        "add-patch; "
        "select point 0,1,4,5; move 0 0 0.4; select point 2,6,8,9; move 0 0 0.2; select point 10; move 0 0 0.1; "
        "select patch 0; move 0.5 0.5 0; cursor 0 0 0; mirror X; select all; mirror Y; "
        "select all; pivot cursor; rotate Z 30; move 1 0 0";
    const RunResult made = runCommand("'" + patchworkBinary().string() + "' edit -c '" + script + "' -o '" + out.string() + "' 2>&1");
    ASSERT_EQ(made.exitCode, 0) << made.output;
    const RunResult info = runCommand("'" + patchworkBinary().string() + "' info --json '" + out.string() + "' 2>&1");
    ASSERT_EQ(info.exitCode, 0) << info.output;
    const nlohmann::json j = nlohmann::json::parse(info.output);
    EXPECT_EQ(j["patches"], 4);
    EXPECT_EQ(j["points"], 49);  // 7 x 7: the seams share their points
    EXPECT_EQ(j["joins"]["C1"], 4);
    EXPECT_EQ(j["joins"]["total"], 4);
    EXPECT_LT(j["maxConstraintResidual"].get<double>(), 1e-12);
    EXPECT_LT(j["largest"]["normalAngleDeg"].get<double>(), 1e-9);
    // Rotated 30° about the cursor (the cushion's centre) and moved by +1 in x: the centre is at x = 1.
    const double minX = j["bounds"]["min"][0], maxX = j["bounds"]["max"][0];
    EXPECT_NEAR(0.5 * (minX + maxX), 1.0, 1e-12);
    EXPECT_NEAR(maxX - minX, 2.0 * (std::cos(M_PI / 6) + std::sin(M_PI / 6)), 1e-12);  // a 2 x 2 square turned 30°
    EXPECT_DOUBLE_EQ(j["bounds"]["max"][2].get<double>(), 0.4);

    // A mistake names the script line and leaves no file.
    const auto bad = dir / "bad.patchwork";
    const RunResult err = runCommand("'" + patchworkBinary().string() + "' edit -c 'add-patch; mirror Q' -o '" + bad.string() + "' 2>&1");
    EXPECT_EQ(err.exitCode, 2);
    EXPECT_NE(err.output.find("expected an axis X, Y or Z"), std::string::npos) << err.output;
    EXPECT_FALSE(std::filesystem::exists(bad));
}

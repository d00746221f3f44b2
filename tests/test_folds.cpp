// Issue 73's fold invariant, beyond the joins themselves: a surface never satisfies a constraint by
// folding. A move whose joins drag a neighbour over is refused naming the patch and its joins; a
// construction that would make a turned-over patch is refused; what a file brings, and copies of a
// fold the model already had, are not; a pole's zero-area triangles are no fold.
#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/construct/model_builders.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/fold_check.hpp"
#include "support.hpp"

using namespace pw;

namespace {

// The refusal's text, or "" when the script was accepted.
std::string refusal(EditSession& s, const std::string& script) {
    try {
        test::runEditScript(s, script);
        return "";
    } catch (const std::exception& e) {
        return e.what();
    }
}

}  // namespace

TEST(Folds, APolesZeroAreaTrianglesAreNoFold) {
    EditSession s;
    s.open((test::dataDir() / "exact_sphere.patchwork").string());
    int poles = 0;
    for (uint32_t p = 0; p < s.doc.patches.size(); ++p) {
        const PatchShape shape = patchShape(s.doc, p);
        EXPECT_EQ(shape.invertedTriangles, 0) << "patch " << p;
        poles += shape.collapsedCorners > 0;
    }
    EXPECT_EQ(poles, 8);  // every patch of the sphere has a pole; its triangles there have no area
}

TEST(Folds, AMoveWhoseJoinsDragANeighbourOverIsRefusedNamingIt) {
    EditSession s;
    s.reset(makePatchGrid(2, 2, Continuity::C1), "");
    const Document before = s.doc;
    // A corner patch turned a quarter about its centre: its C1 neighbours cannot follow unfolded.
    const std::string why = refusal(s, "select patch 0; rotate Z 90");
    EXPECT_NE(why.find("holding its joins would fold patch 1"), std::string::npos) << why;
    EXPECT_NE(why.find("at join 0 (patch 0 u1 – patch 1 u0, C1)"), std::string::npos) << why;
    EXPECT_EQ(s.doc, before);
    // Less far, the neighbours follow without turning over; a rigid move of everything is no fold.
    EXPECT_EQ(refusal(s, "select patch 0; rotate Z 10; move 0 0 1"), "");
    EXPECT_EQ(refusal(s, "select all; rotate Z 90; move 3 0 0"), "");
    // A patch with no join is the user's own to shape, a turned-over one included.
    EditSession lone;
    test::runEditScript(lone, "add-patch");
    EXPECT_EQ(refusal(lone, "point 5 2 2 0"), "");
    EXPECT_GT(patchShape(lone.doc, 0).invertedTriangles, 0);
}

TEST(Folds, AConstructionThatWouldMakeATurnedOverPatchIsRefused) {
    EditSession s;
    s.open((test::dataDir() / "trimmed_plate.patchwork").string());
    const Document before = s.doc;
    // A G1 blend from a flat plate's right edge back into its own left edge must turn over.
    const std::string why = refusal(s, "blend 0:u1 0:u0 G1");
    EXPECT_NE(why.find("it would make a folded surface, new patch 1 ("), std::string::npos) << why;
    EXPECT_EQ(s.doc, before);
}

TEST(Folds, AFilesFoldsComeInAndTheirCopiesMayCarryThem) {
    EditSession s;
    s.open((test::dataDir() / "teapot.bpt").string());
    s.import((test::dataDir() / "teaspoon.bpt").string());  // the spoon's bowl has turned-over triangles of its own
    uint32_t folded = 0;
    while (folded < s.doc.patches.size() && patchShape(s.doc, folded).invertedTriangles == 0) ++folded;
    ASSERT_LT(folded, s.doc.patches.size());
    const size_t patches = s.doc.patches.size();
    EXPECT_EQ(refusal(s, "select patch " + std::to_string(folded) + "; duplicate"), "");
    EXPECT_EQ(s.doc.patches.size(), patches + 1);
}

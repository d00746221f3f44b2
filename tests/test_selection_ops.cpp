// Selection for real models (core/select/selection_ops.hpp and the select / hide / unhide commands):
// linked, invert, hide and reveal, hidden items neither picked nor selected, saved and undone.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/model_builders.hpp"
#include "core/edit/edit_session.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/model/camera_math.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/select/picking.hpp"
#include "core/select/selection_ops.hpp"

#include "support.hpp"

using namespace pw;

namespace {

void run(EditSession& s, const std::string& script) { test::runEditScript(s, script); }

// A C1-joined 2x2 grid (points 0..48) and a separate flat patch beside it (patch 4).
EditSession gridAndPatch() {
    EditSession s;
    Document d = makePatchGrid(2, 2, Continuity::C1);
    addFlatPatch(d, Vec3(5.0, 0.0, 0.0), 1.0);
    s.reset(d, "");
    return s;
}

bool has(const std::vector<uint32_t>& v, uint32_t p) { return std::binary_search(v.begin(), v.end(), p); }

}  // namespace

TEST(SelectionOps, LinkedSelectsTheConnectedItemsOnly) {
    EditSession s = gridAndPatch();
    run(s, "select point 0; select linked");
    EXPECT_EQ(s.sel.points.size(), 49u);  // the whole joined grid
    for (uint32_t p : s.doc.patches[4].idx) EXPECT_FALSE(has(s.sel.points, p));
    run(s, "select patch 4; select linked");
    EXPECT_EQ(s.sel.points.size(), 16u);
    run(s, "select invert");
    EXPECT_EQ(s.sel.points.size(), 49u);
    for (uint32_t p : s.doc.patches[4].idx) EXPECT_FALSE(has(s.sel.points, p));
    run(s, "select none");
    EXPECT_THROW(run(s, "select linked"), InputError);  // nothing to extend
}

TEST(SelectionOps, HideLeavesNeighboursAndIsNotPickedOrSelected) {
    EditSession s = gridAndPatch();
    const size_t steps = s.history().size();
    run(s, "select patch 0; hide");
    EXPECT_TRUE(s.doc.patches[0].hidden);
    for (size_t p = 1; p < s.doc.patches.size(); ++p) EXPECT_FALSE(s.doc.patches[p].hidden) << p;  // not its joined neighbours
    EXPECT_TRUE(s.sel.empty());
    EXPECT_EQ(s.history().size(), steps + 1);
    EXPECT_EQ(s.history().undoLabel(), "Hide");

    // The shown document: one patch fewer, the joins with it gone, the rest renumbered.
    const Document shown = visibleDocument(s.doc);
    EXPECT_EQ(shown.patches.size(), 4u);
    EXPECT_EQ(shown.points, s.doc.points);
    for (const Join& j : shown.joins) EXPECT_LT(std::max(j.patchA, j.patchB), 4u);
    EXPECT_LT(shown.joins.size(), s.doc.joins.size());

    // A ray straight down through patch 0's centre finds nothing; through patch 1 it finds patch 1.
    const auto down = [](double x, double y) { return Ray{Vec3(x, y, 5.0), Vec3(0.0, 0.0, -1.0)}; };
    EXPECT_FALSE(pickSurface(s.doc, down(0.5, 0.5)).has_value());
    const auto hit = pickSurface(s.doc, down(1.5, 0.5));
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->patch, 1);

    // Select all takes the shown points only: patch 0's own inner points are not among them.
    run(s, "select all");
    EXPECT_FALSE(has(s.sel.points, s.doc.patches[0].idx[5]));
    EXPECT_TRUE(has(s.sel.points, s.doc.patches[0].idx[15]));  // shared with shown neighbours

    // Saved and read back with the flag.
    const Document back = parseDocument(serializeDocument(s.doc), "hidden.patchwork");
    EXPECT_TRUE(back.patches[0].hidden);
    EXPECT_EQ(back, s.doc);

    // Alt+H reveals and selects what it revealed; undo hides again.
    run(s, "unhide");
    EXPECT_FALSE(anyHidden(s.doc));
    EXPECT_EQ(s.sel.points.size(), 16u);
    EXPECT_EQ(s.history().undoLabel(), "Reveal hidden");
    run(s, "undo");
    EXPECT_TRUE(s.doc.patches[0].hidden);
}

TEST(SelectionOps, HideUnselectedKeepsWhatTheSelectionTouches) {
    EditSession s = gridAndPatch();
    run(s, "select patch 4; hide unselected");
    for (size_t p = 0; p < 4; ++p) EXPECT_TRUE(s.doc.patches[p].hidden) << p;
    EXPECT_FALSE(s.doc.patches[4].hidden);
    EXPECT_EQ(s.history().undoLabel(), "Hide unselected");
    // Points only: a patch is hidden when all its points are selected, not when it shares one.
    run(s, "unhide; select point 0");
    EXPECT_THROW(run(s, "hide"), InputError);  // refused: nothing whole to hide
    EXPECT_FALSE(anyHidden(s.doc));
    EXPECT_THROW(run(s, "hide sideways"), InputError);
}

// The editing session without a window: commit / undo / redo, import of every kind of content,
// the save rule, and the command table run as scripts (core/commands/command_table.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/model_builders.hpp"
#include "core/io/document_io.hpp"
#include "core/model/document_merge.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/solve/constraint_solver.hpp"
#include "support.hpp"

using namespace pw;
namespace fs = std::filesystem;

namespace {

class RecordingHost final : public CommandHost {
public:
    void write(const Document& doc, const std::string& path) override { writes.emplace_back(path, doc); }
    void saved(const std::string& path) override { savedPaths.push_back(path); }
    void status(const std::string& message) override { statuses.push_back(message); }
    std::vector<std::pair<std::string, Document>> writes;
    std::vector<std::string> savedPaths;
    std::vector<std::string> statuses;
};

void run(EditSession& s, const std::string& script) {
    RecordingHost host;
    makeCommandTable().runScript(s, host, script, "test");
}

// The message of a script that must fail, run on a new empty document.
std::string scriptError(const std::string& script) {
    EditSession s;
    RecordingHost host;
    try {
        makeCommandTable().runScript(s, host, script, "s.txt");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(EditSession, ApplyCommitsOneUndoStepAndUndoRestores) {
    EditSession s;
    s.reset(makePatchGrid(1, 2), "");
    const Document before = s.doc;
    s.apply("Flip", [](Document& d) { flipPatch(d, 0); });
    EXPECT_NE(s.doc, before);
    EXPECT_TRUE(s.isModified());
    EXPECT_EQ(s.history().undoLabel(), "Flip");
    EXPECT_TRUE(s.undo());
    EXPECT_EQ(s.doc, before);
    EXPECT_FALSE(s.isModified());
    EXPECT_TRUE(s.redo());
    EXPECT_NE(s.doc, before);
}

TEST(EditSession, FailedApplyLeavesTheDocumentAndHistory) {
    EditSession s;
    s.reset(makePatchGrid(1, 1), "");
    const Document before = s.doc;
    EXPECT_THROW(s.apply("Bad", [](Document& d) { extrudeEdge(d, 7, Edge::U0); }), std::exception);
    EXPECT_EQ(s.doc, before);
    EXPECT_FALSE(s.history().canUndo());
}

TEST(EditSession, MergeKeepsTrianglesCurvesNetsAndJoins) {
    Document into = makePatchGrid(1, 2);
    Document from = makePatchGrid(2, 2);  // 4 patches, 4 joins
    addCurve(from, Vec3(0.0), 1.0);
    addTriangle(from, Vec3(0.0), 1.0);
    const size_t points = into.points.size(), patches = into.patches.size(), joins = into.joins.size();
    const MergedRange r = mergeDocument(into, from);
    EXPECT_EQ(r.firstPatch, patches);
    EXPECT_EQ(into.patches.size(), patches + from.patches.size());
    EXPECT_EQ(into.joins.size(), joins + from.joins.size());
    EXPECT_EQ(into.triangles.size(), 1u);
    EXPECT_EQ(into.curves.size(), 1u);
    EXPECT_EQ(into.points.size(), points + from.points.size());
    // The imported joins name the imported patches and still hold.
    for (size_t j = joins; j < into.joins.size(); ++j) {
        EXPECT_GE(into.joins[j].patchA, patches);
        EXPECT_GE(into.joins[j].patchB, patches);
    }
    EXPECT_LT(maxConstraintResidual(into), 1e-9);
    // Every imported item's points are the source's, shifted.
    for (size_t k = 0; k < 10; ++k) EXPECT_EQ(into.points[into.triangles[0].idx[k]], from.points[from.triangles[0].idx[k]]);
    EXPECT_EQ(into.points[into.curves[0].idx[3]], from.points[from.curves[0].idx[3]]);
}

TEST(EditSession, ImportSelectsWhatArrivedAndIsOneUndoStep) {
    const fs::path dir = test::freshTempDir("import");
    Document from = makeTriangleDome();
    addCurve(from, Vec3(0.0), 1.0);
    saveDocument(from, dir / "dome.patchwork");
    EditSession s;
    s.reset(makePatchGrid(1, 1), "");
    const size_t before = s.doc.points.size();
    s.import((dir / "dome.patchwork").string());
    EXPECT_EQ(s.doc.triangles.size(), from.triangles.size());
    EXPECT_EQ(s.doc.curves.size(), 1u);
    EXPECT_EQ(s.sel.points.size(), from.points.size());
    EXPECT_EQ(s.sel.points.front(), before);
    s.undo();
    EXPECT_TRUE(s.doc.triangles.empty());
}

TEST(EditSession, SaveRuleKeepsThePathOnlyForLosslessFormats) {
    EditSession s;
    s.reset(makePatchGrid(1, 1), "a.bpt");
    s.apply("Flip", [](Document& d) { flipPatch(d, 0); });
    s.savedTo("export.bpt");
    EXPECT_EQ(s.path(), "a.bpt");
    EXPECT_TRUE(s.isModified());
    s.savedTo("b.patchwork");
    EXPECT_EQ(s.path(), "b.patchwork");
    EXPECT_FALSE(s.isModified());
    EXPECT_TRUE(saveKeepsEverything("x.glb"));
    EXPECT_FALSE(saveKeepsEverything("x.bpt"));
}

TEST(Commands, TableNamesAreUniqueAndEveryCommandIsDocumented) {
    const CommandTable t = makeCommandTable();
    EXPECT_GE(t.commands().size(), 30u);
    for (const Command& c : t.commands()) {
        SCOPED_TRACE(c.name);
        EXPECT_FALSE(c.label.empty());
        EXPECT_FALSE(c.help.empty());
        EXPECT_TRUE(bool(c.exec));
    }
    // Each shortcut belongs to one binding only.
    std::vector<std::string> keys;
    for (const Command& c : t.commands())
        for (const CommandBinding& b : c.bindings)
            for (const std::string& k : b.shortcuts) {
                EXPECT_EQ(std::count(keys.begin(), keys.end(), k), 0) << k << " is bound twice";
                keys.push_back(k);
            }
    for (const char* name : {"new", "open", "import", "select", "move", "rotate", "scale", "cursor", "add-patch", "join", "delete", "undo",
                             "redo", "save", "extrude", "split", "duplicate", "frame", "view"})
        EXPECT_NE(t.find(name), nullptr) << name;
}

TEST(Commands, ScriptBuildsAJoinedPairAndTransformsHoldTheJoin) {
    EditSession s;
    run(s, "add-patch  # one\ncursor 3 0 0; add-patch\njoin 0:u1 1:u0 C1\n");
    ASSERT_EQ(s.doc.patches.size(), 2u);
    ASSERT_EQ(s.doc.joins.size(), 1u);
    EXPECT_EQ(s.doc.joins[0].continuity, Continuity::C1);
    EXPECT_LT(maxConstraintResidual(s.doc), 1e-9);
    // A rigid move of everything keeps every point's offset exactly.
    const Document before = s.doc;
    run(s, "select all; move 1 2 -3");
    for (size_t i = 0; i < s.doc.points.size(); ++i)
        EXPECT_NEAR(glm::length(s.doc.points[i] - before.points[i] - Vec3(1, 2, -3)), 0.0, 1e-12);
    // Moving one patch alone goes through the solver: the join still holds.
    run(s, "select patch 1; rotate Z 30; scale 1.1");
    EXPECT_LT(maxConstraintResidual(s.doc), 1e-9);
    EXPECT_EQ(s.history().size(), 6u);  // 2 adds, join, move, rotate, scale
    run(s, "undo; undo; undo; undo; undo; undo");
    EXPECT_TRUE(s.doc.patches.empty());
}

TEST(Commands, RotateAndScaleUseTheMedianPoint) {
    EditSession s;
    run(s, "cursor 5 0 0; add-patch; select patch 0");
    const Vec3 c0 = selectionCentroid(s.doc, s.sel);
    run(s, "rotate Z 90; scale 2 2 2");
    EXPECT_NEAR(glm::length(selectionCentroid(s.doc, s.sel) - c0), 0.0, 1e-9);
    EXPECT_NEAR(c0.x, 5.0, 1e-9);
}

TEST(Commands, DeleteRemovesWhatTheSelectedPointsCover) {
    EditSession s;
    run(s, "add-patch; cursor 4 0 0; add-triangle; cursor -4 0 0; add-curve");
    run(s, "select triangle 0; delete");
    EXPECT_TRUE(s.doc.triangles.empty());
    run(s, "select all; delete");
    EXPECT_TRUE(s.doc.patches.empty());
    EXPECT_TRUE(s.doc.curves.empty());
}

// flip turns the selected patch, or every patch whose points are all selected, as one undo step.
TEST(Commands, FlipTurnsEveryWholeSelectedPatch) {
    EditSession s;
    s.reset(makePatchGrid(2, 2, Continuity::C1), "");
    const Document before = s.doc;
    run(s, "select patch 1; flip");
    EXPECT_NE(s.doc.patches[1].idx, before.patches[1].idx);
    EXPECT_EQ(s.doc.patches[0].idx, before.patches[0].idx);
    run(s, "undo; select all; flip");
    for (size_t p = 0; p < 4; ++p) EXPECT_NE(s.doc.patches[p].idx, before.patches[p].idx) << p;
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-9);
    run(s, "undo");
    EXPECT_EQ(s.doc.patches, before.patches);
    EXPECT_EQ(s.doc.joins, before.joins);
    s.sel.clear();
    EXPECT_THROW(run(s, "flip"), InputError);  // "not available now", with the script line
}

TEST(Commands, BadLinesNameTheScriptAndLine) {
    EXPECT_EQ(scriptError("add-patch\n\nfrobnicate 3"),
              "s.txt:3: unknown command 'frobnicate' (the F1 help and the palette list every command)");
    EXPECT_NE(scriptError("move 1 2").find("s.txt:1: move: expected 3 arguments, got 2 (usage: move DX DY DZ)"), std::string::npos);
    EXPECT_NE(scriptError("select all; move 1 x 2").find("s.txt:1: move: DY: expected a finite number, got 'x'"), std::string::npos);
    EXPECT_NE(scriptError("select patch 9").find("s.txt:1: select: patch 9 does not exist"), std::string::npos);
    EXPECT_NE(scriptError("help").find("'help' needs the editor window"), std::string::npos);
    EXPECT_NE(scriptError("join 0:u1 0:q0 C1").find("patch 0 does not exist"), std::string::npos);
    EXPECT_NE(scriptError("add-patch; add-patch; join 0:u1 1:q0 C1").find("expected an edge"), std::string::npos);
    EXPECT_NE(scriptError("open /nonexistent/x.patchwork").find("s.txt:1: "), std::string::npos);
    EXPECT_NE(scriptError("tess 0").find("tess: LEVEL: value 0 is outside [1, 64]"), std::string::npos);
}

TEST(Commands, ViewOverlayShadingAndTessellation) {
    EditSession s;
    run(s, "view top; ortho on; overlay wireframe on; overlay grid off; shading zebra; tess 5; spacing fractional_odd");
    EXPECT_DOUBLE_EQ(s.camera.pitchDeg, 90.0);
    EXPECT_TRUE(s.camera.orthographic);
    EXPECT_TRUE(s.doc.display.showWireframe);
    EXPECT_FALSE(s.doc.display.showGrid);
    EXPECT_EQ(s.doc.display.shading, ShadingMode::Zebra);
    EXPECT_EQ(s.doc.tess.outer[2], 5.0f);
    EXPECT_EQ(s.doc.tess.spacing, Spacing::FractionalOdd);
    run(s, "tess 2 3 4 5 6 7");
    EXPECT_EQ(s.doc.tess.inner[1], 7.0f);
    EXPECT_FALSE(s.doc.tess.linked);
}

TEST(Commands, SaveGoesThroughTheHostAndSplitExtrudeWork) {
    EditSession s;
    RecordingHost host;
    const CommandTable t = makeCommandTable();
    t.runScript(s, host, "add-patch; extrude u1; select patch 0; split v 0.25; save \"my file.patchwork\"", "x");
    // The split along v crosses edge u1, joined to the extrusion: the cut runs on through it (the
    // ring), the join becomes two and each patch's halves are joined.
    EXPECT_EQ(s.doc.patches.size(), 4u);
    EXPECT_EQ(s.doc.joins.size(), 4u);
    EXPECT_TRUE(std::any_of(host.statuses.begin(), host.statuses.end(),
                            [](const std::string& m) { return m.find("split 2 patches") != std::string::npos; }));
    t.runScript(s, host, "select patch 1; curve-from-edge v0", "x");
    ASSERT_EQ(s.doc.curves.size(), 1u);
    EXPECT_EQ(s.sel.curve, 0);
    t.runScript(s, host, "undo", "x");
    ASSERT_EQ(host.writes.size(), 1u);
    EXPECT_EQ(host.writes[0].first, "my file.patchwork");
    EXPECT_EQ(host.savedPaths, std::vector<std::string>{"my file.patchwork"});  // the window updates title, recent files, autosave
    EXPECT_EQ(host.writes[0].second.patches.size(), 4u);
    EXPECT_EQ(s.path(), "my file.patchwork");
    EXPECT_FALSE(s.isModified());
}

TEST(Commands, ATransformSaysHowFarItReached) {
    EditSession s;
    RecordingHost host;
    const CommandTable t = makeCommandTable();
    // Patch 0 raised, its C1 neighbour's tangent row follows: more points move than were selected.
    t.runScript(s, host, "add-patch; extrude u1; select patch 0; move 0 0 1", "x");
    ASSERT_FALSE(host.statuses.empty());
    EXPECT_NE(host.statuses.back().find("20 points moved (16 selected)"), std::string::npos) << host.statuses.back();
    t.runScript(s, host, "soft 0.5; select patch 0; move 0 0 1", "x");
    EXPECT_NE(host.statuses.back().find("within the soft 0.5 smooth"), std::string::npos) << host.statuses.back();
}

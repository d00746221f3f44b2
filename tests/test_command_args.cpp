// Commands' typed arguments (core/commands/command_table.hpp): the table checks every word against
// the command's forms before its exec function runs, and writes the usage from them; and the
// commands the panels run instead of writing the document (rename, point, item levels, net edits,
// kept levels, the notes' formulas), each one undo step.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/select/soft_selection.hpp"
#include "core/solve/constraint_solver.hpp"

using namespace pw;

namespace {

class QuietHost final : public CommandHost {
public:
    void write(const Document&, const std::string&) override {}
};

void run(EditSession& s, const std::string& script) {
    QuietHost host;
    makeCommandTable().runScript(s, host, script, "test");
}

// The message a line fails with after `setup`, or "" when it runs.
std::string failure(const std::string& setup, const std::string& line) {
    EditSession s;
    run(s, setup);
    QuietHost host;
    try {
        makeCommandTable().run(s, host, std::string_view(line));
    } catch (const EditError& e) {
        return e.what();
    }
    return "";
}

const Command& command(const CommandTable& t, const char* name) {
    const Command* c = t.find(name);
    if (!c) throw std::logic_error(std::string("no command ") + name);
    return *c;
}

}  // namespace

TEST(CommandArgs, UsageIsWrittenFromTheForms) {
    const CommandTable t = makeCommandTable();
    EXPECT_EQ(commandUsage(command(t, "move")), "DX DY DZ");
    EXPECT_EQ(commandUsage(command(t, "scale")), "S | SX SY SZ");
    EXPECT_EQ(commandUsage(command(t, "rotate")), "X|Y|Z DEG");
    EXPECT_EQ(commandUsage(command(t, "soft")), "on|off|toggle [smooth|linear|sharp|constant] | RADIUS [smooth|linear|sharp|constant]");
    EXPECT_EQ(commandUsage(command(t, "undo")), "");
    // Every form is well made: optional arguments only at the end, a repeated one only last, a
    // choice with choices; every command has an exec function.
    for (const Command& c : t.commands()) {
        SCOPED_TRACE(c.name);
        EXPECT_TRUE(bool(c.exec));
        for (const CommandForm& f : c.forms) {
            bool optional = false;
            for (size_t i = 0; i < f.size(); ++i) {
                EXPECT_TRUE(!optional || f[i].optional) << "argument " << f[i].name << " is required after an optional one";
                optional = optional || f[i].optional;
                EXPECT_TRUE(!f[i].repeated || i + 1 == f.size()) << f[i].name << " is repeated but not last";
                EXPECT_EQ(f[i].type == ArgType::Choice, !f[i].choices.empty()) << f[i].name;
                EXPECT_FALSE(f[i].name.empty());
            }
        }
    }
}

TEST(CommandArgs, WordsAreCheckedBeforeTheCommandRuns) {
    EXPECT_EQ(failure("", "move 1 2"), "move: expected 3 arguments, got 2 (usage: move DX DY DZ)");
    EXPECT_EQ(failure("", "move 1 x 2"), "move: DY: expected a finite number, got 'x'");
    EXPECT_EQ(failure("", "cursor 0 5e10 0"), "cursor: Y: 5e+10 is beyond the coordinate limit ±1e+09 and was not applied");
    EXPECT_EQ(failure("", "rotate W 5"), "rotate: expected an axis X, Y or Z, got 'W'");
    EXPECT_EQ(failure("", "scale 1 2"), "scale: expected another number of arguments, got 2 (usage: scale S | SX SY SZ)");
    EXPECT_EQ(failure("", "pivot middle"), "pivot: expected median, active or cursor, got 'middle'");
    EXPECT_EQ(failure("add-patch", "split-ring 3 u 0.5"), "split-ring: patch 3 does not exist (the document has 1)");
    EXPECT_EQ(failure("", "unhide now"), "unhide: expected 0 arguments, got 1 (usage: unhide)");
    EXPECT_EQ(failure("add-net 5 5", "net-insert 0 row -1"), "net-insert: K: expected a whole number, got '-1'");
    // The first form that fits is taken: "soft 0.5 linear" is the radius form.
    EditSession s;
    run(s, "soft 0.5 linear");
    EXPECT_TRUE(s.soft.on);
    EXPECT_DOUBLE_EQ(s.soft.radius, 0.5);
    EXPECT_EQ(failure("", "soft 0.5 wobbly"), "soft: expected smooth, linear, sharp or constant, got 'wobbly'");
    run(s, "soft on sharp");  // a mode and a falloff, as before the forms
    EXPECT_EQ(s.soft.falloff, *parseFalloff("sharp"));
    // A whole number may be written as one ("5.0"), and a choice may take either case where it did.
    run(s, "add-net 5.0 5");
    EXPECT_EQ(s.doc.surfaces.back().rows, 5u);
    EXPECT_EQ(failure("", "add-net 5.5 5"), "add-net: ROWS: expected a whole number, got '5.5'");
    EXPECT_EQ(failure("", "slide W 1"), "slide: expected u, v or n, got 'W'");
    EXPECT_NE(failure("", "slide U 1"), "slide: expected u, v or n, got 'U'");
    // A command that is not available now cannot be previewed either.
    QuietHost host;
    EditSession empty;
    EXPECT_THROW(makeCommandTable().preview(empty, host, {"displacement-own", "1", "0"}), EditError);
}

TEST(PanelCommands, RenameAndPlaceAPointAreOneUndoStepEach) {
    EditSession s;
    run(s, "add-patch; rename patch 0 \"lid top\"");
    EXPECT_EQ(s.doc.patches[0].name, "lid top");
    run(s, "point 5 0.25 0.5 2");
    EXPECT_EQ(s.doc.points[5], Vec3(0.25, 0.5, 2.0));
    EXPECT_EQ(s.history().size(), 3u);
    run(s, "undo");
    EXPECT_NE(s.doc.points[5], Vec3(0.25, 0.5, 2.0));
    EXPECT_NE(failure("add-patch", "rename mesh 0 x").find("expected patch, net, triangle or curve"), std::string::npos);
    EXPECT_NE(failure("add-patch", "rename patch 4 x").find("patch 4 does not exist"), std::string::npos);
    EXPECT_NE(failure("add-patch", "point 99 0 0 0").find("point 99 does not exist"), std::string::npos);
}

TEST(PanelCommands, APlacedPointKeepsTheJoinsOrIsRefused) {
    EditSession s;
    run(s, "add-patch; cursor 3 0 0; add-patch; join 0:u1 1:u0 G1");
    ASSERT_EQ(s.doc.joins.size(), 1u);
    const uint32_t inner = s.doc.patches[0].idx[5];
    run(s, "point " + std::to_string(inner) + " 0.3 0.4 0.7");
    EXPECT_LT(maxConstraintResidual(s.doc), 1e-6);
    EXPECT_EQ(s.doc.points[inner], Vec3(0.3, 0.4, 0.7));
}

TEST(PanelCommands, OwnLevelsChangeOnlyTheLevels) {
    EditSession s;
    run(s, "add-patch; add-triangle");
    const uint64_t shape = s.shapeVersion(), version = s.version();
    run(s, "patch-levels 0 2 3 4 5 6 7; triangle-levels 0 3 3 3 9");
    ASSERT_TRUE(s.doc.patches[0].tessOverride.has_value());
    EXPECT_EQ(*s.doc.patches[0].tessOverride, (std::array<float, 6>{2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(*s.doc.triangles[0].tessOverride, (std::array<float, 4>{3, 3, 3, 9}));
    // A renderer rewrites levels in place: the shape version stays.
    EXPECT_EQ(s.shapeVersion(), shape);
    EXPECT_GT(s.version(), version);
    // A preview changes the levels with no undo step; the run on release records one.
    QuietHost host;
    const CommandTable t = makeCommandTable();
    const size_t steps = s.history().size();
    t.preview(s, host, {"patch-levels", "0", "8", "8", "8", "8", "8", "8"});
    EXPECT_EQ(s.history().size(), steps);
    t.run(s, host, std::vector<std::string>{"patch-levels", "0", "8", "8", "8", "8", "8", "8"});
    EXPECT_EQ(s.history().size(), steps + 1);
    // A setting's preview changes neither the shape nor the levels: it travels in render options.
    const uint64_t settings = s.settingsVersion();
    t.preview(s, host, {"set", "tess.level", "9"});
    EXPECT_EQ(s.shapeVersion(), shape);
    EXPECT_EQ(s.settingsVersion(), settings + 1);
    // A net's tension previewed is the shape: the scene is uploaded while the slider moves.
    run(s, "add-net 5 5 flat catmull-rom");
    const uint64_t netShape = s.shapeVersion();
    t.preview(s, host, {"net-tension", "0", "0.2"});
    EXPECT_GT(s.shapeVersion(), netShape);
    run(s, "patch-levels 0 off");
    EXPECT_FALSE(s.doc.patches[0].tessOverride.has_value());
    run(s, "undo");
    EXPECT_TRUE(s.doc.patches[0].tessOverride.has_value());
    EXPECT_EQ(failure("add-patch", "patch-levels 0 0 3 4 5 6 7"), "patch-levels: value 0 is outside [1, 64]");
    EXPECT_NE(failure("add-patch", "patch-levels 0 3 4").find("usage: patch-levels P off | P O0 O1 O2 O3 I0 I1"), std::string::npos);
}

TEST(PanelCommands, NetEditsAreCommands) {
    EditSession s;
    run(s, "add-net 5 6 flat catmull-rom");
    run(s, "net-tension 0 0.25");
    EXPECT_DOUBLE_EQ(s.doc.surfaces[0].tension, 0.25);
    run(s, "net-insert 0 row 2; net-delete 0 column 0");
    EXPECT_EQ(s.doc.surfaces[0].rows, 6u);
    EXPECT_EQ(s.doc.surfaces[0].cols, 5u);
    run(s, "net-closed 0 u on");
    EXPECT_TRUE(s.doc.surfaces[0].closedU);
    run(s, "net-basis 0 bspline");
    EXPECT_EQ(s.doc.surfaces[0].basis, Basis::BSpline);
    EXPECT_NE(failure("add-net 5 5", "net-tension 0 0.5").find("is not a Catmull-Rom net"), std::string::npos);
    EXPECT_NE(failure("add-net 5 5 flat catmull-rom", "net-tension 0 1.5").find("TENSION must lie in [0, 1]"), std::string::npos);
    EXPECT_NE(failure("add-net 5 5", "net-delete 0 row 5").find("has no row 5"), std::string::npos);
    EditSession p;
    run(p, "add-net 7 7; net-to-patches 0");
    EXPECT_TRUE(p.doc.surfaces.empty());
    EXPECT_EQ(p.doc.patches.size(), 16u);
    run(p, "patches-to-net 0");
    ASSERT_EQ(p.doc.surfaces.size(), 1u);
    EXPECT_TRUE(p.doc.patches.empty());
    EXPECT_EQ(p.sel.surface, 0);
}

TEST(PanelCommands, KeptLevelsAndTheNotesFormulas) {
    EditSession s;
    run(s, "add-patch; set tess.adaptive screen; tess-fixed fractional_odd 3 4 5 6 7 8");
    const TessSettings& t = s.doc.tess;
    EXPECT_EQ(t.adaptive, AdaptiveMode::None);
    EXPECT_EQ(t.spacing, Spacing::FractionalOdd);
    EXPECT_EQ(t.outer, (std::array<float, 4>{3, 4, 5, 6}));
    EXPECT_EQ(t.inner, (std::array<float, 2>{7, 8}));
    EXPECT_FALSE(t.linked);
    run(s, "adaptive-preset notes-terrain");
    EXPECT_EQ(s.doc.tess.adaptive, AdaptiveMode::Distance);
    EXPECT_EQ(s.doc.tess.spacing, Spacing::FractionalEven);
    run(s, "undo");
    EXPECT_EQ(s.doc.tess.adaptive, AdaptiveMode::None);
}

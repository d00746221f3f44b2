// The editor's own rules, tested by linking the ui library (no window, no GPU): a headless Dear
// ImGui context draws the real panels against a PanelContext that runs the real command table, and
// input is fed through ImGuiIO as the GLFW back end would. Covered: the Surfaces panel's list,
// options, preview and Loft (issue 39), its Fill hole (issue 40); a level typed out of range into
// the Tessellation panel (Ctrl+click, type, Enter) is clamped, recorded as one undo step and the
// saved file reopens (issue 38's live bug); a slider previews without undo steps and commits one
// on release; the editor's keys come from the command table alone; the widgets' test hooks
// gather only while a trace is set.
#include <gtest/gtest.h>
#include <imgui.h>

#include <map>
#include <set>

#include "core/commands/command_table.hpp"
#include "core/construct/model_builders.hpp"
#include "core/io/document_io.hpp"
#include "core/solve/constraint_solver.hpp"
#include "support.hpp"
#include "ui/panels/command_panels.hpp"
#include "ui/panels/dialogs.hpp"
#include "ui/panels/join_tool.hpp"
#include "ui/panels/side_panels.hpp"
#include "ui/platform/item_trace.hpp"
#include "ui/platform/shortcuts.hpp"
#include "ui/platform/widgets.hpp"

using namespace pw;
using namespace pw::ui;

namespace {

constexpr int kEnterKey = 257;  // GLFW_KEY_ENTER: what the GLFW back end puts in io.KeyMap

// The editor as the panels see it, without a window: commands run on a real session through the
// real table; what the editor would show or upload is counted.
class HeadlessContext final : public PanelContext {
public:
    EditSession& session() override { return session_; }
    const CommandTable& commands() const override { return table_; }
    CommandHost& host() override { return hostOverride ? *hostOverride : host_; }
    void runCommand(const std::vector<std::string>& words, bool guarded) override {
        ++commandsRun;
        try {
            table_.run(session_, host(), words, guarded);
        } catch (const std::exception& e) {
            errors.push_back(e.what());
        }
    }
    void previewCommand(const std::vector<std::string>& words) override {
        ++previews;
        table_.preview(session_, host(), words);
    }
    void previewConstruction(const std::vector<std::string>& words) override { previewed = words; }
    void documentChanged(bool) override { ++version_; }
    void settingsChanged() override { ++version_; }
    uint64_t documentVersion() const override { return version_; }
    void showError(const std::string& message) override { errors.push_back(message); }
    void wake() override {}
    bool interacting() const override { return false; }
    bool keyPressed(int, int) const override { return false; }
    float uiScale() const override { return 1.0f; }
    void frameBox(const Bounds&) override {}
    const Camera& viewCamera() const override { return camera_; }
    const PanelLayout& layout() const override { return layout_; }
    const FrameReport& frameReport() const override { return report_; }
    const ContinuityWatch& continuityWatch() const override { return watch_; }

    CommandHost* hostOverride = nullptr;  // the editor's window, where a test needs one
    int commandsRun = 0, previews = 0;
    std::vector<std::string> errors;
    std::vector<std::string> previewed;  // the last construction the panel asked to preview

private:
    EditSession session_;
    CommandTable table_ = makeCommandTable();
    test::NoWritesHost host_;
    uint64_t version_ = 0;
    Camera camera_;
    PanelLayout layout_;
    FrameReport report_;
    ContinuityWatch watch_;
};

// A headless ImGui with the font atlas built, the Enter key mapped, and a trace of named widgets.
class Ui : public ::testing::Test {
protected:
    void SetUp() override {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(800, 900);
        io.DeltaTime = 1.0f / 60.0f;
        io.IniFilename = nullptr;
        io.KeyMap[ImGuiKey_Enter] = kEnterKey;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
        setItemTrace(&trace);
    }
    void TearDown() override {
        setItemTrace(nullptr);
        ImGui::DestroyContext();
    }
    // One frame of `draw` inside a window.
    template <class F>
    void frame(F&& draw) {
        trace.clear();
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(500, 880));
        ImGui::Begin("panel");
        draw();
        ImGui::End();
        ImGui::Render();
    }
    // One frame of `draw` at the top level, outside any window (the modals).
    template <class F>
    void topFrame(F&& draw) {
        trace.clear();
        ImGui::NewFrame();
        draw();
        ImGui::Render();
    }
    // Move the mouse onto `item`, press and release it: one frame each, as a user's click.
    template <class F>
    void click(F&& draw, const std::string& item, bool topLevel = false) {
        ImGuiIO& io = ImGui::GetIO();
        const auto once = [&] { topLevel ? topFrame(draw) : frame(draw); };
        once();
        io.MousePos = centre(item);
        once();
        io.MouseDown[0] = true;
        once();
        io.MouseDown[0] = false;
        once();
    }
    ImVec2 centre(const std::string& item) const {
        const auto it = trace.items.find(item);
        EXPECT_NE(it, trace.items.end()) << item << " was not drawn";
        return it == trace.items.end() ? ImVec2(0, 0) : ImVec2(it->second[0], it->second[1]);
    }
    ItemTrace trace;
};

}  // namespace

// A save over a file another program changed since it was opened asks (issue 73): Cancel writes
// nothing, Overwrite replaces it, Save As opens the file browser. Without a window the same save is
// refused, naming `save FILE overwrite` (test_concurrent_save.cpp).
TEST_F(Ui, ASaveOverAFileChangedOnDiskAsksOverwriteSaveAsOrCancel) {
    class WindowHost final : public CommandHost {
    public:
        explicit WindowHost(Dialogs& d) : dialogs_(d) {}
        bool hasWindow() const override { return true; }
        bool confirmOverwriteChanged(const std::string& path) override {
            dialogs_.askOverwriteChanged(path);
            return false;
        }
        void write(const Document& doc, const std::string& path) override { saveDocument(doc, path); }

    private:
        Dialogs& dialogs_;
    };
    const auto dir = test::freshTempDir("ui-changed");
    const std::string file = (dir / "m.patchwork").string();
    saveDocument(makePatchGrid(1, 1), file);
    Dialogs dialogs;
    WindowHost host(dialogs);
    HeadlessContext ctx;
    ctx.hostOverride = &host;
    ctx.session().open(file);
    ctx.runCommand({"select", "patch", "0"}, true);
    ctx.runCommand({"move", "0", "0", "1"}, true);
    saveDocument(makePatchGrid(2, 2), file);  // another program's work
    const std::string theirs = test::readBytes(file);
    const auto modals = [&] { dialogs.drawModals(ctx, [] {}); };

    ctx.runCommand({"save"}, true);
    EXPECT_TRUE(ctx.errors.empty()) << ctx.errors.front();
    EXPECT_EQ(dialogs.changedFile(), file);
    topFrame(modals);  // it appears (an auto-sized window takes its size in its first frame)
    click(modals, "changed.cancel", true);
    EXPECT_EQ(dialogs.shown(), Modal::None);
    EXPECT_EQ(test::readBytes(file), theirs);
    EXPECT_TRUE(ctx.session().isModified());

    ctx.runCommand({"save"}, true);
    topFrame(modals);
    click(modals, "changed.saveas", true);
    EXPECT_EQ(dialogs.shown(), Modal::None);  // closed; the file browser is asked for next
    EXPECT_EQ(dialogs.waiting().front(), Modal::FileBrowser);
    EXPECT_EQ(test::readBytes(file), theirs);

    Dialogs fresh;  // the same question again, answered Overwrite
    WindowHost again(fresh);
    ctx.hostOverride = &again;
    ctx.runCommand({"save"}, true);
    const auto freshModals = [&] { fresh.drawModals(ctx, [] {}); };
    topFrame(freshModals);
    click(freshModals, "changed.overwrite", true);
    EXPECT_TRUE(ctx.errors.empty());
    EXPECT_EQ(loadDocument(file).points, ctx.session().doc.points);
    EXPECT_FALSE(ctx.session().isModified());
}

TEST_F(Ui, ALevelTypedOutOfRangeIsClampedAndTheSavedFileReopens) {
    HeadlessContext ctx;
    ImGuiIO& io = ImGui::GetIO();
    auto panel = [&] { drawTessellationPanel(ctx); };
    frame(panel);
    const ImVec2 level = centre("tess.level");
    // Ctrl+click the Level slider: it turns into a text field with its text selected.
    io.MousePos = level;
    io.KeyCtrl = true;
    io.MouseDown[0] = true;
    frame(panel);
    io.MouseDown[0] = false;
    io.KeyCtrl = false;
    frame(panel);
    io.AddInputCharactersUTF8("-5");
    frame(panel);
    io.KeysDown[kEnterKey] = true;
    frame(panel);
    io.KeysDown[kEnterKey] = false;
    frame(panel);
    frame(panel);

    const Document& doc = ctx.session().doc;
    EXPECT_TRUE(ctx.errors.empty()) << ::testing::PrintToString(ctx.errors);
    EXPECT_EQ(doc.tess.outer, (std::array<float, 4>{1, 1, 1, 1}));  // -5 clamped to the row's 1
    EXPECT_EQ(doc.tess.inner, (std::array<float, 2>{1, 1}));
    EXPECT_EQ(ctx.session().history().size(), 1u);
    EXPECT_EQ(ctx.session().history().undoLabel(), "Level");
    const auto dir = test::freshTempDir("ui_rules");
    saveDocument(doc, dir / "typed.patchwork");
    const Document back = loadDocument(dir / "typed.patchwork");
    EXPECT_EQ(back.tess, doc.tess);
}

TEST_F(Ui, ASliderPreviewsWhileItMovesAndCommitsOneUndoStepOnRelease) {
    HeadlessContext ctx;
    ImGuiIO& io = ImGui::GetIO();
    auto panel = [&] { drawTessellationPanel(ctx); };
    frame(panel);
    const ImVec2 level = centre("tess.level");
    io.MousePos = level;
    io.MouseDown[0] = true;
    frame(panel);
    for (float dx : {40.0f, 80.0f, 120.0f}) {
        io.MousePos = ImVec2(level.x + dx, level.y);
        frame(panel);
    }
    EXPECT_GT(ctx.previews, 0);
    EXPECT_FALSE(ctx.session().history().canUndo());  // moving: no undo step yet
    const float moved = ctx.session().doc.tess.outer[0];
    EXPECT_GT(moved, 16.0f);
    io.MouseDown[0] = false;
    frame(panel);
    frame(panel);
    EXPECT_EQ(ctx.session().history().size(), 1u);
    EXPECT_EQ(ctx.session().doc.tess.outer[0], moved);
    ctx.session().undo();
    EXPECT_EQ(ctx.session().doc.tess.outer[0], 16.0f);
}

TEST_F(Ui, ATickedBoxRunsItsSettingCommand) {
    HeadlessContext ctx;
    ImGuiIO& io = ImGui::GetIO();
    auto panel = [&] { drawDisplayPanel(ctx); };
    frame(panel);
    io.MousePos = centre("display.showBoundaries");
    io.MouseDown[0] = true;
    frame(panel);
    io.MouseDown[0] = false;
    frame(panel);
    EXPECT_TRUE(ctx.session().doc.display.showBoundaries);
    EXPECT_EQ(ctx.commandsRun, 1);
    EXPECT_EQ(ctx.session().history().undoLabel(), "Boundaries");
}

// The Inspector and the Net panel act only through commands (issue 38): the Override box runs
// patch-levels (one undo step, levels only), the net's Convert button runs net-to-patches.
TEST_F(Ui, TheInspectorAndTheNetPanelRunCommands) {
    HeadlessContext ctx;
    ctx.runCommand({"add-patch"}, true);
    ctx.runCommand({"select", "patch", "0"}, true);
    InspectorPanel inspector;
    auto drawInspector = [&] { inspector.draw(ctx); };
    const uint64_t shape = ctx.session().shapeVersion();
    const int before = ctx.commandsRun;
    click(drawInspector, "inspector.patchOverride");
    ASSERT_TRUE(ctx.session().doc.patches[0].tessOverride.has_value());
    EXPECT_EQ(*ctx.session().doc.patches[0].tessOverride, (std::array<float, 6>{8, 8, 8, 8, 8, 8}));
    EXPECT_EQ(ctx.commandsRun, before + 1);
    EXPECT_EQ(ctx.session().history().undoLabel(), "Patch tessellation override");
    EXPECT_EQ(ctx.session().shapeVersion(), shape);  // the renderer rewrites levels in place
    EXPECT_TRUE(ctx.session().isModified());         // the title's "(modified)", the unsaved-changes prompt
    click(drawInspector, "inspector.patchOverride");
    EXPECT_FALSE(ctx.session().doc.patches[0].tessOverride.has_value());

    // A name typed for patch 0 stays patch 0's when patch 1 is selected before Enter.
    ctx.runCommand({"cursor", "3", "0", "0"}, true);
    ctx.runCommand({"add-patch"}, true);
    ctx.runCommand({"select", "patch", "0"}, true);
    click(drawInspector, "inspector.patchName");
    ImGui::GetIO().AddInputCharactersUTF8("lid");
    frame(drawInspector);
    ctx.runCommand({"select", "patch", "1"}, true);  // as a click in the view does
    ImGui::GetIO().MousePos = ImVec2(5, 870);
    ImGui::GetIO().MouseDown[0] = true;  // a click elsewhere ends the typing
    frame(drawInspector);
    ImGui::GetIO().MouseDown[0] = false;
    frame(drawInspector);
    frame(drawInspector);
    EXPECT_EQ(ctx.session().doc.patches[0].name.substr(ctx.session().doc.patches[0].name.size() - 3), "lid");
    EXPECT_EQ(ctx.session().doc.patches[1].name.find("lid"), std::string::npos);
    EXPECT_EQ(ctx.session().history().undoLabel(), "Rename patch");

    ctx.runCommand({"add-net", "7", "7"}, true);
    ASSERT_EQ(ctx.session().sel.surface, 0);
    NetPanel net;
    click([&] { net.draw(ctx); }, "net.toPatches");
    EXPECT_TRUE(ctx.session().doc.surfaces.empty());
    EXPECT_EQ(ctx.session().doc.patches.size(), 18u);
    EXPECT_EQ(ctx.session().history().undoLabel(), "Convert net to patches");
    EXPECT_TRUE(ctx.errors.empty()) << ::testing::PrintToString(ctx.errors);
}

// Join by picking's states (ui/panels/join_tool), against the real command table: first pick,
// second pick runs the join as a preview, another continuity re-runs it, Cancel takes it back to
// the second pick, Apply keeps it and closes; Esc steps back; another edit keeps the preview.
TEST(UiJoinTool, PicksPreviewChooseCancelApplyAndBack) {
    HeadlessContext ctx;
    ctx.runCommand({"add-patch"}, true);
    ctx.runCommand({"cursor", "3", "0", "0"}, true);
    ctx.runCommand({"add-patch"}, true);
    const Document& doc = ctx.session().doc;
    ASSERT_EQ(doc.patches.size(), 2u);
    JoinTool tool;
    tool.setOn(ctx, true);
    EXPECT_TRUE(tool.state().on);
    const PatchEdge a{0, Edge::U1}, b{1, Edge::U0};
    tool.pick(ctx, a);
    ASSERT_TRUE(tool.state().first.has_value());
    EXPECT_EQ(*tool.state().first, a);
    EXPECT_TRUE(doc.joins.empty());
    tool.pick(ctx, b);  // the join runs at once, as a preview
    ASSERT_EQ(doc.joins.size(), 1u);
    EXPECT_TRUE(tool.state().preview);
    EXPECT_EQ(doc.joins[0].continuity, Continuity::C1);
    tool.choose(ctx, Continuity::G1);  // taken back and run again
    ASSERT_EQ(doc.joins.size(), 1u);
    EXPECT_EQ(doc.joins[0].continuity, Continuity::G1);
    EXPECT_EQ(tool.state().continuity, Continuity::G1);
    tool.cancel(ctx);  // taken back: the second pick again
    EXPECT_TRUE(doc.joins.empty());
    EXPECT_FALSE(tool.state().preview);
    EXPECT_EQ(tool.state().first, a);
    tool.pick(ctx, b);
    ASSERT_EQ(doc.joins.size(), 1u);
    tool.apply(ctx);  // kept; the tool closes
    EXPECT_FALSE(tool.state().on);
    EXPECT_EQ(doc.joins.size(), 1u);
    EXPECT_EQ(ctx.session().history().undoLabel(), "Join edges");
    // Esc: the first pick dropped, then the tool closed.
    tool.setOn(ctx, true);
    tool.pick(ctx, PatchEdge{0, Edge::V0});
    tool.back(ctx);
    EXPECT_TRUE(tool.state().on);
    EXPECT_FALSE(tool.state().first.has_value());
    tool.back(ctx);
    EXPECT_FALSE(tool.state().on);
    // Another edit while the preview shows keeps the join.
    ctx.runCommand({"unjoin", "0:u1"}, true);
    ASSERT_TRUE(doc.joins.empty());
    tool.setOn(ctx, true);
    tool.pick(ctx, a);
    tool.pick(ctx, b);
    ASSERT_TRUE(tool.state().preview);
    ctx.runCommand({"select", "all"}, true);
    ctx.runCommand({"move", "0", "0", "1"}, true);
    tool.followSession(ctx.session());
    EXPECT_FALSE(tool.state().preview);
    tool.back(ctx);
    EXPECT_EQ(doc.joins.size(), 1u);
    EXPECT_TRUE(ctx.errors.empty()) << ::testing::PrintToString(ctx.errors);
}

TEST(UiKeys, TheEditorsKeysComeFromTheCommandTableAlone) {
    const CommandTable table = makeCommandTable();
    const std::vector<KeyBinding> keys = keyBindingsOf(table);
    size_t shortcuts = 0;
    for (const Command& c : table.commands())
        for (const CommandBinding& b : c.bindings) shortcuts += b.shortcuts.size();
    EXPECT_EQ(keys.size(), shortcuts);
    EXPECT_GT(keys.size(), 30u);
    // No chord runs two different lines.
    std::map<std::pair<int, int>, std::string> seen;
    for (const KeyBinding& k : keys) {
        const auto [it, fresh] = seen.emplace(std::pair{k.chord.key, k.chord.mods}, k.line);
        EXPECT_TRUE(fresh || it->second == k.line) << "one key runs '" << it->second << "' and '" << k.line << "'";
        EXPECT_NE(table.find(splitCommandWords(k.line).front()), nullptr) << k.line;
    }
    EXPECT_FALSE(parseShortcut("Ctrl+Hyper+Q").has_value());
}

TEST(UiKeys, F1ListsEveryKeyTheTableBindsAndTheModalKeys) {
    // The F1 window's rows: every command entry's keys, then the modal keys.
    const CommandTable table = makeCommandTable();
    std::set<std::string> listed;
    for (const Command& c : table.commands())
        for (const CommandEntry& e : entriesOf(c)) {
            std::string keys = e.shortcut;
            for (size_t at = 0; (at = keys.find(" / ")) != std::string::npos;) listed.insert(keys.substr(0, at)), keys.erase(0, at + 3);
            if (!keys.empty()) listed.insert(keys);
        }
    for (const KeyHelp& k : modalKeys()) listed.insert(k.keys);
    for (const Command& c : table.commands())
        for (const CommandBinding& b : c.bindings)
            for (const std::string& key : b.shortcuts) EXPECT_TRUE(listed.count(key)) << key << " (" << c.name << ") is not in F1";
    for (const char* key : {"G", "R", "S", "Shift+D"}) EXPECT_TRUE(listed.count(key)) << key << " is not in F1";
}

TEST_F(Ui, WidgetsAreTracedOnlyWhileATraceIsSet) {
    frame([] {
        widget::Button("One##one");
        widget::Button("Unnamed");
        widget::BeginModalWindow("A dialog##modal", nullptr);
        ImGui::End();
    });
    EXPECT_EQ(trace.items.count("one"), 1u);
    EXPECT_EQ(trace.items.size(), 1u);  // a label without "##name" is not traced
    EXPECT_EQ(trace.modal, "modal");
    EXPECT_EQ(traceName("Domain view##teach.domain"), "teach.domain");
    EXPECT_EQ(traceName("Tab###shaders.tab.x"), "shaders.tab.x");
    EXPECT_EQ(traceName("Tese##shaders.tab.x###tese"), "shaders.tab.x");
    setItemTrace(nullptr);
    frame([] { widget::Button("Two##two"); });
    EXPECT_EQ(trace.items.count("two"), 0u);
}

// The Surfaces panel (issue 39): a patch edge and two curves listed, G1 chosen for the loft's start
// from the combo; the mouse over Loft previews exactly the command the click then runs, and the
// click makes the loft joined G1 to the patch.
TEST_F(Ui, TheSurfacesPanelListsCurvesAndEdgesPreviewsAndLofts) {
    HeadlessContext ctx;
    ImGuiIO& io = ImGui::GetIO();
    EditSession& s = ctx.session();
    test::runEditScript(s,
                        "add-patch; curve-control -0.5,1.2,0.6 -0.17,1.2,0.9 0.17,1.2,0.9 0.5,1.2,0.6; "
                        "curve-control -0.5,1.8,1.0 -0.17,1.8,1.4 0.17,1.8,1.4 0.5,1.8,1.0");
    SurfacesPanel panel;
    auto draw = [&] { panel.draw(ctx); };
    s.sel.clear();
    s.sel.patch = 0;
    s.activeEdge = Edge::V1;
    click(draw, "surfaces.addEdge");
    for (int c : {0, 1}) {
        s.sel.clear();
        s.sel.curve = c;
        click(draw, "surfaces.addCurve");
    }
    // G1 from the Start combo: open it, then pick the second entry below it.
    click(draw, "surfaces.loftStart");
    const ImVec2 combo = centre("surfaces.loftStart");
    io.MousePos = ImVec2(combo.x, combo.y + 41.0f);  // below the combo: G0 at +24, G1 at +41 (13 px font, 4 px spacing)
    frame(draw);
    io.MouseDown[0] = true;
    frame(draw);
    io.MouseDown[0] = false;
    frame(draw);
    io.MousePos = centre("op.loft");
    frame(draw);
    frame(draw);
    EXPECT_EQ(ctx.previewed, splitCommandWords("loft 0:v1 c0 c1 start=G1"));
    EXPECT_EQ(s.doc.constructions.size(), 0u);  // a preview changes nothing
    click(draw, "op.loft");
    EXPECT_TRUE(ctx.errors.empty()) << ::testing::PrintToString(ctx.errors);
    ASSERT_EQ(s.doc.constructions.size(), 1u);
    EXPECT_EQ(s.doc.constructions[0].ends[0], Continuity::G1);
    bool joined = false;
    for (const Join& j : s.doc.joins) joined = joined || (j.patchA == 0 && j.continuity == Continuity::G1);
    EXPECT_TRUE(joined);
}

// The Surfaces panel's Fill hole (issue 40): six listed patch edges paired into three sides with
// Join last two; the mouse over Fill hole previews the command the click then runs, and the click
// fills the rounded box's last open corner.
TEST_F(Ui, TheSurfacesPanelPairsEdgesIntoSidesAndFillsAHole) {
    HeadlessContext ctx;
    ImGuiIO& io = ImGui::GetIO();
    EditSession& s = ctx.session();
    const std::string script = test::readBytes(test::dataDir() / "rounded_box.pwscript");
    test::runEditScript(s, script.substr(0, script.rfind("fill-hole")));
    const size_t patches = s.doc.patches.size();
    SurfacesPanel panel;
    auto draw = [&] { panel.draw(ctx); };
    // The script's last line: fill-hole 11:u1+23:u1 13:u0+25:u0 17:u1+29:u1.
    const std::pair<int, Edge> edges[6] = {{11, Edge::U1}, {23, Edge::U1}, {13, Edge::U0}, {25, Edge::U0}, {17, Edge::U1}, {29, Edge::U1}};
    for (int side = 0; side < 3; ++side) {
        for (int k = 0; k < 2; ++k) {
            s.sel.clear();
            s.sel.patch = edges[2 * side + k].first;
            s.activeEdge = edges[2 * side + k].second;
            click(draw, "surfaces.addEdge");
        }
        click(draw, "surfaces.pairEdges");
    }
    io.MousePos = centre("op.fillHole");
    frame(draw);
    frame(draw);
    EXPECT_EQ(ctx.previewed, splitCommandWords("fill-hole 11:u1+23:u1 13:u0+25:u0 17:u1+29:u1"));
    EXPECT_EQ(s.doc.patches.size(), patches);  // a preview changes nothing
    click(draw, "op.fillHole");
    EXPECT_TRUE(ctx.errors.empty()) << ::testing::PrintToString(ctx.errors);
    EXPECT_EQ(s.doc.patches.size(), patches + 3);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-6 * modelSize(s.doc));
}

// The Surfaces panel's Triangle (issue 40): three listed single edges round a hole; the mouse over
// Triangle previews `fill-hole … triangle` and the click fills the hole with one Bézier triangle.
TEST_F(Ui, TheSurfacesPanelFillsAThreeSidedHoleWithATriangle) {
    HeadlessContext ctx;
    ImGuiIO& io = ImGui::GetIO();
    EditSession& s = ctx.session();
    s.doc = test::poleRing();
    SurfacesPanel panel;
    auto draw = [&] { panel.draw(ctx); };
    for (int p = 0; p < 3; ++p) {
        s.sel.clear();
        s.sel.patch = p;
        s.activeEdge = Edge::V0;
        click(draw, "surfaces.addEdge");
    }
    io.MousePos = centre("op.fillTriangle");
    frame(draw);
    frame(draw);
    EXPECT_EQ(ctx.previewed, splitCommandWords("fill-hole 0:v0 1:v0 2:v0 triangle"));
    EXPECT_TRUE(s.doc.triangles.empty());  // a preview changes nothing
    click(draw, "op.fillTriangle");
    EXPECT_TRUE(ctx.errors.empty()) << ::testing::PrintToString(ctx.errors);
    EXPECT_EQ(s.doc.triangles.size(), 1u);
    EXPECT_EQ(s.doc.joins.size(), 6u);
    EXPECT_LE(maxConstraintResidual(s.doc), 1e-6 * modelSize(s.doc));
}

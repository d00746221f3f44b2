// The interactive editor: a composition of the window layer (ui/platform/app_window.hpp), the editing
// session (core/edit/edit_session.hpp) run through the command table (core/commands/command_table.hpp), the
// Vulkan renderer drawing the document, the viewport with its point drags
// (core/edit/drag_controller.hpp), the panels (ui/panel_*.cpp, ui/dialog_*.cpp) and the test trace
// (ui/editor/test_trace.hpp). Blender-style navigation and editing (DESIGN §6).
#pragma once

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/commands/command_table.hpp"
#include "core/edit/autosave.hpp"
#include "core/edit/background_writer.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/edit/edit_session.hpp"
#include "core/edit/emergency_save.hpp"
#include "core/select/edge_pick.hpp"
#include "core/tess/tess_levels.hpp"
#include "ui/editor/test_trace.hpp"
#include "ui/panels/command_panels.hpp"
#include "ui/panels/dialogs.hpp"
#include "ui/panels/join_tool.hpp"
#include "ui/panels/panel_context.hpp"
#include "ui/panels/panel_shaders.hpp"
#include "ui/panels/side_panels.hpp"
#include "ui/panels/teaching.hpp"
#include "ui/platform/app_window.hpp"
#include "ui/platform/shortcuts.hpp"

namespace pw::render {
inline namespace scene {
class Renderer;
struct RenderOptions;
}  // namespace scene
}  // namespace pw::render

namespace pw::ui {
inline namespace editor {

// Opens the editor on `file` (empty: the built-in teapot). Returns the exit code; 2 when there is
// no display.
int runEditor(const std::string& file);

// `patchwork bench --editor`: the editor's frame cost while a control point is dragged (G grab, the
// mouse moving every frame), against a bare offscreen render of the same view in the same run.
struct EditorBenchOptions {
    std::string file;                // empty: the built-in teapot
    int frames = 100;                // measured frames
    int width = 1280, height = 720;  // window size (pixels at content scale 1)
    std::optional<float> level;      // uniform tessellation level of the drag; none: the file's own settings (the teapot: 16)
    std::string json;                // write the results here as JSON when not empty
};
// Needs a display (Xvfb will do); returns the exit code (2 without a display).
int runEditorBench(const EditorBenchOptions& options);

enum class Interaction { None, Orbit, Pan, BoxSelect, PendingDrag, DragPoints, Grab };

// The curve tool (C, ui/editor/curve_tool.cpp): click points on the construction plane through the
// 3D cursor (snapping to points, edges and the grid); Enter makes the curve through them.
struct CurveToolState {
    bool on = false;
    std::vector<Vec3> points;   // clicked so far
    std::optional<Vec3> hover;  // where a click puts the next point
    std::string snapped;        // what the hover point snapped to: "3D cursor", "point", "edge", "grid" or ""
    int plane = 0;              // 0: the axis plane facing the view, 1 XY, 2 XZ, 3 YZ
    int planeAxis = 2;          // the normal axis of the plane in use this frame
    bool gridSnap = true, closed = false, controlPoints = false;
};

// What the editor holds and shows after a frame, read-only, for observers outside it (the test
// trace, ui/editor/test_trace): valid until the next frame.
struct EditorSnapshot {
    const EditSession& session;
    const Teaching& teaching;
    const FrameReport& report;
    const Dialogs& dialogs;
    const ShaderPanel& shaders;
    const CommandPalette& palette;
    const ContinuityWatch& continuity;
    const JoinToolState& join;
    const CurveToolState& curveTool;
    const std::vector<bool>& usedMask;  // pool points some shown item uses
    std::array<int, 2> windowSize, framebufferSize;
    uint64_t frame = 0;
    uint64_t generation = 0;          // the session's committed state
    uint64_t emergencyPublished = 0;  // the committed state a fatal signal would write (0: none)
    Interaction mode = Interaction::None;
    int hovered = -1;                          // the control point under the mouse
    float softRadiusPixels = 0.0f;             // the soft-selection circle during a transform (0: none)
    bool degraded = false;                     // a heavy document drawn screen-adaptive (degradedLoad)
    bool help = false;                         // the F1 window is open
    std::array<float, 4> axisGizmo, viewArea;  // window pixels: x, y, w, h
    PanelLayout layout;
};

class Editor final : public CommandHost, public PanelContext, public WindowClient {
public:
    Editor(AppWindow& window, const std::string& file);
    ~Editor() override;
    int run();
    // The editor benchmark (ui/editor/editor_bench.cpp): drives this editor's own frames.
    int runBench(const EditorBenchOptions& options);
    EditorSnapshot snapshot() const;

private:
    // editor.cpp: documents, commands, autosave, the frame
    void setDocument(Document doc, const std::string& path);
    void documentReplaced();  // after the session's document was replaced: view, title, recent files
    void recoverAutosave();
    void addRecent(const std::string& path);
    void drawUi();
    render::RenderOptions viewOptions() const;   // the 3D view at the document's own levels (export as displayed)
    render::RenderOptions drawnOptions() const;  // what it draws this frame: a heavy document screen-adaptive
    // The load of the levels the view would draw, when it is too heavy for a CPU renderer and full
    // detail is off: the view is then drawn screen-adaptive instead (and says so).
    std::optional<FrameLoad> degradedLoad() const;

    // WindowClient: the frame loop (ui/platform/app_window.cpp).
    bool quitRequested() const override { return quit_; }
    void idleTick() override;  // autosave
    void closeRequested() override { runCommand({"quit"}); }
    bool frameWanted() const override { return screenshotRequested_; }
    void drawFrame() override;

    // PanelContext: what the panels use.
    EditSession& session() override { return session_; }
    const CommandTable& commands() const override { return commands_; }
    CommandHost& host() override { return *this; }
    void runCommand(const std::vector<std::string>& words, bool guarded = true) override;
    // After a command or a preview: what changed in the session reaches the renderer (a new
    // document, the scene uploaded, items' levels rewritten in place, or settings only).
    void followSession();
    void previewCommand(const std::vector<std::string>& words) override;
    void previewConstruction(const std::vector<std::string>& words) override;  // construction_preview.cpp
    void documentChanged(bool topology) override;                              // re-upload
    void levelsChanged() override;                                             // per-patch levels only
    void settingsChanged() override { ++docVersion_; }
    uint64_t documentVersion() const override { return docVersion_; }
    void showError(const std::string& message) override;
    void wake() override { window_.wake(); }
    bool interacting() const override { return mode_ != Interaction::None; }
    bool keyPressed(int key, int mods) const override { return window_.keyPressed(key, mods); }
    float uiScale() const override { return window_.uiScale(); }
    void frameBox(const Bounds& box) override;
    const Camera& viewCamera() const override { return cam_; }
    const PanelLayout& layout() const override { return sidePanels_.layout(); }
    const FrameReport& frameReport() const override { return report_; }
    const ContinuityWatch& continuityWatch() const override { return continuity_; }

    // CommandHost (editor_commands.cpp): what the commands ask of the window.
    bool hasWindow() const override { return true; }
    bool confirmDiscard(const std::vector<std::string>& words) override;
    bool confirmOverwriteChanged(const std::string& path) override;
    void write(const Document& doc, const std::string& path) override;
    void exportFile(const Document& doc, const std::string& path) override;
    // With options.asDisplayed and a tessellated format: the surface the 3D view draws (captured
    // now), options.viewport set, and `doc` reduced to the shown items; otherwise nullopt.
    std::optional<TriangleMesh> displayedMesh(Document& doc, ExportOptions& options, const std::string& path);
    void saved(const std::string& path) override;
    void fileDialog(FileDialogKind kind) override;
    void toggle(WindowToggle which) override;
    bool toggled(WindowToggle which) const override;
    float presentationTextScale() const override { return teaching_.presentationScale; }
    void setPresentationTextScale(float scale) override;
    void quit() override { quit_ = true; }
    void screenshot(const std::string& path) override;
    bool frame(const Bounds& box) override;
    void status(const std::string& message) override;
    void domainFigure(const std::string& path) override;    // editor_figures.cpp
    void sweepAnimation(const std::string& path) override;  // editor_figures.cpp
    std::vector<KeyBinding> keyBindings_;                   // from the command table's shortcuts (keyBindingsOf)
    void bindShortcuts();
    void runShortcuts();  // the table's keys pressed this frame

    // viewport.cpp: input; viewport_overlays.cpp: what is drawn over the 3D view
    void viewportInput();
    // A transform of the selection: a left drag on a selected point or a gizmo handle (`grab`
    // false, the button held; `axis` 0..2 for an arrow), or G / R / S (`grab` true).
    void beginDrag(bool grab, TransformKind kind = TransformKind::Move, int axis = -1);
    void transformKeys(double mx, double my);  // during a transform: axes, planes, typed values
    void placeCursor(double mx, double my);    // Shift+right click: the 3D cursor on a point or surface
    // The move gizmo at the pivot, in pane pixels: the centre, then the X, Y and Z arrow tips
    // (nullopt when there is nothing to transform or the pivot is behind the camera).
    std::optional<std::array<glm::dvec2, 4>> gizmoHandles(int width, int height) const;
    int gizmoHit(double mx, double my) const;  // -1 none, 0..2 an arrow, 3 the centre
    void updateDrag(double mx, double my);
    void finishDrag();
    void cancelDrag();
    DragView dragView() const;            // the interaction pane as the drag sees it
    std::array<int, 2> viewSize() const;  // the interaction pane's width and height in pixels, at least 1
    void drawViewportOverlays();
    // join_tool.cpp: join by picking (J), its state a JoinToolState.
    void setJoinTool(bool on);
    void joinToolInput(double mx, double my, bool overUi);
    void drawJoinPanel();
    void drawJoinOverlay(const std::function<void(const Vec3&, const Vec3&, unsigned, float)>& line) const;
    // curve_tool.cpp: draw a curve by clicking (C), its state a CurveToolState.
    void setCurveTool(bool on);
    void curveToolInput(double mx, double my, bool overUi);
    void finishCurve();  // runs curve-through (or curve-control) with the clicked points
    void drawCurvePanel();
    void drawCurveOverlay(const std::function<void(const Vec3&, const Vec3&, unsigned, float)>& line) const;
    // construction_preview.cpp: the wireframe of what a Surfaces button would make.
    void updateConstructionPreview();  // once a frame, after the panels asked
    void drawConstructionPreview(const std::function<void(const Vec3&, const Vec3&, unsigned, float)>& line) const;
    void drawPaneOverlays(const std::array<float, 4>& pane, bool active);  // selection, gizmo of one pane
    void drawMathOverlay();                                                // math_overlay.cpp: Teaching's Bézier math over the 3D view

    AppWindow& window_;
    std::unique_ptr<render::Renderer> renderer_;
    EditSession session_;
    const CommandTable commands_ = makeCommandTable();
    // Shorthands for the session's parts.
    Document& doc_ = session_.doc;
    Selection& sel_ = session_.sel;
    Camera& cam_ = session_.camera;
    Edge& lastEdge_ = session_.activeEdge;  // edge nearest the last surface click (extrude, unjoin)
    uint64_t seenVersion_ = 0, seenTopology_ = 0, seenShape_ = 0, seenSettings_ = 0, seenSerial_ = 0;  // the session as last drawn
    uint64_t docVersion_ = 0;  // bumped by every edit and settings change (caches of the document)
    std::vector<bool> usedMask_;
    // The document's height map (displacement), loaded when the file it names changes; a map that
    // cannot be read leaves the surface undisplaced and says why once.
    std::shared_ptr<const HeightMap> heightMap_;
    std::string heightMapFile_;
    std::shared_ptr<const HeightMap> documentHeightMap();

    // The viewport.
    Interaction mode_ = Interaction::None;
    DragController drag_;
    int hovered_ = -1;
    int hoveredGizmo_ = -1;
    float softRadiusPixels_ = 0.0f;                   // the soft-selection circle drawn last frame (0: none; the test trace)
    std::array<float, 4> axisGizmoRect_{0, 0, 0, 0};  // where the axis gizmo went last frame (x, y, w, h; the test trace)
    JoinTool join_;                                   // join by picking (ui/panels/join_tool)
    CurveToolState curve_;
    // The construction preview: the words asked this frame, and the last ones made with the
    // document version they were made on and the patches they would add (in a scratch document).
    struct ConstructionPreview {
        std::vector<std::string> asked, shown;
        uint64_t version = 0;
        std::unique_ptr<Document> doc;
        size_t firstPatch = 0;
    } preview_;
    bool grabAfterShortcut_ = false;  // the last shortcut was Shift+D: grab the copy
    double pressX_ = 0, pressY_ = 0;
    bool pressShift_ = false;
    double lastX_ = 0, lastY_ = 0;
    std::array<float, 4> viewArea_{0, 0, 1, 1};  // this frame's interaction pane (window pixels)
    bool showGround_ = true;
    bool fullDetail_ = false;  // View > Full Detail: a document heavy for the CPU renderer drawn at its own levels
    bool xray_ = false;        // box selection through the surface

    // The frame.
    uint64_t frameCount_ = 0;
    FrameReport report_;          // the last frame's times and the 3D view's statistics
    ContinuityWatch continuity_;  // the joins' measured continuity, updated every frame (live next to a drag)
    double dragMs_ = 0.0;         // this frame's drag solve + upload
    bool screenshotRequested_ = false;
    std::string screenshotPath_;
    bool quit_ = false;

    // Files, autosave, status line.
    Autosaver autosaver_;
    std::chrono::steady_clock::time_point lastAutosave_;
    double autosaveSeconds_ = 30.0;
    std::vector<std::string> recent_;
    std::string status_;
    std::chrono::steady_clock::time_point statusTime_;
    std::string autosaveError_;  // shown until an autosave succeeds
    // The last committed state, ready for a fatal signal (issue 72); null when the autosave
    // folder cannot be made.
    std::unique_ptr<EmergencySave> emergency_;
    uint64_t emergencyGeneration_ = ~uint64_t(0);
    bool emergencyModified_ = false;
    void updateEmergencySave();
    BackgroundWriter exports_;  // exports, written while the window goes on

    // The panels.
    TestTrace trace_;
    SidePanels sidePanels_;
    Dialogs dialogs_;
    CommandPalette palette_;
    bool showHelp_ = false;
    ShaderPanel shaders_;
    Teaching teaching_{window_, shaders_.open};
};

}  // namespace editor
}  // namespace pw::ui

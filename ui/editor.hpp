// The interactive editor: one GLFW window, the Vulkan renderer drawing the document into the
// swapchain, Dear ImGui panels on top. Blender-style navigation and editing (DESIGN §6).
#pragma once

#include <vulkan/vulkan.h>

#include <chrono>
#include <functional>
#include <map>
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/autosave.hpp"
#include "core/command_table.hpp"
#include "core/constraint_solver.hpp"
#include "core/continuity_report.hpp"
#include "core/document.hpp"
#include "core/edit_session.hpp"
#include "render/domain_view.hpp"
#include "core/edit_history.hpp"
#include "core/gltf_export.hpp"
#include "render/model_figure.hpp"
#include "core/picking.hpp"
#include "core/selection.hpp"
#include "render/shader_listing.hpp"
#include "render/stats.hpp"

struct GLFWwindow;

namespace pw::render {
class Device;
class SwapchainTarget;
class Renderer;
struct RenderOptions;
}  // namespace pw::render

namespace pw::ui {

// The partitionings a comparison pane can pick, in the order of its combo.
inline constexpr Spacing kPaneSpacings[] = {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2};

class ImGuiLayer;
class X11Presenter;

// Opens the editor on `file` (empty: the built-in teapot). Returns the exit code; 2 when there is
// no display.
int runEditor(const std::string& file);

// `patchwork bench --editor`: the editor's frame cost while a control point is dragged (G grab, the
// mouse moving every frame), against a bare offscreen render of the same view in the same run.
struct EditorBenchOptions {
    std::string file;          // empty: the built-in teapot
    int frames = 100;          // measured frames
    int width = 1280, height = 720;  // window size (pixels at content scale 1)
    float level = 16.0f;       // uniform tessellation level of the benchmarked document
    std::string json;          // write the results here as JSON when not empty
};
// Needs a display (Xvfb will do); returns the exit code (2 without a display).
int runEditorBench(const EditorBenchOptions& options);

// Where one editor frame's time went (wall clock, milliseconds).
struct FrameTimes {
    double ui = 0;       // input, panels and ImGui::Render (CPU), the drag solve included
    double drag = 0;     // of which: the drag's projection onto the joins and the partial upload
    double acquire = 0;  // waiting for a swapchain image
    double view = 0;     // the 3D view: record, submit and wait (Renderer::render), domain panes
    double present = 0;  // ImGui's command buffer, submit and present
    double total = 0;
};

enum class Interaction { None, Orbit, Pan, BoxSelect, PendingDrag, DragPoints, Grab };
enum class FileDialogMode { None, Open, SaveAs, Import, ExportGltf, Screenshot };

struct DragState {
    std::vector<Vec3> start;       // the whole pool at drag start
    std::vector<uint32_t> moved;   // the points the user moves (fixed in the solver)
    std::unique_ptr<DragSolver> solver;
    Vec3 anchor{0.0};              // centroid of the moved points at start
    Vec3 planeNormal{0.0, 0.0, 1.0};
    Vec3 startHit{0.0};            // where the start ray met the drag plane
    int axis = -1;                 // -1 free (view plane); 0/1/2 = X/Y/Z
    double startX = 0, startY = 0; // mouse at start (window coordinates)
    bool grab = false;             // G key (no button held)
    std::vector<Vec3> uploaded;    // pool as last written to the GPU (partial updates)
    std::vector<uint32_t> changed;
};

// The editor window: hosts the command table (core/command_table.hpp) for its menus, keys, F1 help
// and palette, and runs the editing session (core/edit_session.hpp) on screen.
class Editor final : public CommandHost {
public:
    Editor(GLFWwindow* window, const std::string& file);
    ~Editor() override;
    int run();
    // The editor benchmark (ui/editor_bench.cpp): drives this editor's own frames.
    int runBench(const EditorBenchOptions& options);

    // Called by GLFW callbacks.
    void wake() { wakeFrames_ = 8; }  // ImGui popups and hover states settle over a few frames
    // Key presses since the last frame with their modifiers (ImGui 1.86 keeps only key state, so a
    // press and release between two frames would be lost).
    void keyEvent(int key, int mods) { keyQueue_.emplace_back(key, mods); }
    // Where the left button went down (a press and a move can arrive in one frame).
    void leftPress(double x, double y) { leftPressX_ = x, leftPressY_ = y, leftPressed_ = true; }

private:
    // editor.cpp: frame loop and files
    void frame();
    // Runs one line of the command table; errors go to the error dialog. `guarded` false: the
    // unsaved-changes prompt was answered already.
    void runCommand(const std::vector<std::string>& words, bool guarded = true);
    void runCommand(const std::string& line) { runCommand(splitCommandWords(line)); }
    void setDocument(Document doc, const std::string& path);
    void documentReplaced();  // after the session's document was replaced: view, title, recent files
    void documentChanged(bool topology);  // re-upload
    void commit(const std::string& label) { session_.commit(label); }
    void setPointHeld(uint32_t p, const Vec3& position);  // inspector edit, joins held
    void recoverAutosave();
    void autosaveTick();
    void writeTrace();
    void addRecent(const std::string& path);
    void showError(const std::string& message);
    bool isModified() const { return session_.isModified(); }

    // CommandHost: what the commands ask of the window.
    bool hasWindow() const override { return true; }
    bool confirmDiscard(const std::vector<std::string>& words) override;
    void write(const Document& doc, const std::string& path) override;
    void saved(const std::string& path) override;
    void fileDialog(FileDialogKind kind) override;
    void toggle(WindowToggle which) override;
    bool toggled(WindowToggle which) const override;
    void quit() override { quit_ = true; }
    void screenshot(const std::string& path) override;
    bool frame(const Bounds& box) override;
    void status(const std::string& message) override;

    // editor_view.cpp: viewport interaction and overlays
    void viewportInput();
    void beginDrag(bool grab);
    void updateDrag(double mx, double my);
    void finishDrag();
    void cancelDrag();
    void drawViewportOverlays();
    void frameBox(const Bounds& box);
    Camera viewCamera() const { return cam_; }

    // editor_panels.cpp: menus, panels, dialogs
    void drawUi();
    void drawMenuBar();
    void drawLeftPanel();
    void drawRightPanel();
    // A fixed full-height side panel window at x; its background is not drawn by ImGui but filled
    // by one clear in the overlay pass (panelRects_): on CPU devices ImGui's textured, blended
    // background quads cost ~1.5 ms a frame at 720p (docs/PERFORMANCE.md).
    void beginSidePanel(const char* name, float x, float width);
    std::vector<std::array<float, 4>> panelRects_;  // this frame's side panels (window pixels)
    void drawFileDialog();
    void drawModals();
    void drawHelp();
    void patchOp(const std::string& label, const std::function<void(Document&)>& op, bool topology = true);
    // editor_net_panel.cpp: net surfaces (create, rows/columns, closing, basis, conversion)
    void drawNetPanel();
    int activeNet() const;  // the selected net, or the net of the selected point; -1 when none

    GLFWwindow* window_;
    std::unique_ptr<render::Device> dev_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    std::unique_ptr<X11Presenter> hostPresenter_;  // CPU devices on X11: frames go to the window by XPutImage
    std::unique_ptr<render::SwapchainTarget> target_;
    std::unique_ptr<render::Renderer> renderer_;
    std::unique_ptr<ImGuiLayer> imgui_;

    EditSession session_;
    const CommandTable commands_ = makeCommandTable();
    // Shorthands for the session's parts that every panel uses.
    Document& doc_ = session_.doc;
    Selection& sel_ = session_.sel;
    Camera& cam_ = session_.camera;
    Edge& lastEdge_ = session_.activeEdge;  // edge nearest the last surface click (extrude, unjoin)
    uint64_t seenVersion_ = 0, seenTopology_ = 0, seenSerial_ = 0;  // the session as last drawn
    std::unique_ptr<DragSolver> inspectorSolver_;   // factorised for inspectorPoint_ held
    uint32_t inspectorPoint_ = 0;
    uint64_t inspectorGeneration_ = 0;
    int hovered_ = -1;
    int hoveredEdgePatch_ = -1;
    std::vector<bool> usedMask_;
    uint64_t docVersion_ = 0;

    Interaction mode_ = Interaction::None;
    DragState drag_;
    double pressX_ = 0, pressY_ = 0;
    bool pressShift_ = false;
    double lastX_ = 0, lastY_ = 0;

    // frame pacing and stats
    int wakeFrames_ = 3;
    uint64_t frameCount_ = 0;
    std::chrono::steady_clock::time_point lastFrame_{};
    double frameMs_ = 0.0;
    FrameTimes frameTimes_;  // the last frame's breakdown (Stats panel, benchmark)
    double dragMs_ = 0.0;    // this frame's drag solve + upload
    std::optional<std::array<double, 2>> benchMouse_;  // the benchmark's mouse position (window pixels)
    render::RenderOptions viewOptions() const;  // what the 3D view draws this frame
    render::FrameStats stats_;
    bool swapchainDirty_ = false;

    // autosave
    Autosaver autosaver_;
    std::chrono::steady_clock::time_point lastAutosave_;
    double autosaveSeconds_ = 30.0;
    std::vector<AutosaveEntry> recoverable_;
    bool offerRecovery_ = false;

    // UI state
    bool showHelp_ = false;
    bool quit_ = false;
    std::vector<std::string> pendingCommand_;  // waits for the unsaved-changes prompt (empty = none)
    bool runPendingAfterSave_ = false;  // Save As from that prompt: run it once the file is written
    bool openUnsavedPrompt_ = false;
    bool showPalette_ = false;
    void drawPalette();  // ui/editor_commands.cpp: F3, type to search, Enter runs
    // A panel button that runs a command line: disabled when the command is, its help as tooltip.
    void commandButton(const char* label, const std::string& line, const char* trace = nullptr);
    char paletteQuery_[256] = {};
    int paletteCursor_ = 0;
    bool paletteRefocus_ = false;  // give the palette's field the keyboard next frame
    bool paletteCursorToEnd_ = false;  // and put its text cursor after the text
    void completeInPalette(const Command& c);  // open the palette with "name " to complete
    std::string errorMessage_;
    bool openError_ = false;
    FileDialogMode fileMode_ = FileDialogMode::None;
    std::filesystem::path browseDir_;
    char fileName_[512] = {};
    std::vector<std::string> recent_;
    GltfExportOptions& exportOptions_ = session_.exportOptions;
    std::string status_;
    std::chrono::steady_clock::time_point statusTime_;
    std::vector<JoinContinuity> continuity_;
    double continuityResidual_ = 0.0;  // maxConstraintResidual at continuityVersion_
    uint64_t continuityVersion_ = ~0ull;
    bool screenshotRequested_ = false;
    std::string screenshotPath_;
    float splitT_ = 0.5f;
    int netRows_ = 7, netCols_ = 7, netShape_ = 0, netBasis_ = 1;  // "Add net" inputs
    int joinA_ = 0, joinB_ = 1, joinEdgeA_ = 2, joinEdgeB_ = 0, joinKind_ = 1;
    std::string tracePath_;
    std::vector<std::pair<int, int>> keyQueue_;
    double leftPressX_ = 0, leftPressY_ = 0;
    bool leftPressed_ = false;
    bool keyPressed(int key, int mods) const;
    struct KeyBinding {
        int key = 0, mods = 0;
        std::string line;  // the command line it runs
    };
    std::vector<KeyBinding> keyBindings_;  // from the command table's shortcuts
    void runShortcuts();                   // the command table's keys pressed this frame
    void bindShortcuts();                  // keyBindings_ from the table (ui/editor_commands.cpp)
    bool showGround_ = true;
    // Test trace: window-coordinate centres of a few dialog buttons, and which modal is open.
    std::map<std::string, std::array<float, 2>> traceItems_;
    std::string openModal_;
    void traceItem(const std::string& name);
    float leftPanelWidth_ = 0.0f, rightPanelWidth_ = 0.0f;
    float uiScale_ = 1.0f;  // monitor content scale (HiDPI)

    // Teaching (ui/editor_teaching.cpp): the live domain view with 1, 2 or 4 comparison panes, the
    // notes' presets, a level sweep, and presentation mode.
    void teachingInput();       // F5 presentation mode; advances a playing sweep
    void setPresentation(bool on);
    void drawTeachingControls();  // the Teaching section of the right panel
    void drawTeachingWindow();    // the domain view window: where its panes go this frame, labels
    void drawPresentationOverlay();
    void drawDomainPanes();     // after the 3D view, before ImGui: the GPU domain tessellation
    std::unique_ptr<render::DomainView> domainView_;
    bool showDomain_ = false, presentation_ = false;
    int domainKind_ = 0, domainPaneCount_ = 1;
    std::array<int, 4> paneSpacing_{0, 1, 2, 3};       // index into Spacing
    std::array<float, 4> paneLevel_{0, 0, 0, 0};       // a pane's own uniform level; 0: the document's
    // The 3D view split into the same panes (each with its partitioning and level, one camera).
    bool splitView_ = false;
    bool viewSplit() const { return splitView_ && domainPaneCount_ > 1; }
    // Where the 3D view's panes are (window pixels): one covering the window unless split, else the
    // panes between the side panels.
    std::vector<std::array<float, 4>> viewPaneRects() const;
    // The pane the mouse works in: the one under it, held while an interaction lasts.
    std::array<float, 4> interactionPane(double mouseX, double mouseY);
    int activePane_ = 0;
    std::array<float, 4> viewArea_{0, 0, 1, 1};  // this frame's interaction pane (window pixels)
    void renderView(const render::RenderOptions& o);  // the 3D view: one render, or one per pane
    void drawPaneCaptions();                          // each split pane's partitioning, level, triangles
    void drawPaneOverlays(const std::array<float, 4>& pane, bool active);  // ground grid, selection, gizmo of one pane
    std::array<int, 2> viewSize() const;  // the interaction pane's width and height in pixels, at least 1
    std::vector<render::PaneResult> viewPanes_;  // what each split pane drew last frame
    std::vector<render::DomainViewOptions> domainPanes_;  // this frame's panes, framebuffer pixels
    std::vector<render::DomainStats> domainStats_;
    struct Sweep {
        bool playing = false, loop = true;
        float from = 1.0f, to = 16.0f, seconds = 4.0f, level = 1.0f;
        std::chrono::steady_clock::time_point start;
    } sweep_;
    float presentationScale_ = 2.0f;

    // Shader panel (ui/editor_shaders.cpp): the GLSL of the pipelines the current settings draw with.
    void drawShaderWindow();
    bool showShaders_ = false, shaderHideInactive_ = false;
    std::string shaderPipeline_;  // the pipeline picked in the panel (by name: the list changes)
    std::string shaderShown_;     // the variant on screen this frame ("" = panel closed)
    std::vector<std::string> shaderVariantsInUse_;
    std::map<std::string, render::ShaderListing, std::less<>> shaderListings_;  // cache by variant
};

}  // namespace pw::ui

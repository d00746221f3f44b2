// The editor: its parts put together, documents replaced and changed, commands run, autosave and
// recent files, and one frame (UI, the 3D view, ImGui on top, present).
#include "ui/editor/editor.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "core/eval/displacement.hpp"
#include "core/model/camera_math.hpp"
#include "core/model/topology.hpp"

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/io/document_io.hpp"
#include "core/select/picking.hpp"
#include "core/select/selection_ops.hpp"
#include "render/scene/renderer.hpp"
#include "render/vk/device.hpp"
#include "ui/platform/swapchain_target.hpp"

namespace pw::ui {
inline namespace editor {

namespace fs = std::filesystem;

namespace {

fs::path recentFile() { return autosaveDirectory() / "recent.txt"; }

}  // namespace

int runEditor(const std::string& file) {
    return AppWindow::open(std::nullopt, [&](AppWindow& window) {
        Editor editor(window, file);
        return editor.run();
    });
}

int runEditorBench(const EditorBenchOptions& options) {
    return AppWindow::open(std::array<int, 2>{options.width, options.height}, [&](AppWindow& window) {
        Editor editor(window, options.file);
        return editor.runBench(options);
    });
}

Editor::Editor(AppWindow& window, const std::string& file) : window_(window) {
    if (const char* a = std::getenv("PATCHWORK_AUTOSAVE_SECONDS"); a && *a) autosaveSeconds_ = std::max(0.5, std::atof(a));
    renderer_ = std::make_unique<render::Renderer>(window_.device(), window_.target());
    bindShortcuts();

    // The document, recent files, crash recovery.
    // A state file that is not a small regular file (a FIFO, a link to /dev/zero) is left alone:
    // the editor starts without it and says so (issue 73).
    std::string stateNote;
    if (std::error_code ec; std::filesystem::exists(recentFile(), ec)) try {
            std::istringstream in(readFileLimited(recentFile(), 1 << 20));
            for (std::string line; std::getline(in, line);)
                if (!line.empty()) recent_.push_back(line);
        } catch (const InputError& e) {
            stateNote = std::string("The recent files were not read: ") + e.what();
        }
    // Warm the pipelines on the first acquired image with a one-patch scene, before the document is
    // uploaded (the first real frame then pays no JIT, and a big document is not drawn a dozen times
    // to get there), and present it through the normal path.
    if (window_.acquire()) {
        renderer_->warmUp();
        window_.presentEmpty();
    }
    dialogs_.offerRecovery(findRecoverableAutosaves());
    // A bad file on the command line throws InputError: reported with exit 2 like the other commands.
    if (file.empty())
        setDocument(builtinTeapot(), "");
    else {
        const std::vector<std::string> notes = session_.open(file);  // as File > Open
        documentReplaced();
        if (!notes.empty()) status(skippedSummary(notes));
    }
    if (!stateNote.empty()) status(stateNote);
    lastAutosave_ = std::chrono::steady_clock::now();
    try {
        ensurePrivateDirectory(autosaveDirectory());
        emergency_ = std::make_unique<EmergencySave>(autosaver_.documentPath(), autosaver_.notePath());
    } catch (const std::exception& e) {
        autosaveError_ = std::string("No emergency save: ") + e.what();
    }
}

Editor::~Editor() { vkDeviceWaitIdle(window_.device().device()); }

void Editor::setDocument(Document doc, const std::string& path) {
    session_.reset(std::move(doc), path);
    documentReplaced();
}

void Editor::documentReplaced() {
    seenSerial_ = session_.documentSerial();
    hovered_ = -1;
    sidePanels_.inspector.documentReplaced();
    // Files without a stored view (or the teapot) are framed; PATCHWORK_EDITOR_VIEW (tests) names a view.
    const char* fixed = std::getenv("PATCHWORK_EDITOR_VIEW");
    if (fixed && *fixed)
        if (auto c = applyNamedView(cam_, fixed)) cam_ = *c;
    if (cam_ == Camera{} || (fixed && *fixed)) frameBox(computeBounds(doc_.points));
    // The 3D cursor starts at the origin (Blender's): mirror and add-about-cursor act about it
    // until the user places it.
    session_.cursor = Vec3(0.0);
    documentChanged(true);
    if (!session_.path().empty()) addRecent(session_.path());
    window_.setTitle("Patchwork — " + session_.title());
}

std::shared_ptr<const HeightMap> Editor::documentHeightMap() {
    const std::string file = doc_.displacement.active() ? resolveMapPath(doc_.displacement, session_.path()).string() : "";
    if (file != heightMapFile_) {
        heightMapFile_ = file;
        heightMap_.reset();
        if (!file.empty()) {
            try {
                heightMap_ = std::make_shared<const HeightMap>(loadHeightMap(file));
            } catch (const std::exception& e) {
                status(std::string("The height map was not loaded; the surface is shown undisplaced: ") + e.what());
            }
        }
    }
    return heightMap_;
}

void Editor::documentChanged(bool topology) {
    // Hidden items are neither drawn nor picked: the renderer gets the shown document (same pool).
    if (anyHidden(doc_)) {
        const Document shown = visibleDocument(doc_);
        renderer_->setDocument(shown, documentHeightMap());
        if (topology) usedMask_ = usedPointMask(shown);
    } else {
        renderer_->setDocument(doc_, documentHeightMap());
        if (topology) usedMask_ = usedPointMask(doc_);
    }
    clampSelection(sel_, doc_);
    seenVersion_ = session_.version();
    seenTopology_ = session_.topologyVersion();
    seenShape_ = session_.shapeVersion();
    seenSettings_ = session_.settingsVersion();
    ++docVersion_;
    wake();
}

void Editor::levelsChanged() {
    if (anyHidden(doc_)) return documentChanged(false);  // the renderer holds the shown items only
    renderer_->updateLevels(doc_);
    seenVersion_ = session_.version();
    ++docVersion_;
    wake();
}

void Editor::runCommand(const std::vector<std::string>& words, bool guarded) {
    try {
        commands_.run(session_, *this, words, guarded);
    } catch (const std::exception& e) {
        showError(std::string("The command did not run; the document is unchanged.\n\n") + e.what());
    }
    followSession();
    wake();
}

void Editor::followSession() {
    if (session_.documentSerial() != seenSerial_) return documentReplaced();
    if (session_.version() == seenVersion_) return;
    if (session_.shapeVersion() != seenShape_) return documentChanged(session_.topologyVersion() != seenTopology_);
    if (session_.settingsVersion() == seenSettings_) return levelsChanged();  // only items' own levels: rewritten in place
    // Settings travel in the render options: nothing to upload while a slider moves.
    seenVersion_ = session_.version();
    seenSettings_ = session_.settingsVersion();
    settingsChanged();
}

EditorSnapshot Editor::snapshot() const {
    return {.session = session_,
            .teaching = teaching_,
            .report = report_,
            .dialogs = dialogs_,
            .shaders = shaders_,
            .palette = palette_,
            .continuity = continuity_,
            .join = join_.state(),
            .curveTool = curve_,
            .usedMask = usedMask_,
            .windowSize = window_.windowSize(),
            .framebufferSize = window_.framebufferSize(),
            .frame = frameCount_,
            .generation = session_.generation() + 1,
            .emergencyPublished = emergency_ ? emergency_->published() : 0,
            .mode = mode_,
            .hovered = hovered_,
            .softRadiusPixels = softRadiusPixels_,
            .degraded = degradedLoad().has_value(),
            .help = showHelp_,
            .axisGizmo = axisGizmoRect_,
            .viewArea = viewArea_,
            .layout = layout()};
}

void Editor::previewCommand(const std::vector<std::string>& words) {
    try {
        commands_.preview(session_, *this, words);
    } catch (const std::exception&) {
        return;  // the document is unchanged; the runCommand on release reports the error
    }
    followSession();  // a net's tension or an item's own displacement is uploaded, settings and levels are not
}

void Editor::showError(const std::string& message) {
    dialogs_.showError(message);
    wake();
}

void Editor::addRecent(const std::string& path) {
    std::string abs = path;
    std::error_code ec;
    const fs::path a = fs::absolute(path, ec);
    if (!ec) abs = a.string();
    std::erase(recent_, abs);
    recent_.insert(recent_.begin(), abs);
    if (recent_.size() > 10) recent_.resize(10);
    try {
        fs::create_directories(recentFile().parent_path(), ec);
        std::string text;
        for (const std::string& r : recent_) text += r + "\n";
        writeFileAtomic(recentFile(), text);
    } catch (...) {
        // Recent files are a convenience: an unwritable state directory is not an error.
    }
}

void Editor::recoverAutosave() {
    std::vector<AutosaveEntry>& recoverable = dialogs_.recoverable;
    if (recoverable.empty()) return;
    const AutosaveEntry e = recoverable.front();
    try {
        setDocument(loadDocument(e.document), e.originalPath);
        session_.setForceModified(true);  // the recovered state differs from the file on disk
        // Kept until the work is safe elsewhere (a save, or this editor's own autosave): a second
        // crash before then must not lose it.
        autosaver_.adopt(e);
        recoverable.erase(recoverable.begin());
        status("Recovered autosave of " + (e.originalPath.empty() ? std::string("untitled") : e.originalPath));
    } catch (const std::exception& ex) {
        showError(std::string("Could not recover the autosave.\n\n") + ex.what());
    }
}

// Each committed state (a commit, undo, redo, a new or opened document) goes to the emergency save
// while the document is modified; the worker serialises it off the frame.
void Editor::updateEmergencySave() {
    if (!emergency_) return;
    const bool modified = session_.isModified();
    if (session_.generation() == emergencyGeneration_ && modified == emergencyModified_) return;
    emergencyGeneration_ = session_.generation();
    emergencyModified_ = modified;
    if (modified)
        emergency_->submit(session_.documentToSave(), session_.path(), emergencyGeneration_ + 1);
    else
        emergency_->clear(emergencyGeneration_ + 1);
}

void Editor::idleTick() {
    updateEmergencySave();
    for (const BackgroundWriter::Result& r : exports_.takeFinished()) {
        if (r.error.empty())
            status("Exported " + r.path);
        else
            showError(r.error);
        wake();
    }
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - lastAutosave_).count() < autosaveSeconds_) return;
    lastAutosave_ = now;
    if (!session_.isModified() || mode_ == Interaction::DragPoints || mode_ == Interaction::Grab) return;
    try {
        const Document out = session_.documentToSave();
        autosaver_.save(out, session_.path());
        autosaveError_.clear();
    } catch (const std::exception& e) {
        autosaveError_ = std::string("Autosave failed: ") + e.what();
    }
}

int Editor::run() {
    window_.run(*this);
    autosaver_.discard();
    if (exports_.pending()) std::fprintf(stderr, "patchwork: finishing the export of %s\n", printable(exports_.current()).c_str());
    exports_.waitIdle();
    int status = 0;
    for (const BackgroundWriter::Result& r : exports_.takeFinished())
        if (!r.error.empty()) {
            std::fprintf(stderr, "patchwork: %s\n", r.error.c_str());
            status = 2;
        }
    return status;
}

std::optional<FrameLoad> Editor::degradedLoad() const {
    const TessSettings shown = teaching_.shownTess(doc_.tess);
    if (fullDetail_ || shown.adaptive != AdaptiveMode::None || window_.device().properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU)
        return std::nullopt;
    const FrameLoad load = frameLoad(doc_, shown);
    if (!heavyForCpu(load)) return std::nullopt;
    return load;
}

render::RenderOptions Editor::drawnOptions() const {
    render::RenderOptions o = viewOptions();
    if (const auto load = degradedLoad()) {  // too heavy for lavapipe at its own levels: each edge about 8 px instead
        o.tess.adaptive = AdaptiveMode::ScreenSpace;
        o.tess.targetPixels = 8.0f;
        o.tess.maxLevel = float(load->segments);
    }
    return o;
}

render::RenderOptions Editor::viewOptions() const {
    render::RenderOptions o = render::optionsFromDocument(doc_);
    o.tess = teaching_.shownTess(doc_.tess);  // a preset or sweep shows its own levels
    o.camera = cam_;
    o.hoveredPoint = hovered_;
    o.selectedPoint = sel_.points.empty() ? -1 : int(sel_.points.front());
    if (showGround_) o.groundGridStep = niceGridStep(modelSize(doc_));
    o.lodCamera = teaching_.debugCamera;  // levels and culling from the frozen camera, drawn from this one
    // The curvature graph across the selected patch's highlighted edge when it is joined, or, with
    // points selected (dragged), across the first join next to them.
    if (doc_.display.showCombs && sel_.patch >= 0 && size_t(sel_.patch) < doc_.patches.size()) {
        o.combJoin = findJoin(doc_, uint32_t(sel_.patch), lastEdge_);
    } else if (doc_.display.showCombs && !sel_.points.empty()) {
        const std::vector<size_t> near = joinsTouching(doc_, sel_.points);
        if (!near.empty()) o.combJoin = int(near.front());
    }
    return o;
}

void Editor::drawUi() {
    trace_.beginFrame();
    continuity_.update(doc_, documentVersion(), interacting(), interacting() ? session_.selectedPoints() : std::vector<uint32_t>{});
    if (!teaching_.presentation) {
        drawMenuBar(*this, palette_, recent_);
        sidePanels_.drawLeft(*this);
        sidePanels_.drawRight(*this, teaching_);
    }
    teaching_.drawDomainWindow(*this);
    if (teaching_.presentation) teaching_.drawPresentationOverlay(*this);  // with this frame's domain counts
    shaders_.draw(*this, window_.device().caps().geometryShader, teaching_.shownTess(doc_.tess), teaching_.domainPanes);
    if (showHelp_) drawHelp(*this, showHelp_);
    if (palette_.open) palette_.draw(*this);
    drawJoinPanel();
    drawCurvePanel();
    updateConstructionPreview();
    // The modals last, after every other window of the frame (ui/panels/dialogs.hpp): Dear ImGui
    // 1.86 aborts when a window appears after a modal's first Begin in the same frame (issue 72:
    // the palette's refused `net-basis` opened the error, C the Draw curve panel after it).
    dialogs_.drawModals(*this, [this] { recoverAutosave(); });
    // Status line: the last message for 6 s, and a running export for as long as it runs.
    const ImGuiIO& io = ImGui::GetIO();
    std::string line = std::chrono::steady_clock::now() - statusTime_ < std::chrono::seconds(6) ? status_ : std::string();
    if (const std::string exporting = exports_.current(); !exporting.empty()) {
        const size_t more = exports_.pending() - 1;
        line += (line.empty() ? "" : "   |   ") + ("Exporting " + exporting) +
                (more ? " (" + std::to_string(more) + " more queued)" : std::string()) + "...";
    }
    if (!line.empty())
        ImGui::GetForegroundDrawList()->AddText(ImVec2(layout().left + 12.0f, io.DisplaySize.y - 24.0f), IM_COL32(220, 220, 220, 255),
                                                line.c_str());
    // A failed autosave stays in view, above the status line, until an autosave succeeds.
    if (!autosaveError_.empty())
        ImGui::GetForegroundDrawList()->AddText(ImVec2(layout().left + 12.0f, io.DisplaySize.y - 44.0f), IM_COL32(255, 120, 90, 255),
                                                autosaveError_.c_str());
}

void Editor::drawFrame() {
    using clock = std::chrono::steady_clock;
    auto ms = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
    const auto t0 = clock::now();
    dragMs_ = 0.0;
    report_.frameMs = window_.frameMs();
    // Step 1: UI and viewport input.
    sidePanels_.beginFrame();
    window_.beginUi();
    viewportInput();
    teaching_.input(*this);
    if (!teaching_.presentation) drawViewportOverlays();
    drawMathOverlay();
    teaching_.drawPaneCaptions(layout());
    teaching_.drawStageBars(layout(), report_.stats);
    drawUi();
    window_.endUi();
    const auto t1 = clock::now();

    // Step 2: the 3D view into the swapchain image.
    if (!window_.acquire()) return;
    const auto t2 = clock::now();
    report_.stats = teaching_.renderView(*renderer_, drawnOptions(), layout());
    teaching_.drawDomainPanes();
    if (screenshotRequested_) {
        screenshotRequested_ = false;
        try {
            window_.writeScreenshot(screenshotPath_, layout().left, layout().right);
            status("Screenshot saved to " + screenshotPath_);
        } catch (const std::exception& e) {
            showError(std::string("Could not save the screenshot.\n\n") + e.what());
        }
    }
    // Step 3: ImGui on top, present.
    const auto t3 = clock::now();
    window_.present(sidePanels_.fills());
    const auto t4 = clock::now();
    report_.times = {ms(t0, t1), dragMs_, ms(t1, t2), ms(t2, t3), ms(t3, t4), ms(t0, t4)};
    ++frameCount_;
    if (trace_.enabled()) trace_.write(snapshot());
}

}  // namespace editor
}  // namespace pw::ui

// The editor and the command table (core/commands/command_table.hpp): the CommandHost the window is for the
// commands, and the keyboard shortcuts from the table. The menu bar, F1 help and F3 palette
// generated from the table are ui/panels/panel_menu_bar.cpp, ui/panels/panel_help.cpp and ui/panels/panel_palette.cpp.
#include <GLFW/glfw3.h>

#include <cstdio>
#include <ctime>

#include "core/base/file_io.hpp"
#include "core/io/document_io.hpp"
#include "core/select/selection_ops.hpp"
#include "ui/editor/editor.hpp"
#include "ui/platform/app_window.hpp"
#include "ui/platform/shortcuts.hpp"
#include "ui/platform/swapchain_target.hpp"

namespace pw::ui {
inline namespace editor {

void Editor::bindShortcuts() { keyBindings_ = keyBindingsOf(commands_); }

void Editor::runShortcuts() {
    for (const KeyBinding& k : keyBindings_)
        if (window_.keyPressed(k.chord.key, k.chord.mods)) {
            const std::vector<std::string> words = splitCommandWords(k.line);
            const Command* c = commands_.find(words.front());
            if (!c || !commands_.isEnabled(*c, session_)) continue;
            const uint64_t before = session_.version();
            runCommand(words);
            // Shift+D (Blender): the copy follows the mouse at once; Esc leaves it where it appeared.
            grabAfterShortcut_ = words.front() == "duplicate" && session_.version() != before;
        }
}

// --- CommandHost: what the commands ask of the window ---

bool Editor::confirmDiscard(const std::vector<std::string>& words) {
    dialogs_.askToDiscard(words);
    wake();
    return false;
}

bool Editor::confirmOverwriteChanged(const std::string& path) {
    dialogs_.askOverwriteChanged(path);
    wake();
    return false;
}

std::optional<TriangleMesh> Editor::displayedMesh(Document& doc, ExportOptions& options, const std::string& path) {
    if (!options.asDisplayed || !isMeshFormat(path)) return std::nullopt;
    // What the 3D view draws now, from the GPU; hidden items are not drawn, so not exported.
    render::CapturedSurface c = renderer_->captureSurface(viewOptions());
    const VkExtent2D e = window_.target().extent();
    options.viewport = {int(e.width), int(e.height)};
    options.culledPatches = c.culledPatches();
    if (anyHidden(doc)) doc = visibleDocument(doc);
    status("As displayed: " + std::to_string(c.gpuTriangles) + " triangles from the tessellator" +
           (c.patchesCulled ? ", " + std::to_string(c.patchesCulled) + " patches culled as on screen" : std::string()));
    return std::move(c.mesh);
}

void Editor::write(const Document& doc, const std::string& path) {
    Document copy = doc;
    ExportOptions options = session_.exportOptions;
    std::optional<TriangleMesh> displayed = displayedMesh(copy, options, path);
    saveDocument(copy, path, options, displayed ? &*displayed : nullptr);
}

void Editor::exportFile(const Document& doc, const std::string& path) {
    checkOutputPath(path);  // a path that cannot be written is refused now, not seconds later
    Document copy = doc;
    ExportOptions options = session_.exportOptions;
    std::optional<TriangleMesh> displayed = displayedMesh(copy, options, path);  // on this thread: it uses the GPU
    exports_.enqueue(std::move(copy), path, options, std::move(displayed));      // the status line shows it until it is done
    wake();
}

void Editor::saved(const std::string& path) {
    addRecent(path);
    if (!session_.isModified()) autosaver_.discard();  // the file on disk holds everything now
    window_.setTitle("Patchwork — " + session_.title());
}

void Editor::fileDialog(FileDialogKind kind) {
    dialogs_.openFileDialog(kind, doc_.name);
    wake();
}

void Editor::toggle(WindowToggle which) {
    switch (which) {
        case WindowToggle::Help:
            showHelp_ = !showHelp_;
            break;
        case WindowToggle::Palette:
            palette_.toggle();
            break;
        case WindowToggle::Presentation:
            teaching_.setPresentation(*this, !teaching_.presentation);
            break;
        case WindowToggle::DomainView:
            teaching_.showDomain = !teaching_.showDomain;
            break;
        case WindowToggle::ShaderPanel:
            shaders_.open = !shaders_.open;
            break;
        case WindowToggle::GroundGrid:
            showGround_ = !showGround_;
            break;
        case WindowToggle::FullDetail:
            fullDetail_ = !fullDetail_;
            break;
        case WindowToggle::JoinTool:
            setJoinTool(!join_.state().on);
            break;
        case WindowToggle::CurveTool:
            setCurveTool(!curve_.on);
            break;
        case WindowToggle::XRay:
            xray_ = !xray_;
            break;
    }
    wake();
}

void Editor::setPresentationTextScale(float scale) {
    teaching_.presentationScale = scale;
    wake();
}

bool Editor::toggled(WindowToggle which) const {
    switch (which) {
        case WindowToggle::Help:
            return showHelp_;
        case WindowToggle::Palette:
            return palette_.open;
        case WindowToggle::Presentation:
            return teaching_.presentation;
        case WindowToggle::DomainView:
            return teaching_.showDomain;
        case WindowToggle::ShaderPanel:
            return shaders_.open;
        case WindowToggle::GroundGrid:
            return showGround_;
        case WindowToggle::FullDetail:
            return fullDetail_;
        case WindowToggle::JoinTool:
            return join_.state().on;
        case WindowToggle::CurveTool:
            return curve_.on;
        case WindowToggle::XRay:
            return xray_;
    }
    return false;
}

void Editor::screenshot(const std::string& path) {
    std::string file = path;
    if (file.empty()) {
        char name[64];
        const std::time_t t = std::time(nullptr);
        std::strftime(name, sizeof name, "patchwork-%Y%m%d-%H%M%S.png", std::localtime(&t));
        file = name;
    }
    screenshotRequested_ = true;
    screenshotPath_ = file;
    wake();
}

bool Editor::frame(const Bounds& box) {
    frameBox(box);
    return true;
}

void Editor::status(const std::string& message) {
    status_ = message;
    statusTime_ = std::chrono::steady_clock::now();
}

}  // namespace editor
}  // namespace pw::ui

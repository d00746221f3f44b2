// What a panel may use of the editor (ui/editor/editor.hpp implements it): the editing session, the
// command table, and the editor's reactions to an edit. Panels (ui/panel_*.cpp, ui/dialog_*.cpp)
// keep their own inputs and draw with ImGui; what they change goes through here.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/commands/command_table.hpp"
#include "core/edit/edit_session.hpp"
#include "core/solve/continuity_watch.hpp"
#include "render/vk/stats.hpp"

namespace pw::ui {
inline namespace panels {

// Where one editor frame's time went (wall clock, milliseconds).
struct FrameTimes {
    double ui = 0;       // input, panels and ImGui::Render (CPU), the drag solve included
    double drag = 0;     // of which: the drag's projection onto the joins and the partial upload
    double acquire = 0;  // waiting for a swapchain image
    double view = 0;     // the 3D view: record, submit and wait (Renderer::render), domain panes
    double present = 0;  // ImGui's command buffer, submit and present
    double total = 0;
};

// The last frame, for the Stats panel and the presentation overlay.
struct FrameReport {
    double frameMs = 0.0;  // between the last two frames
    FrameTimes times;
    render::FrameStats stats;  // the 3D view's (the first pane's when split)
};

// The side panels' widths this frame (window pixels): other windows open between them.
struct PanelLayout {
    float left = 0.0f, right = 0.0f;
};

class PanelContext {
public:
    virtual ~PanelContext() = default;
    virtual EditSession& session() = 0;
    virtual const CommandTable& commands() const = 0;
    virtual CommandHost& host() = 0;
    // Runs one command line; errors go to the error dialog. `guarded` false: the unsaved-changes
    // prompt was answered already.
    virtual void runCommand(const std::vector<std::string>& words, bool guarded = true) = 0;
    void runLine(const std::string& line) { runCommand(splitCommandWords(line)); }
    // A previewable command (CommandContext::preview) while a slider moves: the document changes,
    // no undo step is recorded; errors are left to the runCommand that follows on release.
    virtual void previewCommand(const std::vector<std::string>& words) = 0;
    // A construction command (revolve c0 Z 270, loft c0 c1, ...) shown as a wireframe in the view
    // for this frame only, the document untouched: what the button under the mouse would make.
    virtual void previewConstruction(const std::vector<std::string>& words) { (void)words; }
    virtual void documentChanged(bool topology) = 0;  // session().doc was edited: upload it
    // Only per-patch or per-triangle levels were edited: the renderer rewrites the levels alone.
    virtual void levelsChanged() { documentChanged(false); }
    virtual void settingsChanged() = 0;            // tessellation or display settings (they travel in the render options)
    virtual uint64_t documentVersion() const = 0;  // bumped by both
    virtual void showError(const std::string& message) = 0;
    virtual void wake() = 0;                               // draw the next frames
    virtual bool interacting() const = 0;                  // a drag, orbit, pan or box select is under way
    virtual bool keyPressed(int key, int mods) const = 0;  // queued this frame
    virtual float uiScale() const = 0;
    virtual void frameBox(const Bounds& box) = 0;  // fit the view to the box
    virtual const Camera& viewCamera() const = 0;  // the 3D view's camera now
    virtual const PanelLayout& layout() const = 0;
    virtual const FrameReport& frameReport() const = 0;
    virtual const ContinuityWatch& continuityWatch() const = 0;  // the joins' live continuity, this frame's
};

// A button that runs a command line: disabled when the command is, its help as tooltip, traced
// under `trace` when given (its label's "##trace").
void commandButton(PanelContext& ctx, const char* label, const std::string& line, const char* trace = nullptr);
// A number as a command word that reads back to the same double ("%.17g").
std::string commandWord(double v);

}  // namespace panels
}  // namespace pw::ui

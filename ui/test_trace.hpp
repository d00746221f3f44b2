// The test trace (PATCHWORK_EDITOR_TRACE=file): after every frame the editor's state as JSON for the
// end-to-end tests (tests/e2e/*.sh) — window size, selection, mode, undo steps, modified flag, the
// open modal and the window-coordinate centres of the widgets the tests click, validation count,
// frame and GPU times, split-view panes, the projected and world positions of every pool point.
// Widgets report themselves in one line (traceItem, traceModal); write() reads the rest from the
// editor. With the variable unset nothing is gathered or written.
#pragma once

#include <array>
#include <map>
#include <string>

namespace pw::ui {

class Editor;

class TestTrace {
public:
    TestTrace();   // on when PATCHWORK_EDITOR_TRACE names a file
    ~TestTrace();
    TestTrace(const TestTrace&) = delete;
    TestTrace& operator=(const TestTrace&) = delete;
    bool enabled() const { return !path_.empty(); }

    void beginFrame();                // forgets the last frame's items and modal
    void write(const Editor& editor);  // after the frame: the whole state, written atomically

private:
    friend void traceItem(const std::string& name);
    friend void traceModal(const char* name);
    static TestTrace* active_;
    std::string path_;
    std::map<std::string, std::array<float, 2>> items_;  // window-coordinate centres of named widgets
    std::string modal_;                                   // the modal (or palette) open this frame
};

// Widgets: the last ImGui item's centre under `name` (e2e tests click it); the modal open now.
void traceItem(const std::string& name);
void traceModal(const char* name);

}  // namespace pw::ui

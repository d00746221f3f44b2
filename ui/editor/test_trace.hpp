// The test trace (PATCHWORK_EDITOR_TRACE=file): after every frame the editor's state as JSON for the
// end-to-end tests (tests/e2e/*.sh) — window size, selection, mode, undo steps, modified flag, the
// open modal and the window-coordinate centres of the widgets the tests click, validation count,
// frame and GPU times, split-view panes, the projected and world positions of every pool point.
// Widgets report themselves through ui/platform/item_trace; write() reads the rest from the editor. With the variable unset nothing is
// gathered or written.
#pragma once

#include <string>

#include "ui/platform/item_trace.hpp"

namespace pw::ui {
inline namespace editor {

struct EditorSnapshot;

class TestTrace {
public:
    TestTrace();  // on when PATCHWORK_EDITOR_TRACE names a file
    ~TestTrace();
    TestTrace(const TestTrace&) = delete;
    TestTrace& operator=(const TestTrace&) = delete;
    bool enabled() const { return !path_.empty(); }

    void beginFrame();                         // forgets the last frame's items and modal
    void write(const EditorSnapshot& editor);  // after the frame: the whole state, written atomically

private:
    std::string path_;
    ItemTrace items_;  // what the widgets reported this frame
};

}  // namespace editor
}  // namespace pw::ui

// Widgets' hooks for the end-to-end tests, in the manner of Dear ImGui's test-engine hooks: a widget
// names itself after it is drawn (traceItem) and a modal says it is open (traceModal); the centres
// are gathered into the ItemTrace set by whoever records the frame (ui/editor/test_trace), and
// nothing is gathered while none is set.
#pragma once

#include <array>
#include <map>
#include <string>

namespace pw::ui {

struct ItemTrace {
    std::map<std::string, std::array<float, 2>> items;  // window-coordinate centres of named widgets
    std::string modal;                                  // the modal (or palette) open this frame
    void clear() {
        items.clear();
        modal.clear();
    }
};

// The trace the hooks fill from now on (nullptr: none).
void setItemTrace(ItemTrace* trace);
ItemTrace* itemTrace();

// Widgets: the last ImGui item's centre under `name` (e2e tests click it); the modal open now.
void traceItem(const std::string& name);
void traceModal(const char* name);

}  // namespace pw::ui

// The test-engine hooks of the editor's widgets, in the manner of Dear ImGui's own test engine
// (its ItemAdd / ItemInfo hooks inside every widget): the widgets of ui/platform/widgets.hpp report
// each item whose label ends in "##name" under `name` (its centre, window coordinates) and each
// modal that is open, into the ItemTrace set by whoever records the frame (ui/editor/test_trace).
// Panels name their widgets by their labels and never call the hooks; nothing is gathered while no
// trace is set.
#pragma once

#include <array>
#include <map>
#include <string>
#include <string_view>

namespace pw::ui {
inline namespace platform {

struct ItemTrace {
    std::map<std::string, std::array<float, 2>> items;  // window-coordinate centres of named widgets
    std::string modal;                                  // the modal (or palette) open this frame
    void clear() {
        items.clear();
        modal.clear();
    }
};

// The one switch: the trace the hooks fill from now on (nullptr: none).
void setItemTrace(ItemTrace* trace);
ItemTrace* itemTrace();

// The name a label gives its item in the trace: what follows "##" ("Domain view##teach.domain" →
// "teach.domain"), up to a "###" that keeps ImGui's id apart from it ("Tese##shaders.tab.x###tese":
// ImGui's id is "###tese" whatever x is); "" for a label without one.
std::string_view traceName(std::string_view label);

// The hooks the widgets call: the last ImGui item drawn with `label`, and a modal `label` open now.
void itemHook(std::string_view label);
void modalHook(std::string_view label);

}  // namespace platform
}  // namespace pw::ui

#include "ui/platform/item_trace.hpp"

#include <imgui.h>

namespace pw::ui {

namespace {
ItemTrace* active = nullptr;
}

void setItemTrace(ItemTrace* trace) { active = trace; }
ItemTrace* itemTrace() { return active; }

void traceItem(const std::string& name) {
    if (!active) return;
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    active->items[name] = {0.5f * (a.x + b.x), 0.5f * (a.y + b.y)};
}

void traceModal(const char* name) {
    if (active) active->modal = name;
}

}  // namespace pw::ui

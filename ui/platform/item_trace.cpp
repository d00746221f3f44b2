#include "ui/platform/item_trace.hpp"

#include <imgui.h>

namespace pw::ui {
inline namespace platform {

namespace {
ItemTrace* active = nullptr;
}

void setItemTrace(ItemTrace* trace) { active = trace; }
ItemTrace* itemTrace() { return active; }

std::string_view traceName(std::string_view label) {
    const size_t at = label.find("##");
    if (at == std::string_view::npos) return {};
    label.remove_prefix(at);
    while (!label.empty() && label.front() == '#') label.remove_prefix(1);
    return label.substr(0, label.find("###"));  // "Text##name###id": ImGui's id is "###id" alone
}

void itemHook(std::string_view label) {
    if (!active) return;
    const std::string_view name = traceName(label);
    if (name.empty()) return;
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    active->items[std::string(name)] = {0.5f * (a.x + b.x), 0.5f * (a.y + b.y)};
}

void modalHook(std::string_view label) {
    if (!active) return;
    const std::string_view name = traceName(label);
    active->modal = std::string(name.empty() ? label : name);
}

}  // namespace platform
}  // namespace pw::ui

// The hover tooltip every editor control carries, and row wrapping for the side panels' buttons.
#pragma once

#include <imgui.h>

namespace pw::ui {
inline namespace platform {

inline void tip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

// SameLine() when a button labelled `nextLabel` still fits on this line of the current window;
// otherwise nothing, so the button starts a new line. Rows of buttons then wrap in a narrow panel
// instead of running past its edge, where ImGui clips them.
inline void sameLineIfFits(const char* nextLabel) {
    const ImGuiStyle& s = ImGui::GetStyle();
    const float width = ImGui::CalcTextSize(nextLabel, nullptr, true).x + 2.0f * s.FramePadding.x;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + s.ItemSpacing.x + width <= right) ImGui::SameLine();
}

}  // namespace platform
}  // namespace pw::ui

// The hover tooltip every editor control carries.
#pragma once

#include <imgui.h>

namespace pw::ui {

inline void tip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

}  // namespace pw::ui

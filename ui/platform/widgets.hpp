// The editor's widgets: Dear ImGui's, each calling the test-engine hook after it is drawn
// (ui/platform/item_trace.hpp), as Dear ImGui's own widgets do when its test engine is compiled in
// (Debian's libimgui is built without it). A label "Text##name" shows "Text" and is traced as
// `name`. Same arguments and results as the ImGui functions of the same names.
#pragma once

#include <imgui.h>

namespace pw::ui {
inline namespace platform {
namespace widget {

bool Button(const char* label, const ImVec2& size = ImVec2(0, 0));
bool SmallButton(const char* label);
bool Checkbox(const char* label, bool* v);
bool RadioButton(const char* label, bool active);
bool Selectable(const char* label, bool selected = false, ImGuiSelectableFlags flags = 0, const ImVec2& size = ImVec2(0, 0));
bool Combo(const char* label, int* current, const char* const items[], int count, int popupMaxHeightInItems = -1);
bool BeginCombo(const char* label, const char* preview, ImGuiComboFlags flags = 0);  // traced while closed
void EndCombo(const char* label);  // traced again: ImGui's End() makes the combo box the last item again
bool SliderFloat(const char* label, float* v, float min, float max, const char* format = "%.3f", ImGuiSliderFlags flags = 0);
bool SliderScalar(const char* label, ImGuiDataType type, void* data, const void* min, const void* max, const char* format = nullptr,
                  ImGuiSliderFlags flags = 0);
bool SliderScalarN(const char* label, ImGuiDataType type, void* data, int components, const void* min, const void* max,
                   const char* format = nullptr, ImGuiSliderFlags flags = 0);
bool ColorEdit3(const char* label, float col[3], ImGuiColorEditFlags flags = 0);
bool DragScalarN(const char* label, ImGuiDataType type, void* data, int components, float speed, const void* min, const void* max,
                 const char* format, ImGuiSliderFlags flags = 0);
bool InputText(const char* label, char* buf, size_t size, ImGuiInputTextFlags flags = 0);
bool InputTextWithHint(const char* label, const char* hint, char* buf, size_t size, ImGuiInputTextFlags flags = 0,
                       ImGuiInputTextCallback callback = nullptr, void* userData = nullptr);
bool InputDouble(const char* label, double* v, double step, double stepFast, const char* format, ImGuiInputTextFlags flags);
bool InputScalarN(const char* label, ImGuiDataType type, void* data, int components, const void* step, const void* stepFast,
                  const char* format, ImGuiInputTextFlags flags);
bool CollapsingHeader(const char* label, ImGuiTreeNodeFlags flags = 0);
bool BeginTabItem(const char* label, bool* open = nullptr, ImGuiTabItemFlags flags = 0);
bool BeginMenu(const char* label, bool enabled = true);
bool MenuItem(const char* label, const char* shortcut = nullptr, bool selected = false, bool enabled = true);
bool BeginPopupModal(const char* name, bool* open = nullptr, ImGuiWindowFlags flags = 0);  // a modal that is open is traced
// A window that takes the keyboard as a modal does (the command palette): traced as the modal.
bool BeginModalWindow(const char* name, bool* open, ImGuiWindowFlags flags = 0);

}  // namespace widget
}  // namespace platform
}  // namespace pw::ui

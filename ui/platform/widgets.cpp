#include "ui/platform/widgets.hpp"

#include "ui/platform/item_trace.hpp"

namespace pw::ui {
inline namespace platform {
namespace widget {

namespace {
// The widget's result, after the hook saw the item it drew.
bool traced(const char* label, bool result) {
    itemHook(label);
    return result;
}
}  // namespace

bool Button(const char* label, const ImVec2& size) { return traced(label, ImGui::Button(label, size)); }
bool SmallButton(const char* label) { return traced(label, ImGui::SmallButton(label)); }
bool Checkbox(const char* label, bool* v) { return traced(label, ImGui::Checkbox(label, v)); }
bool RadioButton(const char* label, bool active) { return traced(label, ImGui::RadioButton(label, active)); }
bool Selectable(const char* label, bool selected, ImGuiSelectableFlags flags, const ImVec2& size) {
    return traced(label, ImGui::Selectable(label, selected, flags, size));
}
bool Combo(const char* label, int* current, const char* const items[], int count, int popupMaxHeightInItems) {
    return traced(label, ImGui::Combo(label, current, items, count, popupMaxHeightInItems));
}
bool BeginCombo(const char* label, const char* preview, ImGuiComboFlags flags) {
    const bool open = ImGui::BeginCombo(label, preview, flags);
    if (!open) itemHook(label);  // open: the last item is the popup's until EndCombo
    return open;
}
void EndCombo(const char* label) {
    ImGui::EndCombo();
    itemHook(label);
}
bool SliderFloat(const char* label, float* v, float min, float max, const char* format, ImGuiSliderFlags flags) {
    return traced(label, ImGui::SliderFloat(label, v, min, max, format, flags));
}
bool SliderScalar(const char* label, ImGuiDataType type, void* data, const void* min, const void* max, const char* format,
                  ImGuiSliderFlags flags) {
    return traced(label, ImGui::SliderScalar(label, type, data, min, max, format, flags));
}
bool SliderScalarN(const char* label, ImGuiDataType type, void* data, int components, const void* min, const void* max, const char* format,
                   ImGuiSliderFlags flags) {
    return traced(label, ImGui::SliderScalarN(label, type, data, components, min, max, format, flags));
}
bool ColorEdit3(const char* label, float col[3], ImGuiColorEditFlags flags) { return traced(label, ImGui::ColorEdit3(label, col, flags)); }
bool DragScalarN(const char* label, ImGuiDataType type, void* data, int components, float speed, const void* min, const void* max,
                 const char* format, ImGuiSliderFlags flags) {
    return traced(label, ImGui::DragScalarN(label, type, data, components, speed, min, max, format, flags));
}
bool InputText(const char* label, char* buf, size_t size, ImGuiInputTextFlags flags) {
    return traced(label, ImGui::InputText(label, buf, size, flags));
}
bool InputTextWithHint(const char* label, const char* hint, char* buf, size_t size, ImGuiInputTextFlags flags,
                       ImGuiInputTextCallback callback, void* userData) {
    return traced(label, ImGui::InputTextWithHint(label, hint, buf, size, flags, callback, userData));
}
bool InputDouble(const char* label, double* v, double step, double stepFast, const char* format, ImGuiInputTextFlags flags) {
    return traced(label, ImGui::InputDouble(label, v, step, stepFast, format, flags));
}
bool InputScalarN(const char* label, ImGuiDataType type, void* data, int components, const void* step, const void* stepFast,
                  const char* format, ImGuiInputTextFlags flags) {
    return traced(label, ImGui::InputScalarN(label, type, data, components, step, stepFast, format, flags));
}
bool CollapsingHeader(const char* label, ImGuiTreeNodeFlags flags) { return traced(label, ImGui::CollapsingHeader(label, flags)); }
bool BeginTabItem(const char* label, bool* open, ImGuiTabItemFlags flags) { return traced(label, ImGui::BeginTabItem(label, open, flags)); }
bool BeginMenu(const char* label, bool enabled) { return traced(label, ImGui::BeginMenu(label, enabled)); }
bool MenuItem(const char* label, const char* shortcut, bool selected, bool enabled) {
    return traced(label, ImGui::MenuItem(label, shortcut, selected, enabled));
}
bool BeginModalWindow(const char* name, bool* open, ImGuiWindowFlags flags) {
    modalHook(name);
    return ImGui::Begin(name, open, flags);
}
bool BeginPopupModal(const char* name, bool* open, ImGuiWindowFlags flags) {
    const bool shown = ImGui::BeginPopupModal(name, open, flags);
    if (shown) modalHook(name);
    return shown;
}

}  // namespace widget
}  // namespace platform
}  // namespace pw::ui

// Rows the settings panels share: an edited value committed as one undo step, and a combo over an
// enum's labels.
#pragma once

#include <imgui.h>

#include <span>

#include "ui/panel_context.hpp"

namespace pw::ui {

// After a slider, drag or field: redraws while it changes and commits one undo step `step` when
// the user lets go (or at once for a click that is already over).
inline void commitEdit(PanelContext& ctx, bool changed, const char* step) {
    if (changed) ctx.settingsChanged();
    if (ImGui::IsItemDeactivatedAfterEdit() || (changed && !ImGui::IsItemActive())) ctx.session().commit(step);
}

// A combo whose entries are the values of enum E in order; a pick is one undo step `step`.
template <class E>
void enumCombo(PanelContext& ctx, const char* label, E& value, std::span<const char* const> labels, const char* step) {
    int i = int(value);
    if (!ImGui::Combo(label, &i, labels.data(), int(labels.size()))) return;
    value = E(i);
    ctx.session().commit(step);
}

}  // namespace pw::ui

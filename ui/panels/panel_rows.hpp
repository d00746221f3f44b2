// Rows the settings panels share: a row of the settings table (core/model/settings.hpp) drawn as
// its widget.
#pragma once

#include <imgui.h>

#include <string_view>

#include "ui/panels/panel_context.hpp"

namespace pw::ui {
inline namespace panels {

// The setting `key` as its widget (slider, drag, colour, checkbox or combo) with its label and
// tooltip. It reads the document and writes it only through the `set` command: a live preview while
// a slider moves, one undo step when it is let go. Typed values are clamped to the row's range, so
// the panel cannot make a document its reader refuses. The widget is traced under `key` (the e2e
// tests click it). Returns true when the value changed this frame.
bool settingRow(PanelContext& ctx, std::string_view key);

}  // namespace panels
}  // namespace pw::ui

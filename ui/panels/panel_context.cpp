// The widgets every panel shares (ui/panels/panel_context.hpp): a button that runs a command.
#include "ui/panels/panel_context.hpp"

#include <imgui.h>

#include <cstdio>
#include <stdexcept>

#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

void commandButton(PanelContext& ctx, const char* label, const std::string& line, const char* trace) {
    const std::vector<std::string> words = splitCommandWords(line);
    const Command* c = ctx.commands().find(words.front());
    if (!c) throw std::logic_error("panel button '" + std::string(label) + "' names no command: " + line);
    ImGui::BeginDisabled(!ctx.commands().isEnabled(*c, ctx.session()));
    const bool pressed = widget::Button(trace ? (std::string(label) + "##" + trace).c_str() : label);
    ImGui::EndDisabled();
    tip(c->help.c_str());
    if (pressed) ctx.runCommand(words);
}

std::string commandWord(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

}  // namespace panels
}  // namespace pw::ui

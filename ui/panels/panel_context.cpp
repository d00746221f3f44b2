// The widgets every panel shares (ui/panels/panel_context.hpp): a button that runs a command, and a
// document operation as one undo step.
#include "ui/panels/panel_context.hpp"

#include <imgui.h>

#include <stdexcept>

#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/item_trace.hpp"

namespace pw::ui {

void commandButton(PanelContext& ctx, const char* label, const std::string& line, const char* trace) {
    const std::vector<std::string> words = splitCommandWords(line);
    const Command* c = ctx.commands().find(words.front());
    if (!c) throw std::logic_error("panel button '" + std::string(label) + "' names no command: " + line);
    ImGui::BeginDisabled(!ctx.commands().isEnabled(*c, ctx.session()));
    const bool pressed = ImGui::Button(label);
    ImGui::EndDisabled();
    if (trace) traceItem(trace);
    tip(c->help.c_str());
    if (pressed) ctx.runCommand(words);
}

void patchOp(PanelContext& ctx, const std::string& label, const std::function<void(Document&)>& op, bool topology) {
    try {
        ctx.session().apply(label, op, topology);
    } catch (const std::exception& e) {
        ctx.showError(label + " failed: " + e.what());
        return;
    }
    ctx.documentChanged(topology);
}

}  // namespace pw::ui

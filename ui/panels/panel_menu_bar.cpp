// The main menu bar (ui/panels/command_panels.hpp): generated from the command table, with each command's
// first key, check marks, Undo/Redo labels, the recent files after Open, and the document's title
// and length unit.
#include <imgui.h>

#include <string>

#include "ui/panels/command_panels.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

void drawMenuBar(PanelContext& ctx, CommandPalette& palette, const std::vector<std::string>& recent) {
    if (!ImGui::BeginMainMenuBar()) return;
    for (const std::string& menu : ctx.commands().menus()) {
        const bool open = widget::BeginMenu((menu + "##menubar." + menu).c_str());
        if (!open) continue;
        for (const Command& c : ctx.commands().commands()) {
            if (c.menu != menu) continue;
            const bool enabled = ctx.commands().isEnabled(c, ctx.session());
            for (const CommandEntry& e : entriesOf(c)) {
                std::string label = e.label;
                if (c.name == "undo" || c.name == "redo") {
                    const std::string& what = c.name == "undo" ? ctx.session().history().undoLabel() : ctx.session().history().redoLabel();
                    if (!what.empty()) label += " " + what;
                }
                const std::string first = e.shortcut.substr(0, e.shortcut.find(" / "));
                const bool checked = c.checked && c.checked(ctx.session(), ctx.host());
                const std::string traced =
                    label + (e.needsArguments() ? "..." : "") + "##menu." + c.name + (e.args.empty() ? "" : "." + e.args);
                if (widget::MenuItem(traced.c_str(), first.empty() ? nullptr : first.c_str(), checked, enabled))
                    e.needsArguments() ? palette.complete(ctx, c) : ctx.runCommand(e.words());
                tip(c.help.c_str());
            }
            if (c.name == "open") {  // the recent files follow Open
                if (ImGui::BeginMenu("Open Recent", !recent.empty())) {
                    for (const std::string& r : recent)
                        if (ImGui::MenuItem(r.c_str())) ctx.runCommand({"open", r});
                    ImGui::EndMenu();
                }
                tip("Recently opened or saved files");
            }
        }
        ImGui::EndMenu();
    }
    ImGui::TextDisabled("%s%s  [%s]", ctx.session().title().c_str(), ctx.session().isModified() ? "  (modified)" : "",
                        std::string(lengthUnitName(ctx.session().doc.unit)).c_str());
    ImGui::EndMainMenuBar();
}

}  // namespace panels
}  // namespace pw::ui

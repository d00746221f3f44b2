// The F1 window (ui/panels/command_panels.hpp): every command of the table with its keys, its script form
// and what it does, then the mouse and modal keys, which are not commands.
#include <imgui.h>

#include <algorithm>

#include "ui/panels/command_panels.hpp"

namespace pw::ui {
inline namespace panels {

const std::vector<KeyHelp>& modalKeys() {
    static const std::vector<KeyHelp> keys{
        {"Middle drag", "Orbit the view"},
        {"Shift + middle drag", "Pan the view"},
        {"Wheel", "Zoom; while moving with soft selection on (O): the soft radius"},
        {"Alt + left drag", "Orbit (laptops)"},
        {"Left click", "Select a control point; on the surface: select the patch (nearest edge highlighted)"},
        {"Shift + left click", "Add / remove a point from the selection"},
        {"Left drag on empty space", "Box select (Shift adds)"},
        {"Left drag on a point", "Move the selected points in the view plane; joins are held"},
        {"G", "Grab the selected points (move the mouse, click or Enter confirms)"},
        {"R", "Rotate the selected points about the pivot (move the mouse, click or Enter confirms); joins are held"},
        {"S", "Scale the selected points about the pivot (move the mouse, click or Enter confirms); joins are held"},
        {"X / Y / Z (while moving)", "Constrain to that axis (again: free)"},
        {"Shift + X / Y / Z (while moving)", "Move in the plane across that axis"},
        {"U / V / N (while moving)", "Slide each point along its own control polygon in u or v, or along the surface normal (again: free)"},
        {"0-9 . - Backspace (while grabbing)", "Type the distance (\"G X 2 Enter\")"},
        {"Ctrl (while moving)", "Snap to the grid"},
        {"Esc / right click (while moving)", "Cancel the move and restore"},
        {"Esc", "Clear the selection"},
    };
    return keys;
}

void drawHelp(PanelContext& ctx, bool& open) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(1100.0f * ctx.uiScale(), io.DisplaySize.x * 0.9f), io.DisplaySize.y * 0.8f),
                             ImGuiCond_Appearing);
    ImGui::SetNextWindowBgAlpha(0.92f);
    if (ImGui::Begin("Keys and commands (F1)", &open)) {
        ImGui::TextDisabled("Every command runs from its menu, its keys, the palette (F3) and `patchwork edit -c '...'`.");
        if (ImGui::BeginTable(
                "keys", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp)) {
            ImGui::TableSetupColumn("Keys", ImGuiTableColumnFlags_WidthStretch, 0.2f);
            ImGui::TableSetupColumn("Command", ImGuiTableColumnFlags_WidthStretch, 0.3f);
            ImGui::TableSetupColumn("What it does", ImGuiTableColumnFlags_WidthStretch, 0.5f);
            ImGui::TableHeadersRow();
            for (const Command& c : ctx.commands().commands())
                for (const CommandEntry& e : entriesOf(c)) {
                    ImGui::TableNextRow();
                    ImGui::TableNextColumn();
                    ImGui::TextUnformatted(e.shortcut.c_str());
                    ImGui::TableNextColumn();
                    const std::string script = c.name + " " + (e.args.empty() ? commandUsage(c) : e.args);
                    ImGui::TextWrapped("%s", script.c_str());
                    ImGui::TableNextColumn();
                    ImGui::TextWrapped("%s: %s", e.label.c_str(), c.help.c_str());
                }
            for (const KeyHelp& k : modalKeys()) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(k.keys);
                ImGui::TableNextColumn();
                ImGui::TableNextColumn();
                ImGui::TextWrapped("%s", k.what);
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

}  // namespace panels
}  // namespace pw::ui

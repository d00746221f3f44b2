// The F3 command palette (ui/panels/command_panels.hpp): type to search the command table, arrows move,
// Enter runs the highlighted entry or the typed line with its arguments.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "ui/panels/command_panels.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

namespace {

// The palette's text as words; an unclosed quote while typing is no error yet.
std::vector<std::string> typedWords(const std::string& text) {
    try {
        return splitCommandWords(text);
    } catch (const std::exception&) {
        return {};
    }
}

std::string lower(std::string s) {
    for (char& ch : s) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return s;
}

}  // namespace

void CommandPalette::toggle() {
    open = !open;
    query_[0] = 0;
    cursor_ = 0;
}

void CommandPalette::complete(PanelContext& ctx, const Command& c) {
    open = true;
    std::snprintf(query_, sizeof query_, "%s ", c.name.c_str());
    cursor_ = 0;
    refocus_ = true;
    cursorToEnd_ = true;
    ctx.host().status("Type the arguments: " + c.name + " " + commandUsage(c));
}

void CommandPalette::draw(PanelContext& ctx) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, ImGui::GetFrameHeight() * 3.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(std::min(640.0f * ctx.uiScale(), io.DisplaySize.x * 0.8f), 0.0f));
    if (!widget::BeginModalWindow("Command palette (F3)##palette", &open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::End();
        return;
    }
    if (ImGui::IsWindowAppearing() || refocus_) ImGui::SetKeyboardFocusHere();
    refocus_ = false;
    ImGui::SetNextItemWidth(-1.0f);
    // After the field was filled by completeInPalette, the text cursor goes to its end.
    auto toEnd = [](ImGuiInputTextCallbackData* data) {
        bool& pending = *static_cast<bool*>(data->UserData);
        if (pending) data->CursorPos = data->SelectionStart = data->SelectionEnd = data->BufTextLen;
        pending = false;
        return 0;
    };
    const bool enter =
        widget::InputTextWithHint("##palette.query", "type a command (e.g. 'save', 'move 1 0 0')", query_, sizeof query_,
                                  ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackAlways, toEnd, &cursorToEnd_);
    if (!ImGui::IsItemActive() && !enter && ImGui::IsWindowFocused()) ImGui::SetKeyboardFocusHere(-1);
    // Entries that contain every typed word (case-insensitive): those matching in the label or
    // the command's name first, then those matching only in the help text.
    const std::vector<std::string> typed = typedWords(lower(query_));
    auto containsAll = [&](const std::string& hay, const Command& c) {
        for (size_t i = 0; i < typed.size(); ++i)
            if (hay.find(typed[i]) == std::string::npos && !(i > 0 && typed[0] == c.name)) return false;  // "move 1 0 0"
        return true;
    };
    std::vector<CommandEntry> matches, helpMatches;
    for (const Command& c : ctx.commands().commands())
        for (const CommandEntry& e : entriesOf(c)) {
            if (containsAll(lower(e.label + " " + c.name + " " + e.args), c))
                matches.push_back(e);
            else if (containsAll(lower(e.label + " " + c.name + " " + e.args + " " + c.help), c))
                helpMatches.push_back(e);
        }
    matches.insert(matches.end(), helpMatches.begin(), helpMatches.end());
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_DownArrow))) ++cursor_;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_UpArrow))) --cursor_;
    cursor_ = std::clamp(cursor_, 0, std::max(int(matches.size()) - 1, 0));
    int clicked = -1;
    ImGui::BeginChild("matches",
                      ImVec2(0, std::min(12.0f, float(std::max<size_t>(matches.size(), 1))) * ImGui::GetTextLineHeightWithSpacing()));
    for (size_t i = 0; i < matches.size(); ++i) {
        const CommandEntry& e = matches[i];
        const bool enabled = ctx.commands().isEnabled(*e.command, ctx.session()) && (!e.command->windowOnly || ctx.host().hasWindow());
        std::string row = e.label + "   (" + e.command->name + (e.args.empty() ? "" : " " + e.args) + ")";
        ImGui::BeginDisabled(!enabled);
        if (ImGui::Selectable(row.c_str(), int(i) == cursor_)) clicked = int(i);
        ImGui::EndDisabled();
        if (int(i) == cursor_) ImGui::SetScrollHereY();
        if (!e.shortcut.empty()) {
            ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize(e.shortcut.c_str()).x);
            ImGui::TextDisabled("%s", e.shortcut.c_str());
        }
        tip(e.command->help.c_str());
    }
    ImGui::EndChild();
    ImGui::End();
    if (ctx.keyPressed(GLFW_KEY_ESCAPE, 0)) open = false;
    if (!enter && clicked < 0) return;
    // Enter runs the highlighted entry, or what was typed when it names a command with arguments.
    std::vector<std::string> words;
    const std::vector<std::string> raw = typedWords(query_);
    if (raw.size() > 1 && ctx.commands().find(raw.front()))
        words = raw;
    else if (clicked >= 0 || !matches.empty())
        words = matches[size_t(clicked >= 0 ? clicked : cursor_)].words();
    if (words.empty()) return;
    const Command* c = ctx.commands().find(words.front());
    if (words.size() == 1 && c && CommandEntry{c, "", "", ""}.needsArguments()) return complete(ctx, *c);
    open = false;
    ctx.runCommand(words);
}

}  // namespace panels
}  // namespace pw::ui

// The editor and the command table (core/command_table.hpp): what the window does for commands
// (CommandHost), and what it generates from the table: the menu bar, the keyboard shortcuts, the F1
// help, the F3 command palette and panel buttons. One entry per binding of a command.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <ctime>

#include <imgui.h>

#include "core/document_io.hpp"
#include "ui/editor.hpp"
#include "ui/imgui_tip.hpp"
#include "ui/shortcuts.hpp"

namespace pw::ui {

namespace {

// Mouse and modal keys: not commands, listed in the F1 help after them.
struct KeyHelp {
    const char* keys;
    const char* what;
};
const KeyHelp kMouseAndModal[] = {
    {"Middle drag", "Orbit the view"},
    {"Shift + middle drag", "Pan the view"},
    {"Wheel", "Zoom"},
    {"Alt + left drag", "Orbit (laptops)"},
    {"Left click", "Select a control point; on the surface: select the patch (nearest edge highlighted)"},
    {"Shift + left click", "Add / remove a point from the selection"},
    {"Left drag on empty space", "Box select (Shift adds)"},
    {"Left drag on a point", "Move the selected points in the view plane; joins are held"},
    {"G", "Grab the selected points (move the mouse, click or Enter confirms)"},
    {"X / Y / Z (while moving)", "Constrain to that axis (again: free)"},
    {"Ctrl (while moving)", "Snap to the grid"},
    {"Esc / right click (while moving)", "Cancel the move and restore"},
    {"Esc", "Clear the selection"},
};

// One menu / palette entry: a command with a binding's arguments.
struct Entry {
    const Command* command;
    std::string label, args, shortcut;  // shortcut: every key of the binding, " / "-joined
    // A command whose arguments are required and not given by the binding: menus and the palette
    // put "name " into the palette's field to be completed instead of running it.
    bool needsArguments() const { return args.empty() && !command->usage.empty() && command->usage[0] != '['; }
    std::vector<std::string> words() const {
        std::vector<std::string> w = splitCommandWords(args);
        w.insert(w.begin(), command->name);
        return w;
    }
};

std::vector<Entry> entriesOf(const Command& c) {
    std::vector<Entry> out;
    if (c.bindings.empty()) out.push_back({&c, c.label, "", ""});
    for (const CommandBinding& b : c.bindings) {
        std::string keys;
        for (const std::string& k : b.shortcuts) keys += (keys.empty() ? "" : " / ") + k;
        out.push_back({&c, b.label.empty() ? c.label : b.label, b.args, keys});
    }
    return out;
}

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

void Editor::bindShortcuts() {
    keyBindings_.clear();
    for (const Command& c : commands_.commands())
        for (const CommandBinding& b : c.bindings)
            for (const std::string& k : b.shortcuts) {
                const auto chord = parseShortcut(k);
                if (!chord) throw std::logic_error("command '" + c.name + "': unknown shortcut '" + k + "'");
                keyBindings_.push_back({chord->key, chord->mods, c.name + (b.args.empty() ? "" : " " + b.args)});
            }
}

void Editor::runShortcuts() {
    for (const KeyBinding& k : keyBindings_)
        if (keyPressed(k.key, k.mods)) {
            const std::vector<std::string> words = splitCommandWords(k.line);
            const Command* c = commands_.find(words.front());
            if (c && commands_.isEnabled(*c, session_)) runCommand(words);
        }
}

// --- CommandHost: what the commands ask of the window ---

bool Editor::confirmDiscard(const std::vector<std::string>& words) {
    pendingCommand_ = words;
    openUnsavedPrompt_ = true;
    wake();
    return false;
}

void Editor::write(const Document& doc, const std::string& path) { saveDocument(doc, path, exportOptions_); }

void Editor::saved(const std::string& path) {
    addRecent(path);
    if (!isModified()) autosaver_.discard();  // the file on disk holds everything now
    glfwSetWindowTitle(window_, ("Patchwork — " + session_.title()).c_str());
}

void Editor::fileDialog(FileDialogKind kind) {
    const std::string name = doc_.name.empty() ? "untitled" : doc_.name;
    fileName_[0] = 0;
    switch (kind) {
        case FileDialogKind::Open: fileMode_ = FileDialogMode::Open; break;
        case FileDialogKind::Import: fileMode_ = FileDialogMode::Import; break;
        case FileDialogKind::SaveAs:
            fileMode_ = FileDialogMode::SaveAs;
            std::snprintf(fileName_, sizeof fileName_, "%s.patchwork", name.c_str());
            break;
        case FileDialogKind::ExportGltf:
            fileMode_ = FileDialogMode::ExportGltf;
            std::snprintf(fileName_, sizeof fileName_, "%s.glb", name.c_str());
            break;
        case FileDialogKind::Screenshot:
            fileMode_ = FileDialogMode::Screenshot;
            std::snprintf(fileName_, sizeof fileName_, "screenshot.png");
            break;
    }
    wake();
}

void Editor::toggle(WindowToggle which) {
    switch (which) {
        case WindowToggle::Help: showHelp_ = !showHelp_; break;
        case WindowToggle::Palette:
            showPalette_ = !showPalette_;
            paletteQuery_[0] = 0;
            paletteCursor_ = 0;
            break;
        case WindowToggle::Presentation: setPresentation(!presentation_); break;
        case WindowToggle::DomainView: showDomain_ = !showDomain_; break;
        case WindowToggle::ShaderPanel: showShaders_ = !showShaders_; break;
        case WindowToggle::GroundGrid: showGround_ = !showGround_; break;
    }
    wake();
}

bool Editor::toggled(WindowToggle which) const {
    switch (which) {
        case WindowToggle::Help: return showHelp_;
        case WindowToggle::Palette: return showPalette_;
        case WindowToggle::Presentation: return presentation_;
        case WindowToggle::DomainView: return showDomain_;
        case WindowToggle::ShaderPanel: return showShaders_;
        case WindowToggle::GroundGrid: return showGround_;
    }
    return false;
}

void Editor::screenshot(const std::string& path) {
    std::string file = path;
    if (file.empty()) {
        char name[64];
        const std::time_t t = std::time(nullptr);
        std::strftime(name, sizeof name, "patchwork-%Y%m%d-%H%M%S.png", std::localtime(&t));
        file = name;
    }
    screenshotRequested_ = true;
    screenshotPath_ = file;
    wake();
}

bool Editor::frame(const Bounds& box) {
    frameBox(box);
    return true;
}

void Editor::status(const std::string& message) {
    status_ = message;
    statusTime_ = std::chrono::steady_clock::now();
}

void Editor::commandButton(const char* label, const std::string& line, const char* trace) {
    const std::vector<std::string> words = splitCommandWords(line);
    const Command* c = commands_.find(words.front());
    if (!c) throw std::logic_error("panel button '" + std::string(label) + "' names no command: " + line);
    ImGui::BeginDisabled(!commands_.isEnabled(*c, session_));
    const bool pressed = ImGui::Button(label);
    ImGui::EndDisabled();
    if (trace) traceItem(trace);
    tip(c->help.c_str());
    if (pressed) runCommand(words);
}

void Editor::completeInPalette(const Command& c) {
    showPalette_ = true;
    std::snprintf(paletteQuery_, sizeof paletteQuery_, "%s ", c.name.c_str());
    paletteCursor_ = 0;
    paletteRefocus_ = true;
    paletteCursorToEnd_ = true;
    status("Type the arguments: " + c.name + " " + c.usage);
}

void Editor::drawMenuBar() {
    if (!ImGui::BeginMainMenuBar()) return;
    for (const std::string& menu : commands_.menus()) {
        if (!ImGui::BeginMenu(menu.c_str())) continue;
        for (const Command& c : commands_.commands()) {
            if (c.menu != menu) continue;
            const bool enabled = commands_.isEnabled(c, session_);
            for (const Entry& e : entriesOf(c)) {
                std::string label = e.label;
                if (c.name == "undo" || c.name == "redo") {
                    const std::string& what = c.name == "undo" ? session_.history().undoLabel() : session_.history().redoLabel();
                    if (!what.empty()) label += " " + what;
                }
                const std::string first = e.shortcut.substr(0, e.shortcut.find(" / "));
                const bool checked = c.checked && c.checked(session_, *this);
                if (ImGui::MenuItem((label + (e.needsArguments() ? "..." : "")).c_str(), first.empty() ? nullptr : first.c_str(), checked, enabled))
                    e.needsArguments() ? completeInPalette(c) : runCommand(e.words());
                traceItem("menu." + c.name + (e.args.empty() ? "" : "." + e.args));
                tip(c.help.c_str());
            }
            if (c.name == "open") {  // the recent files follow Open
                if (ImGui::BeginMenu("Open Recent", !recent_.empty())) {
                    for (const std::string& r : recent_)
                        if (ImGui::MenuItem(r.c_str())) runCommand({"open", r});
                    ImGui::EndMenu();
                }
                tip("Recently opened or saved files");
            }
        }
        ImGui::EndMenu();
    }
    ImGui::TextDisabled("%s%s", session_.title().c_str(), isModified() ? "  (modified)" : "");
    ImGui::EndMainMenuBar();
}

void Editor::drawHelp() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(1100.0f * uiScale_, io.DisplaySize.x * 0.9f), io.DisplaySize.y * 0.8f), ImGuiCond_Appearing);
    ImGui::SetNextWindowBgAlpha(0.92f);
    if (ImGui::Begin("Keys and commands (F1)", &showHelp_)) {
        ImGui::TextDisabled("Every command runs from its menu, its keys, the palette (F3) and `patchwork edit -c '...'`.");
        if (ImGui::BeginTable("keys", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                                             ImGuiTableFlags_SizingStretchProp)) {
            ImGui::TableSetupColumn("Keys", ImGuiTableColumnFlags_WidthStretch, 0.2f);
            ImGui::TableSetupColumn("Command", ImGuiTableColumnFlags_WidthStretch, 0.3f);
            ImGui::TableSetupColumn("What it does", ImGuiTableColumnFlags_WidthStretch, 0.5f);
            ImGui::TableHeadersRow();
            for (const Command& c : commands_.commands())
                for (const Entry& e : entriesOf(c)) {
                    ImGui::TableNextRow();
                    ImGui::TableNextColumn();
                    ImGui::TextUnformatted(e.shortcut.c_str());
                    ImGui::TableNextColumn();
                    const std::string script = c.name + " " + (e.args.empty() ? c.usage : e.args);
                    ImGui::TextWrapped("%s", script.c_str());
                    ImGui::TableNextColumn();
                    ImGui::TextWrapped("%s: %s", e.label.c_str(), c.help.c_str());
                }
            for (const KeyHelp& k : kMouseAndModal) {
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

void Editor::drawPalette() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, ImGui::GetFrameHeight() * 3.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(std::min(640.0f * uiScale_, io.DisplaySize.x * 0.8f), 0.0f));
    openModal_ = "palette";
    if (!ImGui::Begin("Command palette (F3)", &showPalette_, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::End();
        return;
    }
    if (ImGui::IsWindowAppearing() || paletteRefocus_) ImGui::SetKeyboardFocusHere();
    paletteRefocus_ = false;
    ImGui::SetNextItemWidth(-1.0f);
    // After the field was filled by completeInPalette, the text cursor goes to its end.
    auto toEnd = [](ImGuiInputTextCallbackData* data) {
        bool& pending = *static_cast<bool*>(data->UserData);
        if (pending) data->CursorPos = data->SelectionStart = data->SelectionEnd = data->BufTextLen;
        pending = false;
        return 0;
    };
    const bool enter = ImGui::InputTextWithHint("##query", "type a command (e.g. 'save', 'move 1 0 0')", paletteQuery_, sizeof paletteQuery_,
                                                ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackAlways, toEnd,
                                                &paletteCursorToEnd_);
    traceItem("palette.query");
    if (!ImGui::IsItemActive() && !enter && ImGui::IsWindowFocused()) ImGui::SetKeyboardFocusHere(-1);
    // Entries that contain every typed word (case-insensitive): those matching in the label or
    // the command's name first, then those matching only in the help text.
    const std::vector<std::string> typed = typedWords(lower(paletteQuery_));
    auto containsAll = [&](const std::string& hay, const Command& c) {
        for (size_t i = 0; i < typed.size(); ++i)
            if (hay.find(typed[i]) == std::string::npos && !(i > 0 && typed[0] == c.name)) return false;  // "move 1 0 0"
        return true;
    };
    std::vector<Entry> matches, helpMatches;
    for (const Command& c : commands_.commands())
        for (const Entry& e : entriesOf(c)) {
            if (containsAll(lower(e.label + " " + c.name + " " + e.args), c)) matches.push_back(e);
            else if (containsAll(lower(e.label + " " + c.name + " " + e.args + " " + c.help), c)) helpMatches.push_back(e);
        }
    matches.insert(matches.end(), helpMatches.begin(), helpMatches.end());
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_DownArrow))) ++paletteCursor_;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_UpArrow))) --paletteCursor_;
    paletteCursor_ = std::clamp(paletteCursor_, 0, std::max(int(matches.size()) - 1, 0));
    int clicked = -1;
    ImGui::BeginChild("matches", ImVec2(0, std::min(12.0f, float(std::max<size_t>(matches.size(), 1))) * ImGui::GetTextLineHeightWithSpacing()));
    for (size_t i = 0; i < matches.size(); ++i) {
        const Entry& e = matches[i];
        const bool enabled = commands_.isEnabled(*e.command, session_) && (!e.command->windowOnly || hasWindow());
        std::string row = e.label + "   (" + e.command->name + (e.args.empty() ? "" : " " + e.args) + ")";
        ImGui::BeginDisabled(!enabled);
        if (ImGui::Selectable(row.c_str(), int(i) == paletteCursor_)) clicked = int(i);
        ImGui::EndDisabled();
        if (int(i) == paletteCursor_) ImGui::SetScrollHereY();
        if (!e.shortcut.empty()) {
            ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize(e.shortcut.c_str()).x);
            ImGui::TextDisabled("%s", e.shortcut.c_str());
        }
        tip(e.command->help.c_str());
    }
    ImGui::EndChild();
    ImGui::End();
    if (keyPressed(GLFW_KEY_ESCAPE, 0)) showPalette_ = false;
    if (!enter && clicked < 0) return;
    // Enter runs the highlighted entry, or what was typed when it names a command with arguments.
    std::vector<std::string> words;
    const std::vector<std::string> raw = typedWords(paletteQuery_);
    if (raw.size() > 1 && commands_.find(raw.front()))
        words = raw;
    else if (clicked >= 0 || !matches.empty())
        words = matches[size_t(clicked >= 0 ? clicked : paletteCursor_)].words();
    if (words.empty()) return;
    const Command* c = commands_.find(words.front());
    if (words.size() == 1 && c && Entry{c, "", "", ""}.needsArguments()) return completeInPalette(*c);
    showPalette_ = false;
    runCommand(words);
}

}  // namespace pw::ui

// What the editor generates from the command table (core/commands/command_table.hpp): the menu bar
// (panel_menu_bar.cpp), the F1 list of commands and keys (panel_help.cpp) and the F3 command
// palette (panel_palette.cpp: type to search, arrows, Enter runs; a command that needs arguments
// is completed there). One entry per binding of a command.
#pragma once

#include <string>
#include <vector>

#include "core/commands/command_table.hpp"
#include "ui/panels/panel_context.hpp"

namespace pw::ui {
inline namespace panels {

// One menu / palette entry: a command with a binding's arguments.
struct CommandEntry {
    const Command* command;
    std::string label, args, shortcut;  // shortcut: every key of the binding, " / "-joined
    // A command whose arguments are required and not given by the binding: menus and the palette
    // put "name " into the palette's field to be completed instead of running it.
    bool needsArguments() const { return args.empty() && commandNeedsWords(*command); }
    std::vector<std::string> words() const {
        std::vector<std::string> w = splitCommandWords(args);
        w.insert(w.begin(), command->name);
        return w;
    }
};

inline std::vector<CommandEntry> entriesOf(const Command& c) {
    std::vector<CommandEntry> out;
    if (c.bindings.empty()) out.push_back({&c, c.label, "", ""});
    for (const CommandBinding& b : c.bindings) {
        std::string keys;
        for (const std::string& k : b.shortcuts) keys += (keys.empty() ? "" : " / ") + k;
        out.push_back({&c, b.label.empty() ? c.label : b.label, b.args, keys});
    }
    return out;
}

// Mouse and modal keys (G, R, S and what works while moving): not commands; the F1 window lists
// them after the command table's keys.
struct KeyHelp {
    const char* keys;
    const char* what;
};
const std::vector<KeyHelp>& modalKeys();

class CommandPalette {
public:
    bool open = false;
    void toggle();
    // Opens the palette with "name " in its field for the arguments to be typed.
    void complete(PanelContext& ctx, const Command& c);
    void draw(PanelContext& ctx);

private:
    char query_[256] = {};
    int cursor_ = 0;
    bool refocus_ = false;      // give the field the keyboard next frame
    bool cursorToEnd_ = false;  // and put its text cursor after the text
};

// The main menu bar: a menu per table menu, "Open Recent" after Open, the title and modified flag.
void drawMenuBar(PanelContext& ctx, CommandPalette& palette, const std::vector<std::string>& recent);
// The F1 window: every command with its keys and script form, then the mouse and modal keys.
void drawHelp(PanelContext& ctx, bool& open);

}  // namespace panels
}  // namespace pw::ui

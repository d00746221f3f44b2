// Keyboard shortcuts of the command table ("Ctrl+Shift+Z", "Numpad1", "F12", "Shift+/", "Delete")
// as GLFW key codes and modifier bits.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/commands/command_table.hpp"

namespace pw::ui {
inline namespace platform {

struct KeyChord {
    int key = 0;   // GLFW_KEY_*
    int mods = 0;  // GLFW_MOD_* bits
};

// nullopt for a name this table does not know (a test checks every shortcut of the table parses).
std::optional<KeyChord> parseShortcut(std::string_view text);

// A key of the table bound to the command line it runs ("view front").
struct KeyBinding {
    KeyChord chord;
    std::string line;
};
// Every shortcut of every binding of `table`, in table order: the editor's keys come from here
// alone. Throws std::logic_error naming the command for a shortcut parseShortcut does not know.
std::vector<KeyBinding> keyBindingsOf(const CommandTable& table);

}  // namespace platform
}  // namespace pw::ui

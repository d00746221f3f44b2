// Keyboard shortcuts of the command table ("Ctrl+Shift+Z", "Numpad1", "F12", "Shift+/", "Delete")
// as GLFW key codes and modifier bits.
#pragma once

#include <optional>
#include <string_view>

namespace pw::ui {

struct KeyChord {
    int key = 0;   // GLFW_KEY_*
    int mods = 0;  // GLFW_MOD_* bits
};

// nullopt for a name this table does not know (a test checks every shortcut of the table parses).
std::optional<KeyChord> parseShortcut(std::string_view text);

}  // namespace pw::ui

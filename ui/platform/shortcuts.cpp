#include "ui/platform/shortcuts.hpp"

#include <GLFW/glfw3.h>

#include <charconv>
#include <stdexcept>

namespace pw::ui {
inline namespace platform {

std::optional<KeyChord> parseShortcut(std::string_view text) {
    KeyChord k;
    // Modifiers first ("Ctrl+", "Shift+", "Alt+"); the rest names the key ("+" itself is no key here).
    for (;;) {
        const size_t plus = text.find('+');
        if (plus == std::string_view::npos || plus + 1 == text.size()) break;
        const std::string_view mod = text.substr(0, plus);
        if (mod == "Ctrl")
            k.mods |= GLFW_MOD_CONTROL;
        else if (mod == "Shift")
            k.mods |= GLFW_MOD_SHIFT;
        else if (mod == "Alt")
            k.mods |= GLFW_MOD_ALT;
        else
            return std::nullopt;
        text.remove_prefix(plus + 1);
    }
    if (text.size() == 1) {
        const char c = text[0];
        if (c >= 'A' && c <= 'Z')
            k.key = GLFW_KEY_A + (c - 'A');
        else if (c >= '0' && c <= '9')
            k.key = GLFW_KEY_0 + (c - '0');
        else if (c == '/')
            k.key = GLFW_KEY_SLASH;
        else if (c == '=')
            k.key = GLFW_KEY_EQUAL;
        else if (c == '-')
            k.key = GLFW_KEY_MINUS;
        else
            return std::nullopt;
        return k;
    }
    if (text.size() >= 2 && text[0] == 'F') {
        int n = 0;
        const auto [end, ec] = std::from_chars(text.data() + 1, text.data() + text.size(), n);
        if (ec != std::errc() || end != text.data() + text.size() || n < 1 || n > 25) return std::nullopt;
        k.key = GLFW_KEY_F1 + n - 1;
        return k;
    }
    if (text.size() == 7 && text.substr(0, 6) == "Numpad" && text[6] >= '0' && text[6] <= '9') {
        k.key = GLFW_KEY_KP_0 + (text[6] - '0');
        return k;
    }
    if (text == "Delete")
        k.key = GLFW_KEY_DELETE;
    else if (text == "Enter")
        k.key = GLFW_KEY_ENTER;
    else if (text == "Escape")
        k.key = GLFW_KEY_ESCAPE;
    else if (text == "Tab")
        k.key = GLFW_KEY_TAB;
    else
        return std::nullopt;
    return k;
}

std::vector<KeyBinding> keyBindingsOf(const CommandTable& table) {
    std::vector<KeyBinding> out;
    for (const Command& c : table.commands())
        for (const CommandBinding& b : c.bindings)
            for (const std::string& k : b.shortcuts) {
                const auto chord = parseShortcut(k);
                if (!chord) throw std::logic_error("command '" + c.name + "': unknown shortcut '" + k + "'");
                out.push_back({*chord, c.name + (b.args.empty() ? "" : " " + b.args)});
            }
    return out;
}

}  // namespace platform
}  // namespace pw::ui

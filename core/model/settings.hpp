// The document's settings as rows, one per setting: its key (in files and in the `set` command),
// label, tooltip, unit, kind, range and choices, and how it is read from and written into a
// Document. The Tessellation and Display panels draw their widgets from these rows, the `set`
// command checks its values against them, and the .patchwork reader takes its ranges from them, so
// a range is written once (issue 38: a level typed as -5 in the panel was saved and then refused on
// reopening).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace model {

enum class SettingKind : uint8_t {
    Number,  // `count` numbers within [min, max] (whole numbers when `integer`)
    Switch,  // on or off
    Choice,  // one of `choices` (an enum, by its index)
};

enum class SettingWidget : uint8_t { Slider, LogSlider, Drag, Colour };

struct Setting {
    std::string_view key;      // "tess.maxLevel": the file's object and field, the `set` command's name
    std::string_view label;    // the panel's label
    std::string_view tooltip;  // the panel's tooltip and the `set` command's help
    std::string_view unit;     // "", "px", "model units"
    SettingKind kind = SettingKind::Number;
    int count = 1;                            // numbers in the row
    double min = 0.0, max = 0.0;              // the values accepted anywhere (panel, command, file)
    double sliderMin = 0.0, sliderMax = 0.0;  // the panel's slider when narrower (both 0: min, max)
    bool integer = false;
    SettingWidget widget = SettingWidget::Slider;
    std::string_view format = "%.1f";            // the panel's number format
    std::vector<std::string_view> choices;       // Choice: names in enum order (files, commands)
    std::vector<std::string_view> choiceLabels;  // Choice: what the panel shows
    // Choice: other names a command or file may use, with the choice each means ("integer" is equal
    // spacing, as the notes call it); never written.
    std::vector<std::pair<std::string_view, int>> choiceAliases;
    std::function<std::vector<double>(const Document&)> get;
    std::function<void(Document&, const std::vector<double>&)> set;  // values already checked
};

// Every row, in panel order.
std::span<const Setting> settings();
// The row named `key`, or nullptr.
const Setting* findSetting(std::string_view key);
// The row named `key`; throws std::logic_error when there is none (a programming error).
const Setting& setting(std::string_view key);

// Why `values` cannot be the setting's value ("value -5 is outside [1, 64]", "expected 4 numbers"),
// or nullopt when they can.
std::optional<std::string> settingProblem(const Setting& s, const std::vector<double>& values);
// The words a command line takes for a value ("on", "fractional_odd", "12.5") and back. parse
// throws EditError naming the key for a word it cannot read or a value out of range.
std::vector<std::string> formatSettingValues(const Setting& s, const std::vector<double>& values);
std::vector<double> parseSettingValues(const Setting& s, const std::vector<std::string>& words);

}  // namespace model
}  // namespace pw

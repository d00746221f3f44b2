// Command-line parsing shared by render and sweep: tessellation levels (finite, 1..64) and lists,
// each error a pw::InputError naming the command and option.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw::app {

[[noreturn]] void badOption(const std::string& command, const std::string& option, const std::string& what);

// True for a plain decimal number ("4", "-0.5", "1e3"); not "0x20", "inf", " 4" or "0.5abc".
bool isPlainDecimal(const std::string& text);
// A plain decimal number from lo to hi, or badOption naming the option and the range.
double parseNumber(const std::string& command, const std::string& option, const std::string& text, double lo, double hi);
float parseLevel(const std::string& command, const std::string& option, const std::string& text);
// Exactly `count` comma-separated levels; with `zeroCulls`, 0 is accepted too (an outer level of 0
// culls the patch, as the notes' hull shaders use it).
std::vector<float> parseLevels(const std::string& command, const std::string& option, const std::string& text, size_t count,
                               bool zeroCulls = false);
// Non-empty comma-separated items.
std::vector<std::string> splitList(const std::string& text);
// "WIDTHxHEIGHT", sides 1..8192 (--size).
std::array<unsigned, 2> parseImageSize(const std::string& command, const std::string& text);
// Exactly `count` comma-separated plain decimals in [lo, hi]; `form` says what was expected
// ("a point X,Y,Z") when the count is wrong.
std::vector<double> parseNumbers(const std::string& command, const std::string& option, const std::string& text, size_t count, double lo,
                                 double hi, const std::string& form);
// "X,Y,Z": three plain decimals within ±1e9 (--eye, --target).
glm::dvec3 parsePoint(const std::string& command, const std::string& option, const std::string& text);
Spacing parseSpacingOption(const std::string& command, const std::string& option, const std::string& text);

// `--compare`: 1 to 4 comma-separated panes, each a partitioning with an optional uniform level
// after a colon ("equal,fractional_odd:4.5"); level 0 means the pane keeps the other options' levels.
struct PaneSpec {
    Spacing spacing = Spacing::Equal;
    float level = 0.0f;
};
std::vector<PaneSpec> parsePaneSpecs(const std::string& command, const std::string& option, const std::string& text);

}  // namespace pw::app

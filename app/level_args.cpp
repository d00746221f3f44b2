#include "app/level_args.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace pw::app {

void badOption(const std::string& command, const std::string& option, const std::string& what) {
    throw InputError(command, option + ": " + what);
}

bool isPlainDecimal(const std::string& text) {
    static const std::regex decimal(R"(^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$)");
    return std::regex_match(text, decimal);
}

double parseNumber(const std::string& command, const std::string& option, const std::string& text, double lo, double hi) {
    // Plain decimal only: std::stod would take "0x20", "inf", " 4" and stop quietly at "0.5abc".
    if (!isPlainDecimal(text)) badOption(command, option, "'" + text + "' is not a decimal number");
    const double v = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(v) || v < lo || v > hi) {
        std::ostringstream range;
        range << "'" << text << "' must be from " << lo << " to " << hi;
        badOption(command, option, range.str());
    }
    return v;
}

float parseLevel(const std::string& command, const std::string& option, const std::string& text) {
    if (!isPlainDecimal(text)) badOption(command, option, "'" + text + "' is not a number");
    const float v = std::strtof(text.c_str(), nullptr);
    if (!std::isfinite(v) || v < limits::kMinTessLevel || v > limits::kMaxTessLevel)
        badOption(command, option, "tessellation level '" + text + "' must be from 1 to 64");
    return v;
}

std::vector<float> parseLevels(const std::string& command, const std::string& option, const std::string& text, size_t count,
                               bool zeroCulls) {
    std::vector<float> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
        out.push_back(zeroCulls && isPlainDecimal(item) && std::strtof(item.c_str(), nullptr) == 0.0f ? 0.0f
                                                                                                      : parseLevel(command, option, item));
    if (out.size() != count)
        badOption(command, option, "expected " + std::to_string(count) + " comma-separated levels, got '" + text + "'");
    return out;
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) out.push_back(item);
    return out;
}

std::array<unsigned, 2> parseImageSize(const std::string& command, const std::string& text) {
    unsigned w = 0, h = 0;
    char x = 0;
    std::stringstream ss(text);
    if (!(ss >> w >> x >> h) || x != 'x' || !ss.eof() || w < 1 || h < 1 || w > 8192 || h > 8192)
        badOption(command, "--size", "'" + text + "' must be WIDTHxHEIGHT with sides from 1 to 8192");
    return {w, h};
}

std::vector<double> parseNumbers(const std::string& command, const std::string& option, const std::string& text, size_t count, double lo,
                                 double hi, const std::string& form) {
    std::vector<double> v;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) v.push_back(parseNumber(command, option, item, lo, hi));
    if (v.size() != count || text.back() == ',') badOption(command, option, "expected " + form + ", got '" + text + "'");
    return v;
}

glm::dvec3 parsePoint(const std::string& command, const std::string& option, const std::string& text) {
    const auto v = parseNumbers(command, option, text, 3, -limits::kMaxCoordinate, limits::kMaxCoordinate, "a point X,Y,Z");
    return {v[0], v[1], v[2]};
}

Spacing parseSpacingOption(const std::string& command, const std::string& option, const std::string& text) {
    auto s = parseSpacing(text);
    if (!s) badOption(command, option, "'" + text + "' is not one of equal (or integer), fractional_odd, fractional_even, pow2");
    return *s;
}

std::vector<PaneSpec> parsePaneSpecs(const std::string& command, const std::string& option, const std::string& text) {
    std::vector<PaneSpec> out;
    for (const std::string& item : splitList(text)) {
        const size_t colon = item.find(':');
        PaneSpec p;
        p.spacing = parseSpacingOption(command, option, item.substr(0, colon));
        if (colon != std::string::npos) p.level = parseLevel(command, option, item.substr(colon + 1));
        out.push_back(p);
    }
    if (out.empty() || out.size() > 4) badOption(command, option, "give 1 to 4 panes, e.g. equal,fractional_odd:4.5");
    return out;
}

}  // namespace pw::app

namespace pw::app {

void requirePlainDecimals(CLI::App& app) {
    const CLI::Validator decimal(
        [](std::string& text) { return isPlainDecimal(text) ? std::string() : "'" + text + "' is not a decimal number"; }, "", "decimal");
    for (CLI::Option* opt : app.get_options()) {
        const std::string type = opt->get_type_name();
        if (type == "INT" || type == "UINT" || type == "FLOAT" || type == "NUMBER") opt->check(decimal);
    }
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) requirePlainDecimals(*sub);
}

}  // namespace pw::app

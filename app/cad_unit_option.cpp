// `--unit mm|cm|m|in` (issue 73): the length unit of a STEP file that names no valid one, for the
// commands that read documents; without it such a file is refused (core/io/step_import.hpp).
#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "core/io/step_import.hpp"

namespace pw::app {

void addCadUnitOption(CLI::App* cmd) {
    cmd->add_option_function<std::string>(
           "--unit", [](const std::string& unit) { assumeCadUnit(parseLengthUnit(unit)); },
           "The length unit of a STEP file that names none (or an unknown one): mm, cm, m or in; such a file is refused without it")
        ->check(CLI::IsMember({"mm", "cm", "m", "in"}));
}

}  // namespace pw::app

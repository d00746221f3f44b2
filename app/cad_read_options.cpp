// The options of the commands that read documents for STEP and IGES files (core/io/step_import.hpp):
// `--unit mm|cm|m|in` (issue 73), the length unit of a STEP file that names no valid one (refused
// without it); `--tolerance D` (issue 64), how far a face of degree above 3 may move when it is
// approximated by bicubic patches, in the file's units (default 1e-4 of the model's size).
#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "core/io/step_import.hpp"

namespace pw::app {

void addCadReadOptions(CLI::App* cmd) {
    cmd->add_option_function<std::string>(
           "--unit", [](const std::string& unit) { assumeCadUnit(parseLengthUnit(unit)); },
           "The length unit of a STEP file that names none (or an unknown one): mm, cm, m or in; such a file is refused without it")
        ->check(CLI::IsMember({"mm", "cm", "m", "in"}));
    cmd->add_option_function<double>(
           "--tolerance", [](double tolerance) { setCadTolerance(tolerance); },
           "How far a STEP/IGES face of degree above 3 may move when approximated by bicubic patches, in the file's units "
           "(default 1e-4 of the model's size); a face that cannot keep within it is skipped, saying so")
        ->check(CLI::PositiveNumber);
}

}  // namespace pw::app

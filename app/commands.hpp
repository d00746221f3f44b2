// Each sub-command of `patchwork` registers itself on the CLI11 app; `run` is set to the action to
// perform once parsing succeeded. Actions return the process exit code (0 ok, 2 bad input).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <string>
#include <utility>

namespace pw::app {

using Action = std::function<int()>;

// Adds the sub-command `name`; its options fill the returned Options, and once parsing succeeded
// `run` calls runner on them.
template <class Options>
std::pair<CLI::App*, std::shared_ptr<Options>> addSubcommand(CLI::App& app, Action& run, const std::string& name,
                                                             const std::string& description, int (*runner)(const Options&)) {
    auto options = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand(name, description);
    cmd->callback([options, runner, &run] { run = [options, runner] { return runner(*options); }; });
    return {cmd, options};
}

// Every numeric option of every sub-command (CLI11 type INT, UINT, FLOAT, NUMBER) takes plain
// decimals only: CLI11 alone reads "0x20" as 32 and "0b11" as 3.
void requirePlainDecimals(CLI::App& app);

// On a command that reads documents (app/cad_read_options.cpp): `--unit mm|cm|m|in`, the unit of a
// STEP file that names no valid length unit; `--tolerance D`, how far a CAD face of degree above 3
// may move when approximated by bicubic patches (default 1e-4 of the model's size).
void addCadReadOptions(CLI::App* cmd);

void registerInfoCommand(CLI::App& app, Action& run);
void registerExportCommand(CLI::App& app, Action& run);
void registerConvertCommand(CLI::App& app, Action& run);
void registerRenderCommand(CLI::App& app, Action& run);
void registerBenchCommand(CLI::App& app, Action& run);
void registerPresetsCommand(CLI::App& app, Action& run);
void registerRoundingCommand(CLI::App& app, Action& run);
void registerSweepCommand(CLI::App& app, Action& run);
void registerShadersCommand(CLI::App& app, Action& run);
void registerEditCommand(CLI::App& app, Action& run);
void registerCaptureCommand(CLI::App& app, Action& run);

// The default job when no sub-command is given (until the editor window exists: summary + export).
int runDefault(const std::string& file);

}  // namespace pw::app

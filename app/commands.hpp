// Each sub-command of `patchwork` registers itself on the CLI11 app; `run` is set to the action to
// perform once parsing succeeded. Actions return the process exit code (0 ok, 2 bad input).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace pw::app {

using Action = std::function<int()>;

void registerInfoCommand(CLI::App& app, Action& run);
void registerExportCommand(CLI::App& app, Action& run);
void registerConvertCommand(CLI::App& app, Action& run);
void registerRenderCommand(CLI::App& app, Action& run);
void registerBenchCommand(CLI::App& app, Action& run);
void registerPresetsCommand(CLI::App& app, Action& run);
void registerSweepCommand(CLI::App& app, Action& run);
void registerShadersCommand(CLI::App& app, Action& run);
void registerEditCommand(CLI::App& app, Action& run);

// The default job when no sub-command is given (until the editor window exists: summary + export).
int runDefault(const std::string& file);

}  // namespace pw::app

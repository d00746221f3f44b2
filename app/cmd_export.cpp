// PLACEHOLDER until the export command is written.
#include "commands.hpp"
namespace pw::app {
void registerExportCommand(CLI::App& app, Action& run) { (void)app; (void)run; }
}

// PLACEHOLDER until the info command is written.
#include "commands.hpp"
namespace pw::app {
void registerInfoCommand(CLI::App& app, Action& run) { (void)app; (void)run; }
}

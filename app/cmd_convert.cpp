// PLACEHOLDER until the convert command is written.
#include "commands.hpp"
namespace pw::app {
void registerConvertCommand(CLI::App& app, Action& run) { (void)app; (void)run; }
}

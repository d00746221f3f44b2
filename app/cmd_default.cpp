// PLACEHOLDER: default job.
#include "commands.hpp"
namespace pw::app {
int runDefault(const std::string&) { return 0; }
}

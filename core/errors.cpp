#include "core/errors.hpp"

#include <sstream>

namespace pw {

namespace {
std::string formatInput(const std::string& file, const std::string& what, int line, const std::string& field) {
    std::ostringstream msg;
    msg << file;
    if (line > 0) msg << ':' << line;
    if (!field.empty()) msg << ": field '" << field << '\'';
    msg << ": " << what;
    return msg.str();
}
}  // namespace

InputError::InputError(std::string where, std::string what, int line, std::string field)
    : std::runtime_error(formatInput(where, what, line, field)),
      file_(std::move(where)),
      reason_(std::move(what)),
      field_(std::move(field)),
      line_(line) {}

OutputError::OutputError(const std::string& path, const std::string& what)
    : std::runtime_error("cannot write " + path + ": " + what) {}

}  // namespace pw

#include "core/base/errors.hpp"

#include <sstream>

namespace pw {
inline namespace base {

namespace {
std::string formatInput(const std::string& file, const std::string& what, int line, const std::string& field) {
    std::ostringstream msg;
    msg << file;
    if (line > 0) msg << ':' << line;
    if (!field.empty()) msg << ": field '" << field << '\'';
    msg << ": " << what;
    return printable(msg.str());
}
}  // namespace

std::string printable(std::string_view text) {
    static const char* hex = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x20 || c == 0x7f) {
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
        } else {
            out += ch;
        }
    }
    return out;
}

InputError::InputError(std::string where, std::string what, int line, std::string field)
    : std::runtime_error(formatInput(where, what, line, field)),
      file_(std::move(where)),
      reason_(std::move(what)),
      field_(std::move(field)),
      line_(line) {}

OutputError::OutputError(const std::string& path, const std::string& what)
    : std::runtime_error(printable("cannot write " + path + ": " + what)) {}

}  // namespace base
}  // namespace pw

// Errors about bad input, unwritable output and refused edits. The message always names the file and, where known,
// the line or the field, e.g. "teapot.bpt:17: expected 3 numbers, found 2".
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace pw {
inline namespace base {

// `text` with control characters (below 0x20, and 0x7f) written as \xNN, so that a name or path
// from a file cannot move the cursor, clear the screen or retitle the terminal when printed. Every
// error message goes through it; so does anything else that prints a name.
std::string printable(std::string_view text);

class InputError : public std::runtime_error {
public:
    // `where` is the file name; `line` (1-based, 0 = none) or `field` (a JSON path such as
    // "patches[3].idx[7]", empty = none) locate the problem.
    InputError(std::string where, std::string what, int line = 0, std::string field = {});
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& field() const { return field_; }
    const std::string& reason() const { return reason_; }

private:
    std::string file_, reason_, field_;
    int line_ = 0;
};

// Writing an output failed (directory missing, no permission, disk full). Names the path.
class OutputError : public std::runtime_error {
public:
    OutputError(const std::string& path, const std::string& what);
};

// An edit the user asked for cannot be made (the message says why); the document is unchanged.
class EditError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace base
}  // namespace pw

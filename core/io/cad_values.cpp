#include "core/io/cad_values.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace pw {
inline namespace io {

namespace {

bool numberStart(char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-'; }
bool numberChar(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.' || c == 'E' || c == 'e' || c == 'D' || c == 'd';
}

// Refuses `token` (a number as written) when it is too long, not finite or too large.
void checkNumber(const std::string& file, std::string_view token, const std::string& entity, int line) {
    const std::string at = entity.empty() ? std::string() : entity + ": ";
    if (token.size() > limits::kMaxCadNumberDigits)
        throw InputError(file,
                         at + "a number " + std::to_string(token.size()) + " characters long (at most " +
                             std::to_string(limits::kMaxCadNumberDigits) + ")",
                         line);
    std::string s(token);
    for (char& c : s)
        if (c == 'D' || c == 'd') c = 'E';  // IGES writes double-precision exponents with D
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str()) return;  // not a number after all (a lone sign): left to the reader
    if (!std::isfinite(v)) throw InputError(file, at + "the number " + printable(s) + " is not finite", line);
    if (std::abs(v) > limits::kMaxCadNumber)
        throw InputError(
            file, at + "the number " + printable(s) + " is larger than " + std::to_string(int64_t(limits::kMaxCadNumber)) + " in magnitude",
            line);
}

void countValue(const std::string& file, size_t& count, const std::string& entity, int line) {
    if (++count > limits::kMaxCadEntityValues)
        throw InputError(file, entity + ": more than " + std::to_string(limits::kMaxCadEntityValues) + " values in one entity", line);
}

void checkStep(const std::string& file, std::string_view t) {
    const size_t data = t.find("DATA;");
    if (data == std::string_view::npos) return;  // no data section: OpenCASCADE says so
    int line = 1;
    for (size_t i = 0; i < data; ++i) line += t[i] == '\n';
    std::string entity;
    size_t values = 0;
    int depth = 0;
    for (size_t i = data + 5; i < t.size();) {
        const char c = t[i];
        if (c == '\n') {
            ++line, ++i;
        } else if (c == '/' && i + 1 < t.size() && t[i + 1] == '*') {  // comment
            const size_t e = t.find("*/", i + 2);
            for (size_t k = i; k < std::min(e, t.size()); ++k) line += t[k] == '\n';
            i = e == std::string_view::npos ? t.size() : e + 2;
        } else if (c == '\'') {  // string, '' inside
            size_t k = i + 1;
            while (k < t.size() && !(t[k] == '\'' && (k + 1 >= t.size() || t[k + 1] != '\''))) {
                if (t[k] == '\'') ++k;
                line += t[k] == '\n';
                ++k;
            }
            i = k + 1;
        } else if (c == '#' && depth == 0) {  // an entity's name: #123 = ...
            size_t k = i + 1;
            while (k < t.size() && std::isdigit(static_cast<unsigned char>(t[k]))) ++k;
            entity = "entity " + std::string(t.substr(i, k - i));
            values = 0;
            i = k;
        } else if (c == '#') {  // a reference
            ++i;
            while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i;
            countValue(file, values, entity, line);
        } else if (c == '(') {
            ++depth, ++i;
        } else if (c == ')') {
            depth = std::max(depth - 1, 0), ++i;
        } else if (c == ';') {
            depth = 0, ++i;
        } else if (c == '.' && i + 1 < t.size() && std::isalpha(static_cast<unsigned char>(t[i + 1]))) {  // .ENUM.
            const size_t e = t.find('.', i + 1);
            i = e == std::string_view::npos ? t.size() : e + 1;
        } else if (depth > 0 && (numberStart(c) || (c == '.' && i + 1 < t.size() && std::isdigit(static_cast<unsigned char>(t[i + 1]))))) {
            size_t k = i + 1;
            while (k < t.size() && numberChar(t[k])) ++k;
            checkNumber(file, t.substr(i, k - i), entity, line);
            countValue(file, values, entity, line);
            i = k;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {  // a type name, or a bare word
            size_t k = i + 1;
            while (k < t.size() && (std::isalnum(static_cast<unsigned char>(t[k])) || t[k] == '_')) ++k;
            size_t n = k;
            while (n < t.size() && std::isspace(static_cast<unsigned char>(t[n]))) ++n;
            if (depth > 0 && (n >= t.size() || t[n] != '('))
                throw InputError(file, entity + ": '" + printable(std::string(t.substr(i, k - i))) + "' is not a STEP value", line);
            if (std::string_view(t.substr(i, k - i)) == "ENDSEC") break;
            i = k;
        } else {
            ++i;
        }
    }
}

void checkIges(const std::string& file, std::string_view t) {
    int line = 0;
    std::string entity;
    size_t values = 0;
    for (size_t start = 0; start < t.size();) {
        size_t end = t.find('\n', start);
        if (end == std::string_view::npos) end = t.size();
        std::string_view row = t.substr(start, end - start);
        start = end + 1;
        ++line;
        if (!row.empty() && row.back() == '\r') row.remove_suffix(1);
        if (row.size() < 73 || row[72] != 'P') continue;
        const std::string pointer(row.substr(65, 7));
        const std::string name = "directory entry " + std::to_string(std::atol(pointer.c_str()));
        if (name != entity) entity = name, values = 0;
        const std::string_view p = row.substr(0, 64);
        for (size_t i = 0; i < p.size();) {
            const char c = p[i];
            if (std::isdigit(static_cast<unsigned char>(c))) {  // a number, or a Hollerith string nH…
                size_t k = i;
                while (k < p.size() && std::isdigit(static_cast<unsigned char>(p[k]))) ++k;
                if (k < p.size() && (p[k] == 'H' || p[k] == 'h')) {
                    i = k + 1 + size_t(std::atol(std::string(p.substr(i, k - i)).c_str()));
                    continue;
                }
            }
            if (numberStart(c) || c == '.') {
                size_t k = i + 1;
                while (k < p.size() && numberChar(p[k])) ++k;
                checkNumber(file, p.substr(i, k - i), entity, line);
                countValue(file, values, entity, line);
                i = k;
            } else if (std::isalpha(static_cast<unsigned char>(c))) {  // outside a Hollerith string: no IGES value
                size_t k = i + 1;
                while (k < p.size() && (std::isalnum(static_cast<unsigned char>(p[k])) || p[k] == '_')) ++k;
                throw InputError(file, entity + ": '" + printable(std::string(p.substr(i, k - i))) + "' is not an IGES value", line);
            } else {
                ++i;
            }
        }
    }
}

}  // namespace

void checkCadValues(const std::string& file, std::string_view text, bool step) {
    if (step)
        checkStep(file, text);
    else
        checkIges(file, text);
}

}  // namespace io
}  // namespace pw

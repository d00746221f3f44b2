#include "core/base/json_guard.hpp"

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace pw {
inline namespace base {

int lineAt(std::string_view text, size_t byte) {
    byte = std::min(byte, text.size());
    int line = 1;
    for (size_t i = 0; i < byte; ++i)
        if (text[i] == '\n') ++line;
    return line;
}

std::string parseErrorReason(const std::string& what) {
    std::string s = what;
    if (s.rfind("[json.exception.", 0) == 0) {
        const size_t close = s.find("] ");
        if (close != std::string::npos) s = s.substr(close + 2);
    }
    if (s.rfind("parse error", 0) == 0) {
        const size_t colon = s.find(": ");
        if (colon != std::string::npos) s = s.substr(colon + 2);
    }
    return "JSON syntax error: " + s;
}

size_t excessiveNesting(std::string_view text, int maxDepth) {
    int depth = 0;
    bool inString = false, escaped = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > maxDepth) return i;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return std::string_view::npos;
}

namespace {
void guardJsonText(std::string_view text, const std::string& sourceName, int maxDepth) {
    if (text.size() > limits::kMaxFileBytes)
        throw InputError(sourceName,
                         "JSON is " + std::to_string(text.size()) + " bytes; the limit is " + std::to_string(limits::kMaxFileBytes));
    if (const size_t at = excessiveNesting(text, maxDepth); at != std::string_view::npos)
        throw InputError(sourceName, "JSON nested deeper than " + std::to_string(maxDepth) + " levels", lineAt(text, at));
}
}  // namespace

nlohmann::json parseJsonGuarded(std::string_view text, const std::string& sourceName, int maxDepth) {
    guardJsonText(text, sourceName, maxDepth);
    try {
        return nlohmann::json::parse(text.begin(), text.end());
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte is the 1-based position of the offending character (past the end when truncated).
        const size_t byte = e.byte > 0 ? e.byte - 1 : 0;
        throw InputError(sourceName, parseErrorReason(e.what()), lineAt(text, byte));
    } catch (const nlohmann::json::exception& e) {
        // E.g. "number overflow parsing '1e400'" (out_of_range.406), which carries no position:
        // locate the quoted token in the text.
        std::string what = e.what();
        if (what.rfind("[json.exception.", 0) == 0 && what.find("] ") != std::string::npos) what = what.substr(what.find("] ") + 2);
        int line = 0;
        const size_t q0 = what.find('\''), q1 = q0 == std::string::npos ? q0 : what.find('\'', q0 + 1);
        if (q1 != std::string::npos && q1 > q0 + 1) {
            const size_t at = text.find(what.substr(q0 + 1, q1 - q0 - 1));
            if (at != std::string_view::npos) line = lineAt(text, at);
        }
        throw InputError(sourceName, "JSON error: " + what, line);
    }
}

}  // namespace base
}  // namespace pw

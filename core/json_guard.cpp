#include "core/json_guard.hpp"

#include <algorithm>

namespace pw {

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
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
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

}  // namespace pw

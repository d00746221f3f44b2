// Guards and diagnostics in front of every JSON parser (nlohmann/json and tinygltf build their DOM
// recursively): refuse absurd nesting and size before parsing, and turn parse errors into one line
// with a line number. Every JSON Patchwork reads goes through parseJsonGuarded.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace pw {
inline namespace base {

// A Patchwork document nests 4 deep; 64 levels refuse files of millions of '[' before they can
// exhaust the stack or memory.
inline constexpr int kMaxJsonDepth = 64;

// The byte offset of the first bracket nested deeper than `maxDepth` (outside strings), or npos.
size_t excessiveNesting(std::string_view text, int maxDepth = kMaxJsonDepth);

// Byte offset -> 1-based line number.
int lineAt(std::string_view text, size_t byte);

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line 3, column 5: "
// prefix (callers report the line themselves), as "JSON syntax error: ...".
std::string parseErrorReason(const std::string& what);

// Parses `text` as JSON after the guards: more than limits::kMaxFileBytes or nesting deeper than
// kMaxJsonDepth is refused before parsing. Throws InputError naming `sourceName` and the line.
nlohmann::json parseJsonGuarded(std::string_view text, const std::string& sourceName, int maxDepth = kMaxJsonDepth);

}  // namespace base
}  // namespace pw

// The tea-set `.bpt` format (data/README.md): a patch count, then per patch a line "3 3" and 16
// lines "x y z", row-major. Import merges exactly coincident points into one pool entry and
// detects joins (join_detect.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/model/document.hpp"

namespace pw {

// `sourceName` is used in error messages (InputError with the line number).
Document parseBpt(std::string_view text, const std::string& sourceName);
Document loadBpt(const std::filesystem::path& path);

// Writes the document's patches (surfaces expanded to Bézier-basis patches only; refuses other
// bases with an error naming the patch) in the tea-set format, numbers printed round-trip exact.
std::string formatBpt(const Document& doc);

}  // namespace pw

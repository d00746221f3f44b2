// The tea-set `.bpt` format (data/README.md): a patch count, then per patch a line "3 3" and 16
// lines "x y z", row-major. Import merges exactly coincident points into one pool entry and
// detects joins (join_detect.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace io {

// `sourceName` is used in error messages (InputError with the line number). A file whose count
// lists more than limits::kMaxPoints points is refused at its first line. `notes`, when given,
// receives what the reader left out (edges shared by more than two patches, left unjoined).
Document parseBpt(std::string_view text, const std::string& sourceName, std::vector<std::string>* notes = nullptr);
Document loadBpt(const std::filesystem::path& path, std::vector<std::string>* notes = nullptr);

// Writes the document's patches (surfaces expanded to Bézier-basis patches only; refuses other
// bases with an error naming the patch) in the tea-set format, numbers printed round-trip exact.
std::string formatBpt(const Document& doc);

}  // namespace io
}  // namespace pw

// The native `.patchwork` format: JSON with a "format" name and "version"; everything in the
// document (pool, patches, surfaces, joins, tessellation, display, camera). Saving then loading
// gives an identical Document (doubles are written round-trip exact). A newer version is refused.
#pragma once

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

#include "core/model/document.hpp"

namespace pw {
inline namespace io {

nlohmann::json documentToJson(const Document& doc);
// Validates everything (types, counts, index ranges, finite coordinates, limits.hpp); throws
// InputError naming `sourceName` and the field path (e.g. "patches[3].idx[7]"), after
// `fieldPrefix` where the document sits inside another file.
Document documentFromJson(const nlohmann::json& json, const std::string& sourceName, const std::string& fieldPrefix = {});

std::string serializeDocument(const Document& doc);
Document parseDocument(std::string_view text, const std::string& sourceName);  // errors carry the line

}  // namespace io
}  // namespace pw

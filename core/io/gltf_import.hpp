// Import of a Patchwork glTF (.gltf or .glb): restores the document from the "patchwork" extras.
// A glTF without them is refused with a message saying so.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/io/gltf_export.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace io {

// exportOptions (when given) receives the options the file was exported with (extras
// patchworkExport), or nullopt for a file without them.
Document importPatchworkGltf(const std::filesystem::path& path, std::optional<ExportOptions>* exportOptions = nullptr);

// The same from the file's bytes (.glb when they start with "glTF", else JSON). Reads no other
// file and decodes no image: a hostile glTF cannot make Patchwork open paths its URIs name.
Document parsePatchworkGltf(std::string_view data, const std::string& sourceName, std::optional<ExportOptions>* exportOptions = nullptr);
// The same, releasing `data` as soon as the glTF reader has its own copy of what it checks (a large
// .glb then costs two copies of its size at once, not three).
Document parsePatchworkGltf(std::string&& data, const std::string& sourceName, std::optional<ExportOptions>* exportOptions = nullptr);

}  // namespace io
}  // namespace pw

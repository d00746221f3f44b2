// Import of a Patchwork glTF (.gltf or .glb): restores the document from the "patchwork" extras.
// A glTF without them is refused with a message saying so.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/document.hpp"

namespace pw {

Document importPatchworkGltf(const std::filesystem::path& path);

// The same from the file's bytes (.glb when they start with "glTF", else JSON). Reads no other
// file and decodes no image: a hostile glTF cannot make Patchwork open paths its URIs name.
Document parsePatchworkGltf(std::string_view data, const std::string& sourceName);

}  // namespace pw

// Import of a Patchwork glTF (.gltf or .glb): restores the document from the "patchwork" extras.
// A glTF without them is refused with a message saying so.
#pragma once

#include <filesystem>

#include "document.hpp"

namespace pw {

Document importPatchworkGltf(const std::filesystem::path& path);

}  // namespace pw

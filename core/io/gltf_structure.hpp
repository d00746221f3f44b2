// The core glTF 2.0 structure checked with field names, before the glTF reader sees the file: the
// reader checks much of the same but says "'byteLength' property is missing in BufferView" with no
// index, or nothing at all. Covered: asset, scene, scenes, nodes, meshes and their primitives,
// accessors, bufferViews, buffers (every index in range, every enum and count valid), and that each
// other top-level array holds objects.
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace pw {
inline namespace io {

// Throws InputError naming `name` and the field, e.g. "accessors[3].componentType". `binBytes`: the
// size of a .glb's BIN chunk (0 when it has none or the file is .gltf).
void checkGltfStructure(const nlohmann::json& gltf, const std::string& name, bool binary, size_t binBytes);

}  // namespace io
}  // namespace pw

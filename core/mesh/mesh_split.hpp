// How an export groups a welded mesh (mesh_tessellate.hpp) into primitives: one per connected
// surface (the default: what Blender and assimp import as one piece without splitting it at patch
// seams), one per patch, or one for everything. Each group gets its own vertices, so a reader that
// copies a primitive's vertex range (assimp) copies only what the primitive uses.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/mesh_tessellate.hpp"

namespace pw {
inline namespace mesh {

enum class MeshGrouping { Surfaces, Patches, Single };

const char* meshGroupingName(MeshGrouping g);  // "surfaces", "patches", "single"
std::optional<MeshGrouping> parseMeshGrouping(const std::string& name);

struct MeshGroup {
    uint32_t firstIndex = 0, indexCount = 0;    // in SplitMesh::indices (triangles)
    uint32_t firstVertex = 0, vertexCount = 0;  // in SplitMesh::positions / normals / uvs
    bool closed = false;                        // every edge (by position) is shared by exactly two of the group's triangles
    int item = -1;                              // Patches: the window (expandPatches order) or, after them, the Bézier triangle
};

struct SplitMesh {
    std::vector<std::array<float, 3>> positions;
    std::vector<std::array<float, 3>> normals;
    std::vector<std::array<float, 2>> uvs;
    std::vector<uint32_t> indices;  // relative to the group's firstVertex
    std::vector<MeshGroup> groups;  // in order of their first triangle in the mesh
};

// Consumes the mesh. Groups without triangles are left out; a vertex no triangle uses is dropped.
// A mesh of `inPlaceFrom` bytes or more (positions, normals, UVs and indices) grouped by surface or
// as one is split within its own arrays: about half the memory, somewhat slower, the same result;
// smaller ones, and Patches (whose groups share vertices), are copied out group by group.
inline constexpr size_t kSplitInPlaceFrom = size_t(32) << 20;
SplitMesh splitMesh(TriangleMesh&& mesh, MeshGrouping grouping, size_t inPlaceFrom = kSplitInPlaceFrom);

// Vertices with bit-identical positions get one id (the smallest vertex index among them): the
// welded mesh keeps separate vertices at C0 creases and unjoined seams, which are still one surface.
std::vector<uint32_t> positionIds(const std::vector<std::array<float, 3>>& positions);

}  // namespace mesh
}  // namespace pw

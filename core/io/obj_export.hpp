// Wavefront OBJ export (+ MTL): the welded mesh as every tool reads it. One `v` per distinct
// position, `vn` per distinct normal (shared across C1/G1 seams, split at C0 creases), `vt` per
// vertex (each patch's (u, v)); one group `g` per patch, net window and Bézier triangle (named after
// the patch where it has a name); Bézier curves as `l` polylines. OBJ has no up axis and readers
// (Blender, three.js) take +Y as up, so a Z-up document is written turned: (x, y, z) -> (x, z, -y).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "core/mesh/mesh_tessellate.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace io {

struct ObjExportStats {
    int level = 0;
    bool asDisplayed = false;
    size_t positions = 0, normals = 0, uvs = 0, triangles = 0, groups = 0, lineSegments = 0;
    size_t bytes = 0;  // OBJ and MTL together
};

struct ObjFiles {
    std::string obj, mtl;
};

// `mtlName` is the file name the OBJ's mtllib line refers to. level as in glTF export (0: the
// document's). With `displayed` (the surface as the GPU tessellated it, render/surface_capture;
// consumed), that mesh is written instead of tessellateDocument's and `level` only samples curves.
ObjFiles exportObjText(const Document& doc, int level, const std::string& mtlName, ObjExportStats* stats = nullptr,
                       TriangleMesh* displayed = nullptr);

// Writes PATH (.obj) and the MTL beside it (same stem, .mtl), each atomically; on failure neither is
// left changed. Throws OutputError naming the path.
ObjExportStats exportObj(const Document& doc, const std::filesystem::path& path, int level = 0, TriangleMesh* displayed = nullptr);

}  // namespace io
}  // namespace pw

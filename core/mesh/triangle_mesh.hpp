// CPU tessellation of a document's cubic Bézier triangles into the export mesh (DESIGN §5): each
// triangle as the uniform barycentric grid at the export level (level² triangles), welded to the
// other triangles through the pool — corners by pool index, edge interiors by the edge's four pool
// indices in canonical order — with analytic normals (averaged where the sides agree, split at
// creases) and the barycentric (u, v) as UVs.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "core/mesh/mesh_tessellate.hpp"

namespace pw {
inline namespace mesh {

// Vertices already in the mesh on Bézier boundaries, by pool: corners by pool index, edge
// interiors (k = 1 .. level-1 in the canonical direction of the edge's four pool indices, the
// lexicographically smaller of the two orders) by those four indices. The quad windows leave
// theirs here so that triangles sharing an edge with a quad weld to it.
struct BoundaryVertices {
    std::map<uint32_t, uint32_t> corners;
    std::map<std::array<uint32_t, 4>, std::vector<uint32_t>> edges;
};

// Appends every triangle of `doc` to `mesh` (positions, normals, uvs, indices, and one perTriangle
// range each). level >= 1. Vertices on collapsed edges fold into the edge's first corner and the
// triangles they make degenerate are left out. With `quads`, a triangle edge or corner on a quad's
// boundary uses the quad's vertex where their normals agree (a crease keeps its own vertex).
void appendBezierTriangles(const Document& doc, int level, TriangleMesh& mesh, const BoundaryVertices* quads = nullptr);

}  // namespace mesh
}  // namespace pw

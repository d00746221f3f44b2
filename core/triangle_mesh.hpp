// CPU tessellation of a document's cubic Bézier triangles into the export mesh (DESIGN §5): each
// triangle as the uniform barycentric grid at the export level (level² triangles), welded to the
// other triangles through the pool — corners by pool index, edge interiors by the edge's four pool
// indices in canonical order — with analytic normals (averaged where the sides agree, split at
// creases) and the barycentric (u, v) as UVs.
#pragma once

#include "mesh_tessellate.hpp"

namespace pw {

// Appends every triangle of `doc` to `mesh` (positions, normals, uvs, indices, and one perTriangle
// range each). level >= 1. Vertices on collapsed edges fold into the edge's first corner and the
// triangles they make degenerate are left out.
void appendBezierTriangles(const Document& doc, int level, TriangleMesh& mesh);

}  // namespace pw

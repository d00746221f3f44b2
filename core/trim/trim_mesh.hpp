// Trimmed surfaces as triangles (issue 64; the glTF and OBJ exports): each trimmed window's grid,
// as tessellateDocument made it, cut along its trim loops by a constrained Delaunay triangulation
// of its (u, v) square (CGAL), keeping the triangles inside what the loops keep. The grid's own
// vertices stay (so the window still welds to its neighbours along untrimmed edges), and the trim
// edge's vertices of a loop laid from a curve are that curve's points: two surfaces cut by one
// curve get the same positions along their cut, so the mesh is watertight there.
#pragma once

#include "core/mesh/mesh_tessellate.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace trim {

// Cuts every window of mesh.trimmedGrids along its trims (a wholly trimmed window loses all its
// triangles), rewriting mesh.indices and the per-window ranges; clears trimmedGrids.
void trimMesh(const Document& doc, TriangleMesh& mesh);
// tessellateDocument, then trimMesh: what the exports write.
TriangleMesh tessellateTrimmed(const Document& doc, int level);

}  // namespace trim
}  // namespace pw

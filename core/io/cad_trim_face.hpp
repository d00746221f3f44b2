// Trimmed faces for STEP and IGES (issue 64): a surface's trim loops as wires of edges whose
// p-curves are the loops' cubic Bézier segments (exact), their 3D curves built from them, each
// outer loop a face with the holes it encloses. Only core/io includes this (OpenCASCADE).
#pragma once

#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>

#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace io {

// The faces of `surface` that `loops` keep; the loops' (u, v) in [0, 1]² map onto the surface's
// parameter range. No loops: the untrimmed face. Throws std::runtime_error naming `what` when
// OpenCASCADE cannot build a face.
std::vector<TopoDS_Face> trimmedFaces(const Handle(Geom_Surface) & surface, const std::vector<TrimLoop>& loops, double tol,
                                      const std::string& what);

}  // namespace io
}  // namespace pw

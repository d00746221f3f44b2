// A planar CAD face bounded by one loop of lines, circular arcs and other curves of degree <= 3 (a
// cylinder's cap, a plate with rounded corners) as exact Bézier patches: a fan of ruled patches from
// the face's centroid to each boundary segment, the outer edge on the boundary (rational where the
// boundary is) and the opposite edge collapsed at the centre, as add-cylinder builds its caps. Only
// for faces that are star-shaped about their centroid (the boundary turns one way round it
// everywhere), so that no patch folds; otherwise the reason; nothing (monostate) for a face that is
// not planar. Only the STEP/IGES import includes this (it pulls in OCCT headers).
#pragma once

#include <Geom_BezierSurface.hxx>
#include <Standard_Handle.hxx>
#include <TopoDS_Face.hxx>

#include <string>
#include <variant>
#include <vector>

namespace pw {
inline namespace io {
namespace occt {

using BezierPatches = std::vector<Handle(Geom_BezierSurface)>;
std::variant<std::monostate, BezierPatches, std::string> planarFan(const TopoDS_Face& face);

}  // namespace occt
}  // namespace io
}  // namespace pw

// STEP and IGES faces whose outline is not their parameter rectangle (issue 64): holes, curved
// trims, L-shaped planes. The face's surface over its parameter box, cut into spans, and its wires'
// p-curves as trim loops in the spans' grid (span (i, j) of nu x nv covers [i/nu, (i+1)/nu] x
// [j/nv, (j+1)/nv]: the domain of the patch, or of the net the spans become). Only core/io
// includes this (OpenCASCADE).
#pragma once

#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>

#include <string>
#include <variant>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace io {

// A face's surface as a B-spline of degree <= 3, not periodic (planes, cylinders, cones, spheres,
// tori, revolved and extruded surfaces converted by OpenCASCADE, face and p-curves together), with
// the face its p-curves belong to and the name of the surface it was converted from ("" when none).
// A surface of higher degree (FreeCAD's lofts are 14 x 2, its sweeps 6 x 10) is approximated by a
// bicubic B-spline over the same parameters (OpenCASCADE's GeomConvert_ApproxSurface, C1) when
// `tolerance` > 0: `approximated` says from what ("degree 14 x 2") and `deviation` is the largest
// distance between the two measured on a grid; one that cannot keep within `tolerance` is refused.
struct FaceBSpline {
    Handle(Geom_BSplineSurface) surface;
    TopoDS_Face face;
    std::string converted;
    std::string approximated;
    double deviation = 0.0;
};
std::variant<FaceBSpline, std::string> faceBSpline(const TopoDS_Face& face, double tolerance = 0.0);
// The face on a polynomial bicubic B-spline over the same parameters within `tolerance` of its
// rational one (a trimmed cylinder or cone of several spans cannot be one net: Patchwork's nets
// are polynomial); `approximated` says "rational", `deviation` as above. Else why not.
std::variant<FaceBSpline, std::string> polynomialFace(const FaceBSpline& face, double tolerance);

struct TrimmedFace {
    Handle(Geom_BSplineSurface) surface;  // over the face's parameter box, oriented like the face
    std::vector<TrimLoop> loops;          // in the spans' grid, checked
    double deviation = 0.0;               // the largest p-curve approximation error (parameter units), 0 when exact
};
// `f` from faceBSpline. The reason when the wires do not make loops Patchwork can keep.
std::variant<TrimmedFace, std::string> trimmedFace(const FaceBSpline& f);

}  // namespace io
}  // namespace pw

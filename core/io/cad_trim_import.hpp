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
struct FaceBSpline {
    Handle(Geom_BSplineSurface) surface;
    TopoDS_Face face;
    std::string converted;
};
std::variant<FaceBSpline, std::string> faceBSpline(const TopoDS_Face& face);

struct TrimmedFace {
    Handle(Geom_BSplineSurface) surface;  // over the face's parameter box, oriented like the face
    std::vector<TrimLoop> loops;          // in the spans' grid, checked
    double deviation = 0.0;               // the largest p-curve approximation error (parameter units), 0 when exact
};
// `f` from faceBSpline. The reason when the wires do not make loops Patchwork can keep.
std::variant<TrimmedFace, std::string> trimmedFace(const FaceBSpline& f);

}  // namespace io
}  // namespace pw

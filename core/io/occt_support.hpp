// What the STEP export and the STEP/IGES import share around OpenCASCADE: one lock (its data-exchange
// settings are process-wide), silenced console output, the length unit, and the Bézier <-> B-spline
// pole layout.
// Only the STEP/IGES export and import, and the tests that read and write CAD files with
// OpenCASCADE, include this (it pulls in OCCT headers).
#pragma once

#include <Geom_BSplineSurface.hxx>
#include <Standard_Handle.hxx>

#include <array>
#include <mutex>

#include "core/base/math_types.hpp"
#include "core/model/document.hpp"
#include "core/ops/net_ops.hpp"

namespace pw {
inline namespace io {
namespace occt {

// Held for every use of OCCT's readers and writers; the first call also removes OCCT's console
// printers (its transfer statistics would otherwise go to stdout).
std::unique_lock<std::mutex> lock();

// A bicubic Bézier patch (row-major 16 points, row i = v, column j = u) as an exact B-spline
// surface: poles(j + 1, i + 1), knots {0, 1} of multiplicity 4 both ways; rational (the same
// weights at the same places) when `weights` is given.
Handle(Geom_BSplineSurface) bezierSurface(const std::array<Vec3, 16>& net, const Weights16* weights = nullptr);

// A net's Bézier grid (core/ops/net_ops.hpp) as one exact B-spline surface: its poles (a closed
// direction repeating its first row or column), knots 0, 1, … one a window, inner ones of
// multiplicity 3.
Handle(Geom_BSplineSurface) netBezierSurface(const BezierGrid& g);

// OpenCASCADE's name of a length unit (write.step.unit, xstep.cascade.unit): "MM", "CM", "M", "INCH".
const char* unitName(LengthUnit u);

// Makes `u` OpenCASCADE's own length unit for the next transfer, so that shapes are read and
// written in it with no conversion: its setting (xstep.cascade.unit) and its process-wide unit
// cache, which an earlier read or write leaves behind. Returns the unit in millimetres, for the
// STEP model's own units (StepData_StepModel::SetLocalLengthUnit, SetWriteLengthUnit).
double useLengthUnit(LengthUnit u);

}  // namespace occt
}  // namespace io
}  // namespace pw

// Procedural documents for tests and benchmarks.
#pragma once

#include "core/model/document.hpp"

namespace pw {
inline namespace construct {

// A rows x cols grid of bicubic Bézier patches over [0, cols] x [0, rows] (z up), with a gentle
// wave in z, sharing boundary points through the pool, and joined with `continuity` across every
// interior edge (the control net is made to satisfy C1 exactly, or C2 for C2/G2 joins: the Bézier
// form of a cubic B-spline). rows, cols >= 1.
Document makePatchGrid(int rows, int cols, Continuity continuity = Continuity::C1);

// A dome of six cubic Bézier triangles around the origin (z up): the paraboloid
// z = height·(1 − (x² + y²)/radius²) over a regular hexagon of circumradius `radius`, represented
// exactly (the control points are the surface's blossom values). Neighbours share their edges'
// four pool points, so the dome is watertight and smooth; its normals point up (+z).
Document makeTriangleDome(double radius = 1.0, double height = 0.5);

}  // namespace construct
}  // namespace pw

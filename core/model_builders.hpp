// Procedural documents for tests and benchmarks.
#pragma once

#include "document.hpp"

namespace pw {

// A rows x cols grid of bicubic Bézier patches over [0, cols] x [0, rows] (z up), with a gentle
// wave in z, sharing boundary points through the pool, and joined with `continuity` across every
// interior edge (the control net is made to satisfy C1 exactly). rows, cols >= 1.
Document makePatchGrid(int rows, int cols, Continuity continuity = Continuity::C1);

}  // namespace pw

// The trim test that the fragment shader and the C++ share, written once (issue 64): whether a point
// (u, v) of a window's domain is kept, from the window's trim segments. Each segment is a cubic
// Bézier p-curve piece that is monotone in v (core/trim/trim_loops.cpp splits the loops at their
// v extrema), so a ray from the point towards +u crosses it at most once: Schollmeyer and Fröhlich's
// direct trimming (2009). The crossing is found exactly, to the float's precision, by bisection on
// the monotone v(t) — no trim texture, so no jaggies at any zoom. The parity of the crossings, with
// the window's base parity (1 where the surface has no outer loop: its domain boundary is the outer
// loop), says kept (odd) or trimmed away (even).
#ifndef PW_TRIM_MATH_H
#define PW_TRIM_MATH_H

#include "core/gpu/glsl_cpp.h"

PW_BEGIN_NAMESPACE

// Bisection steps: 2^-24 of the segment's parameter, below a float's resolution of it.
PW_CONST int kTrimBisections = 24;

// A cubic Bézier's coordinate at t (one of u or v).
PW_REAL_FN PW_REAL trimBezier1(PW_REAL a, PW_REAL b, PW_REAL c, PW_REAL d, PW_REAL t) {
    PW_REAL s = PW_REAL(1) - t;
    return s * s * s * a + PW_REAL(3) * s * s * t * b + PW_REAL(3) * s * t * t * c + t * t * t * d;
}

// 1 when the ray from p towards +u crosses the v-monotone segment b0..b3, else 0. The segment's
// v range is half open [vmin, vmax), so a ray through a joint of two segments counts once.
PW_REAL_FN uint trimCrossing(PW_REAL_VEC2 p, PW_REAL_VEC2 b0, PW_REAL_VEC2 b1, PW_REAL_VEC2 b2, PW_REAL_VEC2 b3) {
    PW_REAL vmin = min(b0.y, b3.y);
    PW_REAL vmax = max(b0.y, b3.y);
    if (p.y < vmin || p.y >= vmax) return 0u;
    PW_REAL umin = min(min(b0.x, b1.x), min(b2.x, b3.x));
    PW_REAL umax = max(max(b0.x, b1.x), max(b2.x, b3.x));
    if (p.x < umin) return 1u;  // the whole segment lies to the right: the ray crosses it
    if (p.x > umax) return 0u;
    bool rising = b3.y > b0.y;
    PW_REAL lo = PW_REAL(0);
    PW_REAL hi = PW_REAL(1);
    for (int i = 0; i < kTrimBisections; ++i) {
        PW_REAL mid = PW_REAL(0.5) * (lo + hi);
        PW_REAL vm = trimBezier1(b0.y, b1.y, b2.y, b3.y, mid);
        if ((vm < p.y) == rising)
            lo = mid;
        else
            hi = mid;
    }
    PW_REAL t = PW_REAL(0.5) * (lo + hi);
    return p.x < trimBezier1(b0.x, b1.x, b2.x, b3.x, t) ? 1u : 0u;
}

// Per drawn window (PatchData::trim): x the window's block in binding 7 (its cells, then their
// segments, three vec4 each: the box, b0 b1, b2 b3), y the window's segment count, z flags. A window
// without kTrimTest is drawn whole.
PW_CONST uint kTrimBaseKept = 1u;  // the surface has no outer loop: the base parity is 1
PW_CONST uint kTrimAllGone = 2u;   // no segment crosses the window and its centre is trimmed away: not tessellated
PW_CONST uint kTrimTest = 4u;      // the window's fragments are tested against its segments
// A tested window's square is cut into kTrimCells x kTrimCells cells, each listing only the segments
// its rays may meet (core/trim/trim_cells.hpp); binding 7 starts the window's block with one vec4 per
// cell (first vec4 of its list, its segment count, its parity: whole numbers as floats), row-major.
PW_CONST uint kTrimCells = 16u;

PW_END_NAMESPACE

#endif  // PW_TRIM_MATH_H

// Where Mesa's tessellator (lavapipe's draw module, after Microsoft's reference tessellator) puts
// point i of an edge cut into n equal segments (equal_spacing, n <= 64): the parameter in 16.16
// fixed point, i times 1/n rounded to 16 bits for the first half of the edge, mirrored from the far
// end for the second half, exactly 1/2 in the middle. Powers of two give exactly i / n; other
// levels do not, so i / (B n) is not i' / n: a block of windows drawn as one patch at level B n
// (shaders/merged.tesc) snaps each vertex to its index on the block's edge and places it with this
// formula, as the window's own patch at level n would be placed (render/scene/merged_blocks.hpp).
// tests/render_test_capture.cpp checks it against the tessellator's own coordinates.
#ifndef PW_TESS_PLACE_H
#define PW_TESS_PLACE_H

#include "core/gpu/glsl_cpp.h"

PW_BEGIN_NAMESPACE

// 1/n in 16.16 fixed point, rounded to nearest (the reference tessellator's table of reciprocals).
PW_FN uint fixedReciprocal(uint n) { return (65536u + n / 2u) / n; }

// The parameter of point i (0..n) of an edge of n segments, as the fixed-point tessellator places it.
PW_FN float fixedTessPlace(uint i, uint n) {
    uint fx;
    if (2u * i < n)
        fx = i * fixedReciprocal(n);
    else if (2u * i == n)
        fx = 32768u;
    else
        fx = 65536u - (n - i) * fixedReciprocal(n);
    return float(fx) / 65536.0f;
}

PW_END_NAMESPACE

#endif

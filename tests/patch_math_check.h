// Input and output layout of tests/patch_math_check.comp, the compute shader that runs
// core/gpu/patch_math.h on the GPU for tests/render_test_patch_math.cpp (written once for both
// languages, like core/gpu/gpu_interface.h).
#ifndef PW_PATCH_MATH_CHECK_H
#define PW_PATCH_MATH_CHECK_H

#include "core/gpu/patch_math.h"

PW_BEGIN_NAMESPACE

PW_CONST int kCheckLevels = 64;     // requested levels, each rounded under the 4 partitionings
PW_CONST int kCheckBernstein = 65;  // t = i / 64: weights, first and second derivatives
PW_CONST int kCheckPools = 32;      // pool-index quadruples for the canonical direction
PW_CONST int kCheckEdges = 32;      // boundary curves for the adaptive levels and boundary points
PW_CONST int kCheckT = 9;           // t = j / 8 along each boundary

// Output offsets (floats).
PW_CONST int kOutRound = 0;
PW_CONST int kOutBernstein = kOutRound + kCheckLevels * 4;
PW_CONST int kOutSlots = kOutBernstein + kCheckBernstein * 12;  // quad (e, k, depth) then triangle (e, k)
PW_CONST int kOutReversed = kOutSlots + 64 + 12;
PW_CONST int kOutAdaptive = kOutReversed + kCheckPools;      // modes distance, screen, orientation, distance on pow2
PW_CONST int kOutBoundary = kOutAdaptive + kCheckEdges * 4;  // per (edge, t): walked forward, backward
PW_CONST int kOutSize = kOutBoundary + kCheckEdges * kCheckT * 6;

PW_BLOCK(layout(set = 0, binding = 0, std430) readonly buffer CheckInput, CheckInput) {
    mat4 viewProj;
    vec4 eye;       // xyz
    vec4 params;    // x d0, y d1, z max level, w target pixels per segment
    vec4 viewport;  // xy pixels
    vec4 exps;      // xy the pow2 distance curve's exponents
    float levels[kCheckLevels];
    uvec4 pools[kCheckPools];
    vec4 edges[kCheckEdges * 4];  // xyz: four control points per boundary curve
}
PW_END_BLOCK(inp)

PW_END_NAMESPACE

#endif  // PW_PATCH_MATH_CHECK_H

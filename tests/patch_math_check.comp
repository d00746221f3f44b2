#version 450
#extension GL_GOOGLE_include_directive : require
// Runs every function of core/gpu/patch_math.h on the GPU over the inputs of tests/patch_math_check.h;
// tests/render_test_patch_math.cpp runs the same header compiled as C++ and compares.
#include "tests/patch_math_check.h"

layout(local_size_x = 1) in;
layout(set = 0, binding = 1, std430) writeonly buffer CheckOutput { float o[]; } outp;

void main() {
    for (int i = 0; i < kCheckLevels; ++i)
        for (uint s = 0u; s < 4u; ++s) outp.o[kOutRound + i * 4 + int(s)] = roundLevel(inp.levels[i], s);

    for (int i = 0; i < kCheckBernstein; ++i) {
        float t = float(i) / float(kCheckBernstein - 1), s = 1.0f - t;
        vec4 w = bernstein3(t, s), dw = bernstein3D1(t, s), ddw = bernstein3D2(t, s);
        for (int k = 0; k < 4; ++k) {
            outp.o[kOutBernstein + i * 12 + k] = w[k];
            outp.o[kOutBernstein + i * 12 + 4 + k] = dw[k];
            outp.o[kOutBernstein + i * 12 + 8 + k] = ddw[k];
        }
    }

    for (int e = 0; e < 4; ++e)
        for (int k = 0; k < 4; ++k)
            for (int d = 0; d < 4; ++d) outp.o[kOutSlots + e * 16 + k * 4 + d] = float(quadEdgeSlot(e, k, d));
    for (int e = 0; e < 3; ++e)
        for (int k = 0; k < 4; ++k) outp.o[kOutSlots + 64 + e * 4 + k] = float(triEdgeSlot(e, k));

    for (int i = 0; i < kCheckPools; ++i) {
        uvec4 p = inp.pools[i];
        outp.o[kOutReversed + i] = edgeReversed(p.x, p.y, p.z, p.w) ? 1.0f : 0.0f;
    }

    for (int i = 0; i < kCheckEdges; ++i) {
        vec3 p0 = inp.edges[i * 4].xyz, p1 = inp.edges[i * 4 + 1].xyz, p2 = inp.edges[i * 4 + 2].xyz,
             p3 = inp.edges[i * 4 + 3].xyz;
        for (uint m = 0u; m < 4u; ++m)  // distance (linear), screen, orientation, then distance on the pow2 curve
            outp.o[kOutAdaptive + i * 4 + int(m)] =
                adaptiveEdgeLevel(p0, p1, p2, p3, m == 3u ? kAdaptiveDistance : kAdaptiveDistance + m, inp.params.z, inp.eye.xyz,
                                  inp.params.x, inp.params.y, m == 3u ? kCurvePow2 : kCurveLinear, inp.exps.xy, inp.viewProj,
                                  inp.viewport.xy, inp.params.w);
        // Two patches share this boundary and walk it in opposite directions; both evaluate it in
        // the canonical direction of its pool indices (pools[i]).
        uvec4 p = inp.pools[i];
        bool rev = edgeReversed(p.x, p.y, p.z, p.w);
        for (int j = 0; j < kCheckT; ++j) {
            float t = float(j) / float(kCheckT - 1);
            vec3 a = canonicalBoundaryPoint(p0, p1, p2, p3, t, rev);
            vec3 b = canonicalBoundaryPoint(p3, p2, p1, p0, 1.0f - t, !rev);
            int o = kOutBoundary + (i * kCheckT + j) * 6;
            outp.o[o] = a.x; outp.o[o + 1] = a.y; outp.o[o + 2] = a.z;
            outp.o[o + 3] = b.x; outp.o[o + 4] = b.y; outp.o[o + 5] = b.z;
        }
    }
}

#version 450
#extension GL_GOOGLE_include_directive : require
// Curvature combs through the isoline domain (issue 21, DESIGN §3): on a cubic Bézier curve (4
// points) or, with -DISOCURVES, on line k of n of a window's isocurves (at k / (n − 1), along u or,
// with draw.isoDirection bit 0, along v; any basis), like curve.tese.
// Teeth (draw.drawMode kDrawCombTeeth): a line of 3·N − 1 segments; vertex i belongs to tooth
// floor(i / 3) at t = tooth / (N − 1), at its tip when i mod 3 = 1, else at its base, so the
// segments draw base → tip, back, and the chord to the next tooth's base.
// Envelope (kDrawCombEnvelope): 64 segments, every vertex a tip.
// A tip is p − frame.comb.x · κN: outward from the centre of curvature, κN from the curve's first
// and second derivatives by core/gpu/curvature_math.h (the CPU's formula, one home).
#include "common.glsl"
#include "core/gpu/curvature_math.h"
#include "core/gpu/rational_math.h"

layout(isolines, equal_spacing) in;
layout(location = 0) out vec4 outColor;

// Control points arrive homogeneous (core/gpu/rational_math.h: w·P, w − 1): the sums below are
// homogeneous and the quotient rule gives the rational curve's derivatives.
vec4 cp(int s) { return gl_in[s].gl_Position; }

// Weights of the draw's basis at t and their first and second derivatives.
void basisAt(float t, out vec4 w, out vec4 d1, out vec4 d2) {
    if (draw.basisKind == kBasisBezier) {
        float s = 1.0 - t;
        w = bernstein3(t, s);
        d1 = bernstein3D1(t, s);
        d2 = bernstein3D2(t, s);
        return;
    }
    w = draw.basis * vec4(t * t * t, t * t, t, 1.0);
    d1 = draw.basis * vec4(3.0 * t * t, 2.0 * t, 1.0, 0.0);
    d2 = draw.basis * vec4(6.0 * t, 2.0, 0.0, 0.0);
}

void main() {
    float teeth = clamp(frame.comb.y, 2.0, 21.0);
    float t = gl_TessCoord.x;
    bool tip = true;
    if (draw.drawMode == kDrawCombTeeth) {
        float i = round(gl_TessCoord.x * (3.0 * teeth - 1.0));
        float tooth = floor(i / 3.0);
        tip = i - 3.0 * tooth == 1.0;
        t = tooth / (teeth - 1.0);
    }
    vec4 w, d, dd;
    basisAt(t, w, d, dd);
    vec4 p = vec4(0.0), d1 = vec4(0.0), d2 = vec4(0.0);
#ifdef ISOCURVES
    float n = ceil(gl_TessLevelOuter[0]);
    float k = round(gl_TessCoord.y * n);
    vec4 wa, da, dda;
    basisAt(n > 1.0 ? k / (n - 1.0) : 0.0, wa, da, dda);
    if ((draw.isoDirection & 1u) == 0u) {  // along u: row i weighs wa[i] (v fixed), columns w(t)
        for (int i = 0; i < 4; ++i) {
            vec4 c0 = cp(i * 4), c1 = cp(i * 4 + 1), c2 = cp(i * 4 + 2), c3 = cp(i * 4 + 3);
            p += wa[i] * (w.x * c0 + w.y * c1 + w.z * c2 + w.w * c3);
            d1 += wa[i] * (d.x * c0 + d.y * c1 + d.z * c2 + d.w * c3);
            d2 += wa[i] * (dd.x * c0 + dd.y * c1 + dd.z * c2 + dd.w * c3);
        }
    } else {  // along v: column j weighs wa[j] (u fixed), rows w(t)
        for (int i = 0; i < 4; ++i) {
            vec4 row = wa.x * cp(i * 4) + wa.y * cp(i * 4 + 1) + wa.z * cp(i * 4 + 2) + wa.w * cp(i * 4 + 3);
            p += w[i] * row;
            d1 += d[i] * row;
            d2 += dd[i] * row;
        }
    }
#else
    p = w.x * cp(0) + w.y * cp(1) + w.z * cp(2) + w.w * cp(3);
    d1 = d.x * cp(0) + d.y * cp(1) + d.z * cp(2) + d.w * cp(3);
    d2 = dd.x * cp(0) + dd.y * cp(1) + dd.z * cp(2) + dd.w * cp(3);
#endif
    vec3 q = rationalPoint(p);
    vec3 e1 = rationalDerivative(p, d1, q);
    vec3 e2 = rationalSecondDerivative(p, d1, d1, d2, q, e1, e1);
    if (tip) q -= frame.comb.x * curveCurvatureVector(e1, e2);
    gl_Position = frame.viewProj * vec4(q, 1.0);
    gl_Position.z -= 2e-6 * gl_Position.w;  // in front of the surface the curve lies on
    outColor = draw.color;
}

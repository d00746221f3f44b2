#version 450
#extension GL_GOOGLE_include_directive : require
// The isoline domain (DESIGN §3): gl_TessCoord.x runs along a line in steps the segments level
// made, gl_TessCoord.y = k / lines says which line. Curves: the cubic Bézier of the 4 points at x.
// -DISOCURVES: line k of n is the window's isoparametric curve at k / (n - 1), so the first and the
// last lie on its boundary (n = 2: the boundary curves; n = 1: the u0 or v0 boundary), along u or,
// with draw.isoDirection = 1, along v; any basis (draw.basis).
#include "common.glsl"
#include "core/gpu/rational_math.h"

layout(isolines, SPACING) in;
layout(location = 0) out vec4 outColor;

// Control points arrive homogeneous (core/gpu/rational_math.h: w·P, w − 1); rational curves and windows
// sum them and divide.
vec4 cph(int s) { return gl_in[s].gl_Position; }

vec4 weights(float t) {
    float s = 1.0 - t;
    return draw.basisKind == kBasisBezier ? bernstein3(t, s) : draw.basis * vec4(t * t * t, t * t, t, 1.0);
}

void main() {
    float t = gl_TessCoord.x;
#ifdef ISOCURVES
    float n = ceil(gl_TessLevelOuter[0]);
    float k = round(gl_TessCoord.y * n);
    float across = n > 1.0 ? k / (n - 1.0) : 0.0;
    bool alongV = draw.isoDirection == 1u;
    vec4 wu = weights(alongV ? across : t);  // along a row of the net (slots i*4 + 0..3)
    vec4 wv = weights(alongV ? t : across);  // across the rows
    vec4 h = vec4(0.0);
    for (int i = 0; i < 4; ++i)
        h += wv[i] * (wu.x * cph(i * 4) + wu.y * cph(i * 4 + 1) + wu.z * cph(i * 4 + 2) + wu.w * cph(i * 4 + 3));
    vec3 p = rationalPoint(h);
#else
    vec4 w = bernstein3(t, 1.0 - t);
    vec3 p = rationalPoint(w.x * cph(0) + w.y * cph(1) + w.z * cph(2) + w.w * cph(3));
    p = t == 0.0 ? rationalPoint(cph(0)) : (t == 1.0 ? rationalPoint(cph(3)) : p);  // exact ends, like core/eval/bezier_curve.cpp
#endif
    gl_Position = frame.viewProj * vec4(p, 1.0);
    gl_Position.z -= 2e-6 * gl_Position.w;  // in front of the surface the curve lies on
    outColor = draw.color;
}

#version 450
#extension GL_GOOGLE_include_directive : require
// Levels of the isoline domain for curvature combs (shaders/comb.tese), on Bézier curves (4 points)
// and, with -DISOCURVES, on the isocurves of 16-point windows: outer level 0 = lines (a curve: 1;
// the isocurve overlay's lines; a join's curvature graph, draw.isoDirection bit 1: frame.comb.z),
// outer level 1 = 3·teeth − 1 segments for the teeth (base, tip, base per tooth) or 64 for the
// envelope through the tips. Equal spacing: a tooth sits at an exact parameter.
#include "common.glsl"

#ifdef ISOCURVES
layout(vertices = 16) out;
#else
layout(vertices = 4) out;
#endif

void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    if (gl_InvocationID == 0) {
        float teeth = clamp(frame.comb.y, 2.0, 21.0);
#ifdef ISOCURVES
        float lines = (draw.isoDirection & 2u) != 0u ? frame.comb.z : frame.isoline.x;
        gl_TessLevelOuter[0] = clamp(lines, 1.0, 64.0);
#else
        gl_TessLevelOuter[0] = 1.0;
#endif
        gl_TessLevelOuter[1] = draw.drawMode == kDrawCombTeeth ? 3.0 * teeth - 1.0 : 64.0;
    }
}

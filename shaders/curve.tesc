#version 450
#extension GL_GOOGLE_include_directive : require
// Levels of the isoline domain (DESIGN §3) for Bézier curves (4 points) and, with -DISOCURVES, for
// the isocurve overlay of 16-point windows: outer level 0 = lines (the tessellator always rounds it
// up to an integer), outer level 1 = segments per line (under the document's partitioning; pow2 is
// equal spacing with the level rounded up to a power of two here, core/gpu/patch_math.h's roundLevel).
// A curve is one line.
#include "common.glsl"

#ifdef ISOCURVES
layout(vertices = 16) out;
#else
layout(vertices = 4) out;
#endif

void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    if (gl_InvocationID == 0) {
        float segments = roundLevel(max(frame.isoline.y, 1.0), frame.modes.x);
#ifdef ISOCURVES
        gl_TessLevelOuter[0] = clamp(frame.isoline.x, 1.0, 64.0);
#else
        gl_TessLevelOuter[0] = 1.0;
#endif
        gl_TessLevelOuter[1] = segments;
    }
}

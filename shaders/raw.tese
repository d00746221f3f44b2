#version 450
#extension GL_GOOGLE_include_directive : require
// The raw tessellator's reference (`patchwork bench`, with raw.tesc): a bilinear position of the
// four corner points and a constant normal, equal spacing, the lean varyings surface.frag reads.
#include "common.glsl"
#include "core/gpu/rational_math.h"
layout(quads, equal_spacing, ccw) in;
layout(location = 1) out vec3 outNormal;
layout(location = 5) flat out float outCulled;
layout(location = 6) out float outWire;
void main() {
    float u = gl_TessCoord.x, v = gl_TessCoord.y;
    vec3 p = mix(mix(rationalPoint(gl_in[0].gl_Position), rationalPoint(gl_in[3].gl_Position), u),
                 mix(rationalPoint(gl_in[12].gl_Position), rationalPoint(gl_in[15].gl_Position), u), v);
    outNormal = vec3(0.0, 0.0, 1.0);
    outCulled = 0.0;
    outWire = 1.0;
    gl_Position = frame.viewProj * vec4(p, 1.0);
}

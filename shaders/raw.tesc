#version 450
#extension GL_GOOGLE_include_directive : require
// The raw tessellator's reference (`patchwork bench`): the same 16-point patches at the frame's
// uniform levels with nothing else, so the benchmark can show what the tessellation stages cost
// with trivial shaders against what Patchwork's own shaders add.
#include "common.glsl"
layout(vertices = 16) out;
layout(location = 0) in int inIdx[];
void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    if (gl_InvocationID != 0) return;
    gl_TessLevelOuter[0] = frame.outer.x;
    gl_TessLevelOuter[1] = frame.outer.y;
    gl_TessLevelOuter[2] = frame.outer.z;
    gl_TessLevelOuter[3] = frame.outer.w;
    gl_TessLevelInner[0] = frame.inner.x;
    gl_TessLevelInner[1] = frame.inner.y;
}

#version 450
#extension GL_GOOGLE_include_directive : require
// Domain view: hands the requested levels to the fixed tessellator unchanged (it clamps and rounds
// them by the evaluation shader's partitioning), except pow2, which does not exist in Vulkan and is
// emulated as in surface.tesc: the next power of two of the integer level, with equal spacing.
#include "domain_common.glsl"

layout(vertices = 1) out;

float level(float f) { return dp.inner.z < 0.5 ? f : roundLevel(f, kSpacingPow2); }

void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    for (int e = 0; e < 4; ++e) gl_TessLevelOuter[e] = level(dp.outer[e]);
    gl_TessLevelInner[0] = level(dp.inner.x);
    gl_TessLevelInner[1] = level(dp.inner.y);
}

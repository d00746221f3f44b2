#version 450
#extension GL_GOOGLE_include_directive : require
// A block of Bu x Bv windows of one net (Bu, Bv in 1, 2, 4) that all get the same levels this frame (nu along u, nv along v),
// drawn as one patch (render/scene/merged_blocks.hpp decides which; lavapipe pays per patch, whatever
// its level): levels Bu nu along u and Bv nv along v, so the tessellator makes each window's vertices,
// and the evaluation shader (surface.tese -DMERGED) places each where the window's own patch would
// put it (core/gpu/tess_place.h) and evaluates it on its window. Levels and culling were decided on the CPU from the same formulas.
#include "common.glsl"
layout(vertices = 1) out;
layout(location = 0) in int inBlock[];
layout(location = 4) patch out uvec4 blockPatch;
// binding 6: the blocks of this frame: first window, windows per net row, Bu + 256 Bv, nu + 256 nv.
layout(set = 0, binding = 6, std430) readonly buffer Blocks { uvec4 blocks[]; };
void main() {
    uvec4 b = blocks[uint(inBlock[0])];
    blockPatch = b;
    float alongU = float((b.z & 255u) * (b.w & 255u)), alongV = float((b.z >> 8u) * (b.w >> 8u));
    gl_TessLevelOuter[0] = alongV;  // u0 and u1 run along v; v0 and v1 along u (quad-domain order)
    gl_TessLevelOuter[1] = alongU;
    gl_TessLevelOuter[2] = alongV;
    gl_TessLevelOuter[3] = alongU;
    gl_TessLevelInner[0] = alongU;
    gl_TessLevelInner[1] = alongV;
}

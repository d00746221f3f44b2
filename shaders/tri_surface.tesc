#version 450
#extension GL_GOOGLE_include_directive : require
// Tessellation levels of one cubic Bézier triangle (10 control points, core/eval/bezier_triangle.hpp
// order): three outer levels (edge 0: u = 0, 1: v = 0, 2: w = 0) and one inner, from the uniform
// levels (outer[0..2], inner[0]), a per-triangle override or adaptive (each edge from its own four
// points in canonical order, with the quads' code: crack free against triangles and quads alike);
// back-face and off-screen culling; DESIGN §3 rounding, pow2 emulated. Built with and without
// -DADAPTIVE_AND_CULLING like surface.tesc.
#include "common.glsl"

layout(vertices = 10) out;
layout(location = 0) in int inIdx[];
#include "tess_levels.glsl"
layout(location = 1) patch out float netScalePatch;  // largest extent of the net
// Bit e set: edge e runs from the higher pool index to the lower (evaluate it reversed).
layout(location = 2) patch out uint edgeFlipPatch;
layout(location = 3) patch out float culledPatch;  // 1: culled, drawn greyed for a debug camera (tess_levels.glsl showCulled)

vec3 cp(int s) { return gl_in[s].gl_Position.xyz; }

#ifdef ADAPTIVE_AND_CULLING
// Edge e's level: adaptive (or `centre` when >= 0: measured from the patch centre), raised for the
// height map's detail along it (tess_levels.glsl).
float adaptiveLevel(int e, PatchData pd, float centre) {
    vec3 p[4];
    bool rev = reversedEdge(triEdgeSlot(e, 0), triEdgeSlot(e, 1), triEdgeSlot(e, 2), triEdgeSlot(e, 3));
    for (int k = 0; k < 4; ++k) p[k] = cp(triEdgeSlot(e, rev ? 3 - k : k));
    float level = centre >= 0.0 ? centre : clamp(adaptiveEdgeLevel(p), 1.0, frame.inner.z);
    return raiseForDisplacement(level, p, e, pd);
}

// The centre of the control points (the patch's distance for the far cull).
vec3 netCentre() {
    vec3 c = vec3(0.0);
    for (int i = 0; i < 10; ++i) c += cp(i);
    return c / 10.0;
}

bool offscreen(float margin) {
    for (int k = 0; k < 6; ++k) {
        vec4 plane = frustumPlane(k);
        float pad = margin * length(plane.xyz);
        bool outside = true;
        for (int i = 0; i < 10; ++i) outside = outside && dot(plane, vec4(cp(i), 1.0)) + pad < 0.0;
        if (outside) return true;
    }
    return false;
}

// Conservative normal cone: du x dv is a non-negative combination of the products of the net's
// u-differences b(a+1,b,c) - b(a,b,c+1) and v-differences b(a,b+1,c) - b(a,b,c+1) (a+b+c = 2).
bool backfacing(float margin) {
    if (margin > 0.0) return false;  // a displaced surface may face the eye where the patch does not
    // Slots of (a+1,b,c), (a,b+1,c), (a,b,c+1) for the six (a,b,c) with a+b+c = 2.
    const int su[6] = int[6](0, 1, 2, 3, 4, 5);
    const int sv[6] = int[6](1, 3, 4, 6, 7, 8);
    const int sw[6] = int[6](2, 4, 5, 7, 8, 9);
    vec3 du[6], dv[6];
    for (int i = 0; i < 6; ++i) {
        du[i] = cp(su[i]) - cp(sw[i]);
        dv[i] = cp(sv[i]) - cp(sw[i]);
    }
    for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b) {
            vec3 c = cross(du[a], dv[b]);
            if (dot(c, c) == 0.0) continue;
            for (int q = 0; q < 10; ++q)
                if (dot(c, frame.lodEye.xyz - cp(q)) >= 0.0) return false;
        }
    return true;
}
#endif

void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    if (gl_InvocationID != 0) return;

    vec3 lo = cp(0), hi = cp(0);
    for (int i = 1; i < 10; ++i) { lo = min(lo, cp(i)); hi = max(hi, cp(i)); }
    netScalePatch = max(max(hi.x - lo.x, hi.y - lo.y), max(hi.z - lo.z, 1e-20));
    uint flip = 0u;
    for (int e = 0; e < 3; ++e)
        if (reversedEdge(triEdgeSlot(e, 0), triEdgeSlot(e, 1), triEdgeSlot(e, 2), triEdgeSlot(e, 3))) flip |= 1u << uint(e);
    edgeFlipPatch = flip;
    culledPatch = 0.0;

    // The settings' levels, then the shared-edge rule (core/tess/edge_levels.hpp), as in surface.tesc.
    PatchData pd = patches[draw.patchBase + uint(gl_PrimitiveID)];
    float o[3];
    float in0;
    bool adaptive = false;
    float centreInnerLevel = 0.0;  // > 0: the inner level measured from the centre
#ifdef ADAPTIVE_AND_CULLING
    adaptive = frame.modes.y != kAdaptiveNone;
#endif
    if (!adaptive) {
        o[0] = frame.outer.x; o[1] = frame.outer.y; o[2] = frame.outer.z;
    }
#ifdef ADAPTIVE_AND_CULLING
    else {
        float centre = centreInner() ? centreLevel(netCentre()) : 1.0;  // tess.distanceFrom, as surface.tesc
        for (int e = 0; e < 3; ++e) o[e] = adaptiveLevel(e, pd, centreLevels() ? centre : -1.0);
        if (centreInner()) centreInnerLevel = centre;
    }
#endif
    uint fixedMask = uint(pd.inner.w + 0.5);
    o[0] = sharedEdgeLevel(o[0], pd.outer.x, (fixedMask & 1u) != 0u);
    o[1] = sharedEdgeLevel(o[1], pd.outer.y, (fixedMask & 2u) != 0u);
    o[2] = sharedEdgeLevel(o[2], pd.outer.z, (fixedMask & 4u) != 0u);
    if (pd.inner.z > 0.5) in0 = pd.inner.x;  // the triangle's own inner level
    else if (centreInnerLevel > 0.0) in0 = centreInnerLevel;
    else if (adaptive) in0 = max(o[0], max(o[1], o[2]));
    else in0 = frame.inner.x;
    for (int e = 0; e < 3; ++e) gl_TessLevelOuter[e] = roundLevel(o[e]);
    gl_TessLevelOuter[3] = 0.0;
    gl_TessLevelInner[0] = roundLevel(in0);
    gl_TessLevelInner[1] = 0.0;

#ifdef ADAPTIVE_AND_CULLING
    float margin = displacementMargin(pd);
    bool cull = ((frame.modes.z & kCullOffscreen) != 0u && offscreen(margin)) ||
                ((frame.modes.z & kCullBackFaces) != 0u && backfacing(margin)) || (farCulling() && beyondFar(netCentre()));
    if (cull) {
        if (showCulled()) {
            culledPatch = 1.0;
        } else {
            for (int e = 0; e < 3; ++e) gl_TessLevelOuter[e] = 0.0;
            gl_TessLevelInner[0] = 0.0;
        }
        if (draw.drawMode == kDrawShaded) atomicAdd(counters.culled, 1u);  // once, not again for each overlay
    }
#endif
}

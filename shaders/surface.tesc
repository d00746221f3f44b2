#version 450
#extension GL_GOOGLE_include_directive : require
// Tessellation levels of one 4x4 window: uniform, per-patch override or adaptive (distance, screen,
// orientation); crack-free (an edge's level depends on that edge's control points only, taken in a
// canonical order); back-face and off-screen culling by zero outer levels; DESIGN §3 rounding.
// Built twice: with -DADAPTIVE_AND_CULLING for adaptive levels and culling, and without for uniform
// levels and per-patch overrides only. lavapipe runs every branch whether taken or not, so the
// adaptive and culling code would otherwise cost ~25 ms a frame on 1 024 patches when switched off.
#include "common.glsl"
#include "core/gpu/rational_math.h"
#include "core/gpu/trim_math.h"

layout(vertices = 16) out;
layout(location = 0) in int inIdx[];
#include "tess_levels.glsl"
layout(location = 1) patch out float netScalePatch;  // largest extent of the net, for the evaluation shader
// Bit e set: boundary e (quad-domain order u0, v0, u1, v1) runs from the higher pool index to the
// lower, so the evaluation shader evaluates it reversed (canonical direction, bit-identical seams).
layout(location = 2) patch out uint edgeFlipPatch;
layout(location = 3) patch out float culledPatch;  // 1: culled, drawn greyed for a debug camera (tess_levels.glsl showCulled)

// Net slot of the k-th point of the row/column that represents edge e (quad-domain order u0,v0,u1,v1).
// Bézier: the boundary row itself; splines: the row the neighbouring window shares (one inside).
int edgeSlot(int e, int k) { return quadEdgeSlot(e, k, draw.basisKind == kBasisBezier ? 0 : 1); }

vec3 cp(int s) { return rationalPoint(gl_in[s].gl_Position); }  // the control point (homogeneous in)

// The edge's four points in canonical order.
void edgePoints(int e, out vec3 p[4]) {
    bool rev = reversedEdge(edgeSlot(e, 0), edgeSlot(e, 1), edgeSlot(e, 2), edgeSlot(e, 3));
    for (int k = 0; k < 4; ++k) p[k] = cp(edgeSlot(e, rev ? 3 - k : k));
}


#ifdef ADAPTIVE_AND_CULLING
// The centre of the control points (the patch's distance for the far cull).
vec3 netCentre() {
    vec3 c = vec3(0.0);
    for (int i = 0; i < 16; ++i) c += cp(i);
    return c / 16.0;
}

// Per control point: bit k set when it lies outside frustum plane k by more than the margin (the
// largest displacement: the displaced surface stays within it of the convex hull). Each invocation
// tests its own point, so the 96 plane tests run 16 wide instead of in invocation 0 alone (on an
// H100 the serial loop cost 7 % of grid128's frame: 6.81 -> 6.34 ms).
layout(location = 4) out uint outsidePlanes[];

uint outsideBits(vec3 q, float margin) {
    uint bits = 0u;
    for (int k = 0; k < 6; ++k) {
        vec4 plane = frustumPlane(k);
        if (dot(plane, vec4(q, 1.0)) + margin * length(plane.xyz) < 0.0) bits |= 1u << uint(k);
    }
    return bits;
}

// Off screen when every control point is outside one and the same plane (after the barrier).
bool offscreen() {
    uint everyPoint = 63u;
    for (int i = 0; i < 16; ++i) everyPoint &= outsidePlanes[i];
    return everyPoint != 0u;
}

// Conservative normal cone: du x dv is a non-negative combination of the products of the u- and
// v-differences of the net (Bézier and B-spline weights are non-negative). If every such product
// faces away from the eye at every control point (hence over the convex hull), the patch is back-facing.
bool backfacing(float margin) {
    if (draw.basisKind == kBasisCatmullRom) return false;  // Catmull-Rom weights change sign
    if (margin > 0.0) return false;  // a displaced surface may face the eye where the patch does not
    vec3 du[12], dv[12];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
            du[i * 3 + j] = cp(i * 4 + j + 1) - cp(i * 4 + j);
            dv[j * 4 + i] = cp((j + 1) * 4 + i) - cp(j * 4 + i);
        }
    for (int a = 0; a < 12; ++a)
        for (int b = 0; b < 12; ++b) {
            vec3 c = cross(du[a], dv[b]);
            if (dot(c, c) == 0.0) continue;
            for (int q = 0; q < 16; ++q)
                if (dot(c, frame.lodEye.xyz - cp(q)) >= 0.0) return false;
        }
    return true;
}

#endif

void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
#ifdef ADAPTIVE_AND_CULLING
    outsidePlanes[gl_InvocationID] =
        (frame.modes.z & kCullOffscreen) != 0u
            ? outsideBits(cp(gl_InvocationID), displacementMargin(patches[draw.patchBase + uint(gl_PrimitiveID)]))
            : 0u;
    barrier();
#endif
    if (gl_InvocationID != 0) return;

    vec3 lo = cp(0), hi = cp(0);
    for (int i = 1; i < 16; ++i) { lo = min(lo, cp(i)); hi = max(hi, cp(i)); }
    netScalePatch = max(max(hi.x - lo.x, hi.y - lo.y), max(hi.z - lo.z, 1e-20));
    uint flip = 0u;  // the Bézier boundary rows (depth 0), whatever the basis
    for (int e = 0; e < 4; ++e)
        if (reversedEdge(quadEdgeSlot(e, 0, 0), quadEdgeSlot(e, 1, 0), quadEdgeSlot(e, 2, 0), quadEdgeSlot(e, 3, 0)))
            flip |= 1u << uint(e);
    edgeFlipPatch = flip;
    culledPatch = 0.0;

    // The settings' levels (uniform or adaptive), then the shared-edge rule: an edge whose windows
    // all have their own levels takes the largest of those, any other edge at least that much
    // (core/tess/edge_levels.hpp), so both sides of a shared edge agree.
    PatchData pd = patches[draw.patchBase + uint(gl_PrimitiveID)];
    float o[4];
    float in0, in1;
    bool adaptive = false;
    float centreInnerLevel = 0.0;  // > 0: the inner levels measured from the centre
#ifdef ADAPTIVE_AND_CULLING
    adaptive = frame.modes.y != kAdaptiveNone;
#endif
    if (!adaptive) {
        o[0] = frame.outer.x; o[1] = frame.outer.y; o[2] = frame.outer.z; o[3] = frame.outer.w;
    }
#ifdef ADAPTIVE_AND_CULLING
    else {
        // Distance from the patch centre (tess.distanceFrom): the first notes' one level per patch,
        // or the terrain notes' inner levels; otherwise each edge from its own midpoint.
        float centre = centreInner() ? centreLevel(netCentre()) : 1.0;
        for (int e = 0; e < 4; ++e) {
            vec3 p[4];
            edgePoints(e, p);
            float level = centreLevels() ? centre : clamp(adaptiveEdgeLevel(p), 1.0, frame.inner.z);
            o[e] = raiseForDisplacement(level, p, e, pd);
        }
        if (centreInner()) centreInnerLevel = centre;
    }
#endif
    uint fixedMask = uint(pd.inner.w + 0.5);
    o[0] = sharedEdgeLevel(o[0], pd.outer.x, (fixedMask & 1u) != 0u);
    o[1] = sharedEdgeLevel(o[1], pd.outer.y, (fixedMask & 2u) != 0u);
    o[2] = sharedEdgeLevel(o[2], pd.outer.z, (fixedMask & 4u) != 0u);
    o[3] = sharedEdgeLevel(o[3], pd.outer.w, (fixedMask & 8u) != 0u);
    if (pd.inner.z > 0.5) {  // the window's own inner levels
        in0 = pd.inner.x; in1 = pd.inner.y;
    } else if (centreInnerLevel > 0.0) {
        in0 = centreInnerLevel;
        in1 = centreInnerLevel;
    } else if (adaptive) {
        in0 = max(o[1], o[3]);  // inner[0] subdivides along u, like the v0 and v1 edges
        in1 = max(o[0], o[2]);
    } else {
        in0 = frame.inner.x; in1 = frame.inner.y;
    }
    for (int e = 0; e < 4; ++e) gl_TessLevelOuter[e] = roundLevel(o[e]);
    gl_TessLevelInner[0] = roundLevel(in0);
    gl_TessLevelInner[1] = roundLevel(in1);
    if ((pd.trim.z & kTrimAllGone) != 0u) {  // wholly trimmed away (core/gpu/trim_math.h): not tessellated
        for (int e = 0; e < 4; ++e) gl_TessLevelOuter[e] = 0.0;
        gl_TessLevelInner[0] = 0.0;
        gl_TessLevelInner[1] = 0.0;
    }

#ifdef ADAPTIVE_AND_CULLING
    float margin = displacementMargin(pd);
    bool cull = ((frame.modes.z & kCullOffscreen) != 0u && offscreen()) ||
                ((frame.modes.z & kCullBackFaces) != 0u && backfacing(margin)) || (farCulling() && beyondFar(netCentre()));
    if (cull) {
        if (showCulled()) {
            culledPatch = 1.0;
        } else {
            for (int e = 0; e < 4; ++e) gl_TessLevelOuter[e] = 0.0;
            gl_TessLevelInner[0] = 0.0;
            gl_TessLevelInner[1] = 0.0;
        }
        if (draw.drawMode == kDrawShaded) atomicAdd(counters.culled, 1u);  // once, not again for each overlay
    }
#endif
}

#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates a cubic Bézier triangle at gl_TessCoord = (u, v, w) (core/eval/bezier_triangle.cpp): the
// Bernstein sum for the position, the quadratic difference sums for ∂p/∂u and ∂p/∂v, the normal
// du × dv with a fallback a small step towards the centroid where that vanishes (collapsed edges),
// and boundary points from the edge's four points only, in canonical order, with the same code as
// the quads' boundaries (bit-identical shared edges). One variant per partitioning (-DSPACING=),
// lean (normal), -DPOINT_MODE (the normal-vector overlay) or -DFULL_VARYINGS (UV = (u, v), patch id, Gaussian and mean curvature from the
// second derivatives when a curvature shading is on).
#include "common.glsl"
#include "core/gpu/curvature_math.h"
#ifdef DISPLACE
#include "displacement.glsl"  // -DDISPLACE: moved along the normal by the height map
#endif

#ifdef POINT_MODE
layout(triangles, SPACING, ccw, point_mode) in;  // the normal-vector overlay
#else
layout(triangles, SPACING, ccw) in;
#endif

layout(location = 1) patch in float netScalePatch;
layout(location = 2) patch in uint edgeFlipPatch;  // bit e: evaluate edge e reversed
layout(location = 3) patch in float culledPatch;  // 1: culled, drawn greyed for a debug camera (control shader)
#ifdef CAPTURE  // export as displayed: position, normal, UV and patch id into transform feedback (36 bytes a vertex)
layout(xfb_buffer = 0, xfb_stride = 36) out;
#define XFB(offset) , xfb_buffer = 0, xfb_offset = offset
#else
#define XFB(offset)
#endif
#if defined(POINT_MODE) || defined(CAPTURE)
layout(location = 0 XFB(0)) out vec3 outPos;  // the normal-vector overlay's base point; the captured position
#endif
layout(location = 1 XFB(12)) out vec3 outNormal;
layout(location = 5) flat out float outCulled;
layout(location = 6) out float outWire;  // the wireframe's opacity here (core/gpu/patch_math.h wireOpacity)
#ifdef FULL_VARYINGS
layout(location = 2 XFB(24)) out vec2 outUV;
layout(location = 3 XFB(32)) flat out uint outPatch;
layout(location = 4) out vec2 outCurv;
#endif

vec3 cp(int s) { return gl_in[s].gl_Position.xyz; }

// ∂p/∂u and ∂p/∂v (w = 1 - u - v) from the quadratic Bernstein weights.
void derivs(float u, float v, float w, out vec3 du, out vec3 dv) {
    float B200 = u * u, B020 = v * v, B002 = w * w;
    float B110 = 2.0 * u * v, B101 = 2.0 * u * w, B011 = 2.0 * v * w;
    // (a,b,c) -> u-point b(a+1,b,c), v-point b(a,b+1,c), w-point b(a,b,c+1)
    du = 3.0 * (B200 * (cp(0) - cp(2)) + B110 * (cp(1) - cp(4)) + B101 * (cp(2) - cp(5)) +
                B020 * (cp(3) - cp(7)) + B011 * (cp(4) - cp(8)) + B002 * (cp(5) - cp(9)));
    dv = 3.0 * (B200 * (cp(1) - cp(2)) + B110 * (cp(3) - cp(4)) + B101 * (cp(4) - cp(5)) +
                B020 * (cp(6) - cp(7)) + B011 * (cp(7) - cp(8)) + B002 * (cp(8) - cp(9)));
}

#ifdef FULL_VARYINGS
// ∂²p/∂u², ∂²p/∂u∂v, ∂²p/∂v² (w = 1 - u - v) from the linear Bernstein weights u, v, w.
void secondDerivs(float u, float v, float w, out vec3 duu, out vec3 duv, out vec3 dvv) {
    duu = 6.0 * (u * (cp(0) - 2.0 * cp(2) + cp(5)) + v * (cp(1) - 2.0 * cp(4) + cp(8)) + w * (cp(2) - 2.0 * cp(5) + cp(9)));
    duv = 6.0 * (u * (cp(1) - cp(2) - cp(4) + cp(5)) + v * (cp(3) - cp(4) - cp(7) + cp(8)) + w * (cp(4) - cp(5) - cp(8) + cp(9)));
    dvv = 6.0 * (u * (cp(3) - 2.0 * cp(4) + cp(5)) + v * (cp(6) - 2.0 * cp(7) + cp(8)) + w * (cp(7) - 2.0 * cp(8) + cp(9)));
}
#endif

vec3 position(float u, float v, float w) {
    float u2 = u * u, v2 = v * v, w2 = w * w;
    return u2 * u * cp(0) + 3.0 * u2 * v * cp(1) + 3.0 * u2 * w * cp(2) + 3.0 * u * v2 * cp(3) +
           6.0 * u * v * w * cp(4) + 3.0 * u * w2 * cp(5) + v2 * v * cp(6) + 3.0 * v2 * w * cp(7) +
           3.0 * v * w2 * cp(8) + w2 * w * cp(9);
}

// A boundary point from edge e's four points only, lower pool index first; t runs along the edge
// in its own direction (edge 0: slots 6→9, 1: 9→0, 2: 0→6). The quads' function (surface.tese).
vec3 boundaryPoint(int e, float t) {
    bool rev = (edgeFlipPatch & (1u << uint(e))) != 0u;
    vec3 q0 = e == 0 ? cp(6) : (e == 1 ? cp(9) : cp(0));
    vec3 q1 = e == 0 ? cp(7) : (e == 1 ? cp(5) : cp(1));
    vec3 q2 = e == 0 ? cp(8) : (e == 1 ? cp(2) : cp(3));
    vec3 q3 = e == 0 ? cp(9) : (e == 1 ? cp(0) : cp(6));
    return canonicalBoundaryPoint(q0, q1, q2, q3, t, rev);
}

void main() {
    float u = gl_TessCoord.x, v = gl_TessCoord.y, w = gl_TessCoord.z;
    vec3 du, dv;
    derivs(u, v, w, du, dv);
    vec3 p = position(u, v, w);
    if (u == 0.0) p = boundaryPoint(0, w);
    else if (v == 0.0) p = boundaryPoint(1, u);
    else if (w == 0.0) p = boundaryPoint(2, v);

    float s2 = netScalePatch * netScalePatch;
    vec3 n = cross(du, dv);
    float len2 = dot(n, n);
    if (!(len2 > 1e-10 * s2 * s2)) {
        // Collapsed edge or parallel corner tangents: the tangent plane a small step inside.
        const float k = 0.02;
        vec3 eu, ev;
        derivs(u + (1.0 / 3.0 - u) * k, v + (1.0 / 3.0 - v) * k, w + (1.0 / 3.0 - w) * k, eu, ev);
        n = cross(eu, ev);
        len2 = dot(n, n);
    }
    n = len2 > 0.0 ? n * inversesqrt(len2) : vec3(0.0, 0.0, 1.0);
#ifdef DISPLACE
    displaceSurface(p, n, du, dv, vec2(u, v), patches[draw.patchBase + uint(gl_PrimitiveID)]);
#endif

#if defined(POINT_MODE) || defined(CAPTURE)
    outPos = p;
#endif
    outNormal = n;
    outCulled = culledPatch;
    outWire = draw.drawMode != kDrawFlatColour
                  ? 1.0
                  : wireOpacity(segmentSpan(segmentPixels(p, du, gl_TessLevelInner[0], frame.viewProj, frame.viewport.xy),
                                            segmentPixels(p, dv, gl_TessLevelInner[0], frame.viewProj, frame.viewport.xy)));
#ifdef FULL_VARYINGS
    outUV = vec2(u, v);
    outPatch = draw.patchBase + uint(gl_PrimitiveID);
    // Gaussian and mean curvature from the fundamental forms (curvature shading only).
    vec2 curv = vec2(0.0);
    if (frame.modes.w == kShadingGaussCurvature || frame.modes.w == kShadingMeanCurvature) {
        vec3 duu, duv, dvv;
        secondDerivs(u, v, w, duu, duv, dvv);
        curv = gaussMeanCurvature(du, dv, duu, duv, dvv, n);
    } else if (frame.modes.w == kShadingLevel) {  // the level the control shader chose for this triangle
        curv = vec2(gl_TessLevelInner[0], 0.0);
    }
    outCurv = curv;
#endif
    gl_Position = frame.viewProj * vec4(p, 1.0);
}

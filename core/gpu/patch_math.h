// Patch math that the C++ code and the GLSL shaders share, written once (OpenSubdiv's
// patchBasisCommon.h is the model; core/gpu/glsl_cpp.h says how one header serves both languages):
// the named modes the shaders receive, the control-point slots of each boundary edge, the edge's
// canonical direction, cubic Bernstein weights, the control shader's level rounding and the
// adaptive edge level. tests/render_test_patch_math.cpp runs these functions on the GPU and on the
// CPU and holds them equal.
#ifndef PW_PATCH_MATH_H
#define PW_PATCH_MATH_H

#include "core/gpu/glsl_cpp.h"

PW_BEGIN_NAMESPACE

// Partitioning (core's Spacing has the same values).
PW_CONST uint kSpacingEqual = 0u;
PW_CONST uint kSpacingFractionalOdd = 1u;
PW_CONST uint kSpacingFractionalEven = 2u;
PW_CONST uint kSpacingPow2 = 3u;  // emulated: next power of two, then equal spacing

// Adaptive tessellation (core's AdaptiveMode).
PW_CONST uint kAdaptiveNone = 0u;
PW_CONST uint kAdaptiveDistance = 1u;
PW_CONST uint kAdaptiveScreen = 2u;
PW_CONST uint kAdaptiveOrientation = 3u;

// Distance mode's curve (core's DistanceCurve) and where the distance is measured (core's DistanceFrom).
PW_CONST uint kCurveLinear = 0u;           // maxLevel at d0 or nearer, 0 at d1 or farther (the first notes)
PW_CONST uint kCurvePow2 = 1u;             // 2^mix(near, far exponent, saturate((d - d0) / (d1 - d0))) (the terrain notes)
PW_CONST uint kFromEdges = 0u;             // each edge from its own midpoint, inner the larger opposite edge: crack-free
PW_CONST uint kFromCentre = 1u;            // all six levels from the patch centre (the first notes): neighbours may disagree
PW_CONST uint kFromEdgesInnerCentre = 2u;  // edges from their midpoints, inner from the centre (the terrain notes)

// Culling bits.
PW_CONST uint kCullBackFaces = 1u;
PW_CONST uint kCullOffscreen = 2u;
PW_CONST uint kKeepHeightLevels = 8u;  // the height map's detail does not raise edge levels (tess.heightDetail off)
PW_CONST uint kCullFar = 4u;           // distance mode: a patch centred at or beyond the far distance (the notes' factor 0)

// Shading (core's ShadingMode).
PW_CONST uint kShadingLit = 0u;
PW_CONST uint kShadingNormal = 1u;
PW_CONST uint kShadingPatchId = 2u;
PW_CONST uint kShadingUvChecker = 3u;
PW_CONST uint kShadingZebra = 4u;
PW_CONST uint kShadingGaussCurvature = 5u;
PW_CONST uint kShadingMeanCurvature = 6u;
PW_CONST uint kShadingLevel = 7u;  // the tessellation level (core/gpu/level_colour.h)

// Basis of a 4x4 window (core's Basis).
PW_CONST uint kBasisBezier = 0u;
PW_CONST uint kBasisBSpline = 1u;
PW_CONST uint kBasisCatmullRom = 2u;

// What a draw draws.
PW_CONST uint kDrawShaded = 0u;        // the lit surface
PW_CONST uint kDrawFlatColour = 1u;    // one colour (wireframe, isocurves, cage)
PW_CONST uint kDrawPlainMesh = 2u;     // a pre-tessellated mesh (the benchmark's reference)
PW_CONST uint kDrawGridPoints = 3u;    // the control points as dots
PW_CONST uint kDrawCombTeeth = 4u;     // curvature comb teeth (shaders/comb.tese)
PW_CONST uint kDrawCombEnvelope = 5u;  // the line through the comb teeth's tips

PW_CONST uint kNoPoint = 0xffffffffu;  // no hovered or selected point
PW_CONST float kMaxTessLevel = 64.0f;  // Vulkan's guaranteed maxTessellationGenerationLevel

// Slot (row * 4 + column) in a 4x4 net of the k-th point of boundary e (quad-domain order
// u0, v0, u1, v1; k along the edge), `depth` rows inside: 0 the boundary row itself, 1 the row
// next to it (a spline window's shared boundary, or the tangent row of a join).
PW_FN int quadEdgeSlot(int e, int k, int depth) {
    if (e == 0) return k * 4 + depth;
    if (e == 1) return depth * 4 + k;
    if (e == 2) return k * 4 + 3 - depth;
    return (3 - depth) * 4 + k;
}

// Slot in a cubic Bézier triangle's ten points (core/eval/bezier_triangle.hpp order) of the k-th point
// of edge e: 0 (u = 0) = 6 7 8 9, 1 (v = 0) = 9 5 2 0, 2 (w = 0) = 0 1 3 6.
PW_FN int triEdgeSlot(int e, int k) {
    if (e == 0) return 6 + k;
    if (e == 1) return (3 - k) * (6 - k) / 2;
    return k * (k + 1) / 2;
}

// True when an edge through pool indices i0 i1 i2 i3 runs against its canonical direction: read
// backwards, the indices are lexicographically smaller. Both patches of a shared edge then walk it
// the same way, so its points and levels come out bit-identical (watertight seams, DESIGN §2).
PW_FN bool edgeReversed(uint i0, uint i1, uint i2, uint i3) {
    if (i0 != i3) return i3 < i0;
    return i2 < i1;
}

// Cubic Bernstein weights and their first and second derivatives at t, with s = 1 - t passed
// separately (a caller can give s exactly, e.g. (n - k) / n).
// @teach{ the cubic Bernstein weights B_0..B_3 at t (s = 1 - t)
PW_REAL_FN PW_REAL_VEC4 bernstein3(PW_REAL t, PW_REAL s) {
    return PW_REAL_VEC4(s * s * s, PW_REAL(3) * t * s * s, PW_REAL(3) * t * t * s, t * t * t);
}
// @teach}
PW_REAL_FN PW_REAL_VEC4 bernstein3D1(PW_REAL t, PW_REAL s) {
    return PW_REAL_VEC4(PW_REAL(-3) * s * s, PW_REAL(3) * s * s - PW_REAL(6) * t * s, PW_REAL(6) * t * s - PW_REAL(3) * t * t,
                        PW_REAL(3) * t * t);
}
PW_REAL_FN PW_REAL_VEC4 bernstein3D2(PW_REAL t, PW_REAL s) {
    return PW_REAL_VEC4(PW_REAL(6) * s, PW_REAL(6) * t - PW_REAL(12) * s, PW_REAL(6) * s - PW_REAL(12) * t, PW_REAL(6) * t);
}

// The point at t of the cubic Bézier boundary q0 q1 q2 q3 (t along the edge as this patch walks it),
// computed from the end the canonical direction starts at when `reversed`: every patch sharing the
// edge, quad or triangle, gets the same bits there (no cracks; DESIGN §2).
PW_FN vec3 canonicalBoundaryPoint(vec3 q0, vec3 q1, vec3 q2, vec3 q3, float t, bool reversed) {
    vec3 p0 = reversed ? q3 : q0, p1 = reversed ? q2 : q1, p2 = reversed ? q1 : q2, p3 = reversed ? q0 : q3;
    PW_PRECISE float tc = reversed ? 1.0f - t : t;
    PW_PRECISE float sc = 1.0f - tc;
    PW_PRECISE vec4 w = bernstein3(tc, sc);
    PW_PRECISE vec3 r = w.x * p0 + w.y * p1 + w.z * p2 + w.w * p3;
    return r;
}

// The same for homogeneous points (core/gpu/rational_math.h: w·P, w − 1), the sum still homogeneous;
// rationalPoint() of it is the rational boundary's point, and for weights 1 the same bits as above.
PW_FN vec4 canonicalBoundaryPointH(vec4 q0, vec4 q1, vec4 q2, vec4 q3, float t, bool reversed) {
    vec4 p0 = reversed ? q3 : q0, p1 = reversed ? q2 : q1, p2 = reversed ? q1 : q2, p3 = reversed ? q0 : q3;
    PW_PRECISE float tc = reversed ? 1.0f - t : t;
    PW_PRECISE float sc = 1.0f - tc;
    PW_PRECISE vec4 w = bernstein3(tc, sc);
    PW_PRECISE vec4 r = w.x * p0 + w.y * p1 + w.z * p2 + w.w * p3;
    return r;
}

// The outer level of an edge under the shared-edge rule (core/tess/edge_levels.hpp): `stored` as is when
// the edge's level is fixed (every window on it has its own levels), else the level the settings
// give (`computed`, the same on both sides) raised to `stored` (the windows' largest own level).
PW_FN float sharedEdgeLevel(float computed, float stored, bool fixedLevel) { return fixedLevel ? stored : max(computed, stored); }

// The level a control shader hands the tessellator for requested level f (DESIGN §3): equal ceil(f)
// in [1, 64]; fractional_odd f in [1, 63]; fractional_even f in [2, 64] (the tessellator rounds
// those); pow2 the next power of two of ceil(f) in [1, 64]. NaN counts as 1.
PW_FN float roundLevel(float f, uint spacing) {
    if (!(f == f)) f = 1.0f;
    if (spacing == kSpacingEqual) return clamp(ceil(f), 1.0f, kMaxTessLevel);
    if (spacing == kSpacingFractionalOdd) return clamp(f, 1.0f, kMaxTessLevel - 1.0f);
    if (spacing == kSpacingFractionalEven) return clamp(f, 2.0f, kMaxTessLevel);
    float c = clamp(ceil(f), 1.0f, kMaxTessLevel);
    return clamp(exp2(ceil(log2(c) - 1e-4f)), 1.0f, kMaxTessLevel);
}

// Point p in pixels of a viewport of size `viewport` (Vulkan NDC); `behind` when at or behind the eye.
PW_FN vec2 toPixels(vec3 p, mat4 viewProj, vec2 viewport, PW_OUT(bool) behind) {
    vec4 c = viewProj * vec4(p, 1.0f);
    behind = c.w <= 1e-6f;
    return (vec2(c.x, c.y) / max(c.w, 1e-6f) * 0.5f + 0.5f) * viewport;
}

// Distance mode's level (before clamping and rounding) at distance d: linear, maxLevel at d0 or
// nearer and 0 at d1 or farther (64 saturate((d1 - d) / (d1 - d0)), the first notes); pow2,
// 2^lerp(exps.x, exps.y, s) with s = saturate((d - d0) / (d1 - d0)) (the terrain notes' 2^lerp(20, 4, s)).
PW_FN float distanceLevel(float d, float maxLevel, float d0, float d1, uint curve, vec2 exps) {
    if (curve == kCurvePow2) return exp2(mix(exps.x, exps.y, clamp((d - d0) / max(d1 - d0, 1e-6f), 0.0f, 1.0f)));
    return maxLevel * clamp((d1 - d) / max(d1 - d0, 1e-6f), 0.0f, 1.0f);
}

// Adaptive level (before rounding) of one boundary curve from its four control points in
// canonical order, so a neighbour sharing the curve gets the same value and no crack opens.
// distance: distanceLevel at the distance of the curve's chord midpoint; screen: the control
// polygon's length in pixels over `targetPx`; orientation: edges whose bend is seen side-on get more.
PW_FN float adaptiveEdgeLevel(vec3 p0, vec3 p1, vec3 p2, vec3 p3, uint mode, float maxLevel, vec3 eye, float d0, float d1, uint curve,
                              vec2 exps, mat4 viewProj, vec2 viewport, float targetPx) {
    if (mode == kAdaptiveDistance) {
        PW_PRECISE vec3 mid = 0.5f * (p0 + p3);
        return distanceLevel(distance(eye, mid), maxLevel, d0, d1, curve, exps);
    }
    if (mode == kAdaptiveScreen) {
        bool b0, b1, b2, b3;
        vec2 s0 = toPixels(p0, viewProj, viewport, b0), s1 = toPixels(p1, viewProj, viewport, b1);
        vec2 s2 = toPixels(p2, viewProj, viewport, b2), s3 = toPixels(p3, viewProj, viewport, b3);
        if (b0 || b1 || b2 || b3) return maxLevel;
        PW_PRECISE float len = length(s1 - s0) + length(s2 - s1) + length(s3 - s2);
        return len / max(targetPx, 0.5f);
    }
    vec3 mid = 0.5f * (p0 + p3);
    vec3 vdir = normalize(mid - eye);
    vec3 bend = (p1 + p2) - (p0 + p3);
    vec3 side = bend - dot(bend, vdir) * vdir;
    float chord = max(distance(p0, p3), 1e-6f);
    return maxLevel * clamp(2.0f * length(side) / chord, 0.0f, 1.0f);
}

// Plane k (0..5: left, right, top, bottom, near, far) of the frustum of view-projection m, in world
// space: a point p is inside when dot(plane, vec4(p, 1)) >= 0 (Vulkan clip space, depth 0..w).
PW_FN vec4 frustumPlane(mat4 m, int k) {
    vec4 rx = vec4(m[0][0], m[1][0], m[2][0], m[3][0]), ry = vec4(m[0][1], m[1][1], m[2][1], m[3][1]);
    vec4 rz = vec4(m[0][2], m[1][2], m[2][2], m[3][2]), rw = vec4(m[0][3], m[1][3], m[2][3], m[3][3]);
    return k == 0 ? rw + rx : k == 1 ? rw - rx : k == 2 ? rw + ry : k == 3 ? rw - ry : k == 4 ? rz : rw - rz;
}

// Pixels that one of `level` segments along the derivative d (a whole parameter's change) at p spans
// on a viewport of `viewport` pixels: the projection's derivative in that direction, over the level.
// Behind the eye: large (no fading).
PW_FN float segmentPixels(vec3 p, vec3 d, float level, mat4 viewProj, vec2 viewport) {
    vec4 c = viewProj * vec4(p, 1.0f);
    vec4 dc = viewProj * vec4(d, 0.0f);
    if (c.w <= 1e-6f) return 1e6f;
    vec2 dn = (vec2(dc.x, dc.y) * c.w - vec2(c.x, c.y) * dc.w) / (c.w * c.w);
    return length(dn * 0.5f * viewport) / max(level, 1.0f);
}

// The wireframe's opacity where its segments span `px` pixels: opaque from 8 px, then in proportion.
// A pixel is crossed by about 3 / px lines of a wire that dense (three edge directions), so the
// wire covers about 1 - (1 - px / 8)^(3 / px), at most a third, however dense it gets: level 64 far
// away tints the surface instead of blacking it out.
PW_FN float wireOpacity(float px) { return clamp(px / 8.0f, 0.0f, 1.0f); }

// Displacement-adaptive level of one boundary (DESIGN §11): n straight segments miss the displaced
// edge by about detail / (8 n^2) world units (detail: core/model/height_map.hpp edgeDetail, times |scale|),
// which at `pxPerUnit` pixels per world unit stays under `tolPx` pixels from
// n = sqrt(detail * pxPerUnit / (8 tolPx)); never more segments than the texels the edge crosses.
// From the edge's canonical points and its stored detail only, so both windows on it agree.
PW_FN float displacementEdgeLevel(float detail, float texels, float pxPerUnit, float tolPx) {
    PW_PRECISE float n = sqrt(max(detail * pxPerUnit, 0.0f) / (8.0f * max(tolPx, 1e-3f)));
    return min(n, max(texels, 1.0f));
}
PW_CONST float kDisplacementTolerancePx = 0.5f;

// Pixels per world unit across the view at p under viewProj, a view `viewportHeight` pixels high
// (0 at or behind the eye).
PW_FN float pixelsPerUnit(mat4 viewProj, vec3 p, float viewportHeight) {
    PW_PRECISE float w = viewProj[0][3] * p.x + viewProj[1][3] * p.y + viewProj[2][3] * p.z + viewProj[3][3];
    if (w <= 1e-6f) return 0.0f;
    PW_PRECISE float s = 0.5f * viewportHeight * length(vec3(viewProj[0][1], viewProj[1][1], viewProj[2][1])) / w;
    return s;
}

// Band-limited displacement (DESIGN §11): the height map's mip level a view shows where it draws
// `pxPerUnit` pixels per world unit, log2 of the map's texels per pixel there: 0 while a texel
// covers a pixel or more, at most maxLod. 0 when texelsPerUnit is 0 (band limiting off). The
// evaluation samples the map at this level of the undisplaced point, which both windows of a seam
// evaluate bit-identically (DESIGN §2), so the level cannot open a crack; an edge's adaptive level
// takes the map's detail at the level of its canonical midpoint.
PW_FN float heightMapLod(float texelsPerUnit, float pxPerUnit, float maxLod) {
    if (texelsPerUnit <= 0.0f || pxPerUnit <= 0.0f) return 0.0f;
    PW_PRECISE float lod = log2(max(texelsPerUnit / pxPerUnit, 1.0f));
    return min(lod, maxLod);
}
// Mip levels above 0 whose detail each window edge carries (PatchData coarserDetail): levels 1..8.
PW_CONST int kHeightDetailLevels = 8;

PW_END_NAMESPACE

#endif  // PW_PATCH_MATH_H

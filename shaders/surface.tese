#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates a 4x4 window at gl_TessCoord for any basis (matrix M per draw), with analytic normals
// (degenerate-edge fallback like core/eval/patch_eval.cpp normalAt), Bézier boundary points from the
// boundary's four points in canonical order (bit-identical seams), and curvatures.
// With -DDISPLACE the point moves along the normal by the height map (displacement.glsl).
// With -DMERGED one patch is a block of Bu x Bv windows of a net at one level (shaders/merged.tesc,
// render/scene/merged_blocks.hpp): each vertex finds its window and reads that window's points.
// Built once per partitioning: -DSPACING=equal_spacing|fractional_odd_spacing|fractional_even_spacing,
// with -DPOINT_MODE for the normal-vector overlay, and with -DFULL_VARYINGS for the shading modes
// that need UV, patch id or curvatures (lit, normal, zebra and wireframe pass position and normal
// only: every varying costs per-vertex work in lavapipe's draw module and attribute bandwidth on GPUs).
#include "common.glsl"
#include "core/gpu/curvature_math.h"
#include "core/gpu/rational_math.h"
#ifdef MERGED
#include "core/gpu/tess_place.h"
#endif
#ifdef DISPLACE
#include "displacement.glsl"
#endif

// @teach{ the fixed tessellator: the quad domain, the partitioning, counter-clockwise triangles
#ifdef POINT_MODE
layout(quads, SPACING, ccw, point_mode) in;
#else
layout(quads, SPACING, ccw) in;
#endif
// @teach}

#ifdef MERGED
// The block (shaders/merged.tesc): its first window, windows per net row, Bu + 256 Bv, the windows' levels nu + 256 nv.
layout(location = 4) patch in uvec4 blockPatch;
layout(set = 0, binding = 4, std430) readonly buffer PoolPoints { vec4 poolPoints[]; };    // xyz, weight
layout(set = 0, binding = 5, std430) readonly buffer WindowIndices { uint windowIndices[]; };  // 16 a window
vec4 windowNet[16];  // this vertex's window, homogeneous (core/gpu/rational_math.h)
float windowScale;   // the window net's largest extent
vec4 cph(int s) { return windowNet[s]; }
uint edgeFlips() { return 0u; }  // only Bézier boundaries are evaluated canonically, and Bézier nets never merge
float netScale() { return windowScale; }
float culled() { return 0.0; }  // the renderer merges no window that the control shader would cull
#else
layout(location = 1) patch in float netScalePatch;  // largest extent of the net (control shader)
layout(location = 2) patch in uint edgeFlipPatch;    // bit e: evaluate boundary e reversed (control shader)
layout(location = 3) patch in float culledPatch;  // 1: culled, drawn greyed for a debug camera (control shader)
// Control points arrive homogeneous (core/gpu/rational_math.h): w·P and w − 1.
vec4 cph(int s) { return gl_in[s].gl_Position; }
uint edgeFlips() { return edgeFlipPatch; }
float netScale() { return netScalePatch; }
float culled() { return culledPatch; }
#endif
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
layout(location = 4) out vec2 outCurv;  // Gaussian, mean
#endif

vec3 cp(int s) { return rationalPoint(cph(s)); }

void weights(float t, out vec4 w, out vec4 dw, out vec4 ddw) {
    if (draw.basisKind == kBasisBezier) {  // Bernstein from t and s = 1 - t (core/gpu/patch_math.h)
        float s = 1.0 - t;
        w = bernstein3(t, s);
        dw = bernstein3D1(t, s);
        ddw = bernstein3D2(t, s);
    } else {
        w = draw.basis * vec4(t * t * t, t * t, t, 1.0);
        dw = draw.basis * vec4(3.0 * t * t, 2.0 * t, 1.0, 0.0);
        ddw = draw.basis * vec4(6.0 * t, 2.0, 0.0, 0.0);
    }
}

struct Derivs { vec3 p, du, dv, duu, dvv, duv; };

// Position, first derivatives and the mixed derivative; duu and dvv only when `second` (curvature).
// The sums run over the homogeneous points and the quotient rule of core/gpu/rational_math.h gives the
// rational patch's derivatives (for weights 1 the polynomial's, bit for bit).
// (lavapipe runs both sides of divergent branches, so the common path stays branch-free.)
Derivs evalAt(float u, float v, bool second) {
    // @teach{ S(u, v) = sum over rows i of B_i(v) * (sum over j of B_j(u) P_ij), with the weights
    vec4 wu, dwu, ddwu, wv, dwv, ddwv;
    weights(u, wu, dwu, ddwu);
    weights(v, wv, dwv, ddwv);
    vec4 h = vec4(0.0), hu = vec4(0.0), hv = vec4(0.0), huv = vec4(0.0), huu = vec4(0.0), hvv = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        vec4 P0 = cph(i * 4), P1 = cph(i * 4 + 1), P2 = cph(i * 4 + 2), P3 = cph(i * 4 + 3);
        vec4 r = wu.x * P0 + wu.y * P1 + wu.z * P2 + wu.w * P3;
        // @teach}
        vec4 ru = dwu.x * P0 + dwu.y * P1 + dwu.z * P2 + dwu.w * P3;
        h += wv[i] * r;  // @teach= the row's point, weighted by B_i(v)
        hu += wv[i] * ru;
        hv += dwv[i] * r;
        huv += dwv[i] * ru;
        if (second) {
            vec4 ruu = ddwu.x * P0 + ddwu.y * P1 + ddwu.z * P2 + ddwu.w * P3;
            huu += wv[i] * ruu;
            hvv += ddwv[i] * r;
        }
    }
    Derivs d;
    d.p = rationalPoint(h);
    d.du = rationalDerivative(h, hu, d.p);
    d.dv = rationalDerivative(h, hv, d.p);
    d.duv = rationalSecondDerivative(h, hu, hv, huv, d.p, d.du, d.dv);
    d.duu = d.dvv = vec3(0.0);
    if (second) {
        d.duu = rationalSecondDerivative(h, hu, hu, huu, d.p, d.du, d.du);
        d.dvv = rationalSecondDerivative(h, hv, hv, hvv, d.p, d.dv, d.dv);
    }
    return d;
}

// A Bézier boundary point from that boundary's four points only, lower pool index first.
// e in quad-domain order (u0, v0, u1, v1). The points are picked with constant indices and
// selects: indexing gl_in[] by a per-vertex edge number is very slow on lavapipe.
vec3 boundaryPoint(int e, float t) {
    bool rev = (edgeFlips() & (1u << uint(e))) != 0u;
    bool alongU = (e & 1) == 1;  // v0, v1: a row of the net; u0, u1: a column
    bool far = e >= 2;           // u1 (column 3) or v1 (row 3)
    vec4 q0 = alongU ? (far ? cph(12) : cph(0)) : (far ? cph(3) : cph(0));
    vec4 q1 = alongU ? (far ? cph(13) : cph(1)) : (far ? cph(7) : cph(4));
    vec4 q2 = alongU ? (far ? cph(14) : cph(2)) : (far ? cph(11) : cph(8));
    vec4 q3 = alongU ? (far ? cph(15) : cph(3)) : (far ? cph(15) : cph(12));
    return rationalPoint(canonicalBoundaryPointH(q0, q1, q2, q3, t, rev));
}

vec3 normalAt(float u, float v, Derivs d) {
    float scale = netScale();
    float s2 = scale * scale;
    // Common case first: du x dv is well defined away from collapsed edges.
    vec3 n = cross(d.du, d.dv);
    float len2 = dot(n, n);
    bool duZero = dot(d.du, d.du) <= 1e-8 * s2;  // |du| <= 1e-4 scale, without a square root
    bool dvZero = dot(d.dv, d.dv) <= 1e-8 * s2;
    if (!duZero && !dvZero && len2 > 1e-12 * s2 * s2) return n * inversesqrt(len2);
    // A collapsed row or column (teapot lid top, bottom centre): the derivative along it is float
    // noise, so use the limit from inside through the mixed derivative.
    vec3 nu = cross(d.duv, d.dv) * (v < 0.5 ? 1.0 : -1.0);
    vec3 nv = cross(d.du, d.duv) * (u < 0.5 ? 1.0 : -1.0);
    n = duZero == dvZero ? n : (duZero ? nu : nv);
    if (duZero && dvZero) n = vec3(0.0);
    float len = length(n);
    if (len > 1e-6 * s2) return n / len;
    n = cross(cp(15) - cp(0), cp(12) - cp(3));
    len = length(n);
    return len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
}

#ifdef MERGED
// Loads window w's points and, as the control shader computes it for a patch of its own, its net's extent.
void loadWindow(uint w) {
    uint idx[16];
    for (int s = 0; s < 16; ++s) {
        idx[s] = windowIndices[w * 16u + uint(s)];
        vec4 p = poolPoints[idx[s]];
        windowNet[s] = homogeneousPoint(p.xyz, p.w);
    }
    vec3 lo = cp(0), hi = cp(0);
    for (int i = 1; i < 16; ++i) { lo = min(lo, cp(i)); hi = max(hi, cp(i)); }
    windowScale = max(max(hi.x - lo.x, hi.y - lo.y), max(hi.z - lo.z, 1e-20));
}
#endif

void main() {
#ifdef MERGED
    // The block's domain is Bu x Bv windows at levels Bu nu and Bv nv: each vertex is snapped to its
    // index k on the block's edge (the tessellator places it within 1/(2 B n) of k / (B n)), which
    // names its window (k / n) and its index there (k mod n), placed as the window's own patch gets it
    // (core/gpu/tess_place.h: exactly j / n for powers of two; lavapipe's 16.16 rounding otherwise).
    uint blockU = blockPatch.z & 255u, blockV = blockPatch.z >> 8u, nu = blockPatch.w & 255u, nv = blockPatch.w >> 8u;
    uint ku = uint(round(gl_TessCoord.x * float(blockU * nu))), kv = uint(round(gl_TessCoord.y * float(blockV * nv)));
    uint col = min(ku / nu, blockU - 1u), row = min(kv / nv, blockV - 1u);
    uint window = blockPatch.x + row * blockPatch.y + col;
    loadWindow(window);
    float u = fixedTessPlace(ku - col * nu, nu), v = fixedTessPlace(kv - row * nv, nv);
    vec2 windowLevels = vec2(float(nu), float(nv));
    uint patchId = window;
#else
    float u = gl_TessCoord.x, v = gl_TessCoord.y;  // @teach= main: where the tessellator put this vertex
    vec2 windowLevels = vec2(gl_TessLevelInner[0], gl_TessLevelInner[1]);
    uint patchId = draw.patchBase + uint(gl_PrimitiveID);
#endif
#ifdef FULL_VARYINGS
    bool curvature = frame.modes.w == kShadingGaussCurvature || frame.modes.w == kShadingMeanCurvature;
#else
    const bool curvature = false;
#endif
    Derivs d = evalAt(u, v, curvature);  // @teach=
    vec3 p = d.p;
    bool onV = v == 0.0 || v == 1.0, onU = u == 0.0 || u == 1.0;
    if (draw.basisKind == kBasisBezier && (onU || onV)) {
        int e = onV ? (v == 0.0 ? 1 : 3) : (u == 0.0 ? 0 : 2);
        p = boundaryPoint(e, onV ? u : v);
    }
    vec3 n = normalAt(u, v, d);  // @teach=
#ifdef DISPLACE
    displaceSurface(p, n, d.du, d.dv, vec2(u, v), patches[patchId]);
#endif

#if defined(POINT_MODE) || defined(CAPTURE)
    outPos = p;
#endif
    outNormal = n;
    outCulled = culled();
    // The wire's opacity only where a wire is drawn (flat colour): two projections a vertex otherwise wasted.
    outWire = draw.drawMode != kDrawFlatColour
                  ? 1.0
                  : wireOpacity(segmentSpan(segmentPixels(p, d.du, windowLevels.x, frame.viewProj, frame.viewport.xy),
                                            segmentPixels(p, d.dv, windowLevels.y, frame.viewProj, frame.viewport.xy)));
#ifdef FULL_VARYINGS
    // curvatures from the fundamental forms (curvature shading only)
    vec2 curv = vec2(0.0);
    if (curvature) {
        curv = gaussMeanCurvature(d.du, d.dv, d.duu, d.duv, d.dvv, n);
    } else if (frame.modes.w == kShadingLevel) {  // the level the control shader chose for this patch
        curv = vec2(max(windowLevels.x, windowLevels.y), 0.0);
    }
    outUV = vec2(u, v);
    outPatch = patchId;
    outCurv = curv;
#endif
    gl_Position = frame.viewProj * vec4(p, 1.0);  // @teach=
}

#version 450
#extension GL_GOOGLE_include_directive : require
// Shading modes: lit (two-sided, back faces tinted), normal as colour, patch id, UV checker, zebra
// stripes, Gaussian and mean curvature maps, the tessellation level (core/gpu/level_colour.h). drawMode 1 draws a flat colour (wireframe pass).
// Without -DFULL_VARYINGS only position and normal come in (lit, normal, zebra, flat colour).
#include "common.glsl"
#include "core/gpu/level_colour.h"
layout(location = 1) in vec3 inNormal;
layout(location = 6) in float inWire;  // the wireframe's opacity (dense wires fade)
layout(location = 5) flat in float inCulled;  // a patch the deciding camera culls, shown by a debug camera
#ifdef FULL_VARYINGS
layout(location = 2) in vec2 inUV;
layout(location = 3) flat in uint inPatch;
layout(location = 4) in vec2 inCurv;
#include "core/gpu/trim_math.h"
// The trimmed windows' blocks (core/gpu/trim_math.h): per window one vec4 per cell (the first vec4
// of its list, its count, its parity), then the cells' v-monotone segments in the window's (u, v),
// sorted by their lowest v, three vec4 each: the box (umin, vmin, umax, vmax), b0 b1, b2 b3.
layout(set = 0, binding = 7, std430) readonly buffer TrimSegments { vec4 trimSegs[]; };
// Direct trimming (core/gpu/trim_math.h): the ray from (u, v) towards +u against the segments of
// the point's cell; an even count (with the cell's parity) is trimmed away. Exact per pixel at any
// zoom. Most cells list none; the box alone settles most segments (above, below, wholly right or
// left of the point), and the first segment starting above the point ends the loop.
bool trimmedAway(uint patchIndex, vec2 uv) {
    uvec4 t = patches[patchIndex].trim;
    if ((t.z & kTrimTest) == 0u) return false;
    uvec2 c = min(uvec2(clamp(uv, 0.0, 1.0) * float(kTrimCells)), uvec2(kTrimCells - 1u));
    vec4 cell = trimSegs[t.x + c.y * kTrimCells + c.x];
    uint first = uint(cell.x), count = uint(cell.y);
    uint crossings = uint(cell.z);
    for (uint i = 0u; i < count; ++i) {
        uint at = first + 3u * i;
        vec4 box = trimSegs[at];
        if (uv.y < box.y) break;
        if (uv.y >= box.w || uv.x > box.z) continue;
        if (uv.x < box.x) {
            crossings += 1u;
            continue;
        }
        vec4 a = trimSegs[at + 1u];
        vec4 b = trimSegs[at + 2u];
        crossings += trimCrossing(uv, a.xy, a.zw, b.xy, b.zw);
    }
    return (crossings & 1u) == 0u;
}
#endif
layout(location = 0) out vec4 outColor;

vec3 hashColor(uint id) {
    uint h = id * 2654435761u;
    h ^= h >> 15; h *= 2246822519u; h ^= h >> 13;
    vec3 c = vec3(float(h & 255u), float((h >> 8) & 255u), float((h >> 16) & 255u)) / 255.0;
    return 0.25 + 0.7 * c;
}

vec3 diverging(float x) {  // blue (negative) - white - red (positive)
    float t = tanh(x);
    return t < 0.0 ? mix(vec3(1.0), vec3(0.15, 0.35, 0.95), -t) : mix(vec3(1.0), vec3(0.95, 0.2, 0.15), t);
}

// A culled patch seen from a debug camera: grey hatching, so it reads as "not drawn from the real camera".
vec3 culledGrey() { return ((int(gl_FragCoord.x + gl_FragCoord.y) / 5) & 1) == 0 ? vec3(0.42) : vec3(0.58); }

void main() {
#ifdef FULL_VARYINGS
    if (draw.drawMode != kDrawPlainMesh && trimmedAway(inPatch, inUV)) discard;
#endif
    if (draw.drawMode == kDrawFlatColour) {
        outColor = inCulled > 0.5 ? vec4(mix(draw.color.rgb, vec3(0.5), 0.6), draw.color.a) : draw.color;
        outColor.a *= inWire;  // the wire pipelines blend
        return;
    }
    vec3 n = normalize(inNormal);
    vec2 ndc = (gl_FragCoord.xy - frame.viewport.zw) / frame.viewport.xy * 2.0 - 1.0;
    vec3 v = -normalize(frame.rayZ.xyz + ndc.x * frame.rayX.xyz + ndc.y * frame.rayY.xyz);  // towards the eye
    bool back = dot(n, v) < 0.0;
    vec3 nf = back ? -n : n;
    vec3 l = frame.lightDir.xyz;  // unit length (renderer)
    float diff = abs(dot(nf, l));
    float spec = pow(max(dot(nf, normalize(l + v)), 0.0), 48.0);
    float light = 0.25 + 0.75 * diff;
    uint mode = frame.modes.w;
    vec3 base;
    if (mode == kShadingNormal) { outColor = vec4(n * 0.5 + 0.5, 1.0); return; }
#ifdef FULL_VARYINGS
    else if (mode == kShadingPatchId) base = hashColor(inPatch);
    else if (mode == kShadingUvChecker) {
        ivec2 c = ivec2(floor(clamp(inUV, 0.0, 0.9999) * 8.0));
        base = ((c.x + c.y) & 1) == 0 ? vec3(0.92) : vec3(0.25, 0.3, 0.4);
        base = mix(base, vec3(inUV, 0.4), 0.25);
    }
#endif
    else if (mode == kShadingZebra) {
        vec3 r = reflect(-v, nf);
        float stripe = fract(frame.dist.w * (r.z * 0.5 + 0.5));
        outColor = vec4(vec3(stripe < 0.5 ? 0.05 : 0.95), 1.0);
        return;
    }
#ifdef FULL_VARYINGS
    else if (mode == kShadingGaussCurvature) base = diverging(inCurv.x * frame.dist.z * frame.dist.z);
    else if (mode == kShadingMeanCurvature) base = diverging(inCurv.y * frame.dist.z);
    else if (mode == kShadingLevel) base = levelColour(inCurv.x);
#endif
    else base = vec3(0.72, 0.74, 0.78);
    if (inCulled > 0.5) base = culledGrey();
    if (back) base *= vec3(1.0, 0.55, 0.5);  // back faces tinted
    vec3 c = base * light + (mode == kShadingLit ? vec3(0.35) * spec : vec3(0.0));
    outColor = vec4(clamp(c, 0.0, 1.0), 1.0);
}

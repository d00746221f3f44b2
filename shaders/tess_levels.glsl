// Tessellation-level helpers shared by the quad (surface.tesc) and triangle (tri_surface.tesc)
// control shaders: adaptive edge levels (under ADAPTIVE_AND_CULLING) and DESIGN §3 rounding. Both
// control shaders compute a shared edge's level with the same code from the same canonical points.
// Needs common.glsl first.
#ifdef ADAPTIVE_AND_CULLING
vec2 toPixels(vec3 p, out bool behind) {
    vec4 c = frame.viewProj * vec4(p, 1.0);
    behind = c.w <= 1e-6;
    return (c.xy / max(c.w, 1e-6) * 0.5 + 0.5) * frame.viewport.xy;
}

// Adaptive level of one boundary curve from its four control points in canonical order (lower pool
// index first): a neighbour sharing the curve gets the same value, so there are no cracks.
float adaptiveEdgeLevel(vec3 p[4]) {
    float maxL = frame.inner.z;
    uint mode = frame.modes.y;
    if (mode == 1u) {  // distance to the eye
        precise vec3 mid = 0.5 * (p[0] + p[3]);
        float d = distance(frame.eye.xyz, mid);
        float d0 = frame.dist.x, d1 = frame.dist.y;
        return maxL * clamp((d1 - d) / max(d1 - d0, 1e-6), 0.0, 1.0);
    }
    if (mode == 2u) {  // screen-space length of the control polygon, target pixels per segment
        bool b0, b1, b2, b3;
        vec2 s0 = toPixels(p[0], b0), s1 = toPixels(p[1], b1), s2 = toPixels(p[2], b2), s3 = toPixels(p[3], b3);
        if (b0 || b1 || b2 || b3) return maxL;
        precise float len = length(s1 - s0) + length(s2 - s1) + length(s3 - s2);
        return len / max(frame.inner.w, 0.5);
    }
    // orientation: edges whose bend is seen side-on (silhouette-like) get more segments
    vec3 mid = 0.5 * (p[0] + p[3]);
    vec3 vdir = normalize(mid - frame.eye.xyz);
    vec3 bend = (p[1] + p[2]) - (p[0] + p[3]);
    vec3 side = bend - dot(bend, vdir) * vdir;
    float chord = max(distance(p[0], p[3]), 1e-6);
    return maxL * clamp(2.0 * length(side) / chord, 0.0, 1.0);
}

#endif

// DESIGN §3: equal -> ceil in [1,64]; odd -> [1,63]; even -> [2,64]; pow2 -> next power of two.
float roundLevel(float f) {
    uint s = frame.modes.x;
    if (!(f == f)) f = 1.0;  // NaN never reaches the tessellator
    if (s == 0u) return clamp(ceil(f), 1.0, 64.0);
    if (s == 1u) return clamp(f, 1.0, 63.0);
    if (s == 2u) return clamp(f, 2.0, 64.0);
    float c = clamp(ceil(f), 1.0, 64.0);
    return clamp(exp2(ceil(log2(c) - 1e-4)), 1.0, 64.0);
}


// Tessellation-level helpers of the quad (surface.tesc) and triangle (tri_surface.tesc) control
// shaders: core/patch_math.h's adaptive edge level and rounding with this frame's settings. Both
// control shaders compute a shared edge's level with the same code from the same canonical points.
// Needs common.glsl first, and the control shader's `inIdx[]` (the pool index of each control point)
// declared before the include.
#ifdef ADAPTIVE_AND_CULLING
// Adaptive level of one boundary curve from its four control points in canonical order.
float adaptiveEdgeLevel(vec3 p[4]) {
    return adaptiveEdgeLevel(p[0], p[1], p[2], p[3], frame.modes.y, frame.inner.z, frame.eye.xyz, frame.dist.x,
                             frame.dist.y, frame.viewProj, frame.viewport.xy, frame.inner.w);
}
#endif

// DESIGN §3 rounding under this frame's partitioning.
float roundLevel(float f) { return roundLevel(f, frame.modes.x); }

// True when the edge through control points a, b, c, d (their pool indices inIdx[]) runs against
// its canonical direction.
bool reversedEdge(int a, int b, int c, int d) {
    return edgeReversed(uint(inIdx[a]), uint(inIdx[b]), uint(inIdx[c]), uint(inIdx[d]));
}

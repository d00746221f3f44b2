// Tessellation-level helpers of the quad (surface.tesc) and triangle (tri_surface.tesc) control
// shaders: core/gpu/patch_math.h's adaptive edge level and rounding with this frame's settings. Both
// control shaders compute a shared edge's level with the same code from the same canonical points.
// Needs common.glsl first, and the control shader's `inIdx[]` (the pool index of each control point)
// declared before the include.
#ifdef ADAPTIVE_AND_CULLING
// Adaptive level of one boundary curve from its four control points in canonical order, seen from
// the camera that decides levels (frame.lodEye: the view's, or the one a debug camera looks at).
float adaptiveEdgeLevel(vec3 p[4]) {
    return adaptiveEdgeLevel(p[0], p[1], p[2], p[3], frame.modes.y, frame.inner.z, frame.lodEye.xyz, frame.dist.x, frame.dist.y,
                             frame.distModes.x, frame.lodDist.xy, frame.lodViewProj, frame.viewport.xy, frame.inner.w);
}

// Distance mode measured from the patch centre (tess.distanceFrom centre, or the inner levels of
// edges-inner-centre): the level at `centre`, clamped like an edge's.
bool centreLevels() { return frame.modes.y == kAdaptiveDistance && frame.distModes.y == kFromCentre; }
bool centreInner() { return frame.modes.y == kAdaptiveDistance && frame.distModes.y != kFromEdges; }
float centreLevel(vec3 centre) {
    float l = distanceLevel(distance(frame.lodEye.xyz, centre), frame.inner.z, frame.dist.x, frame.dist.y, frame.distModes.x,
                            frame.lodDist.xy);
    return clamp(l, 1.0, frame.inner.z);
}

// A debug camera draws culled patches greyed (their levels kept) instead of dropping them.
bool showCulled() { return frame.lodEye.w > 0.5; }

// The notes' factor 0 (tess.cullFar): in distance mode, a patch whose control points' centre is at
// or beyond the far distance, where their formula 64 saturate((d1 - d) / (d1 - d0)) gives 0, is
// culled. farCulling() first, so the centre is computed only when it is on.
bool farCulling() { return (frame.modes.z & kCullFar) != 0u && frame.modes.y == kAdaptiveDistance; }
bool beyondFar(vec3 centre) { return distance(frame.lodEye.xyz, centre) >= frame.dist.y; }

// How far the displaced surface may leave the patch: the largest |height| (0 without a map, whose
// texture then reads 0 and whose windows carry no detail).
float displacementMargin(PatchData pd) {
    vec2 sb = displacementScaleBias(pd);
    return max(abs(sb.y), abs(sb.x + sb.y));
}

// The map's detail along edge e at mip level `level` (0..8): level 0's `detail` times the stored
// fraction of that level (PatchData coarserDetail).
float detailAtLevel(PatchData pd, int e, int level) {
    if (level <= 0) return pd.detail[e];
    level = min(level, kHeightDetailLevels);
    vec2 pair = unpackHalf2x16(pd.coarserDetail[e][(level - 1) / 2]);
    return pd.detail[e] * ((level & 1) == 1 ? pair.x : pair.y);
}
// ... and at a fractional level, between the two levels round it. Precise, like every step of an
// edge's level: the quad and triangle control shaders are separate modules and must agree.
float detailAtLod(PatchData pd, int e, float lod) {
    int level = int(floor(lod));
    precise float f = lod - float(level);
    precise float d = mix(detailAtLevel(pd, e, level), detailAtLevel(pd, e, level + 1), f);
    return d;
}

// Edge level `level` raised for the height map's detail along edge e (core/gpu/patch_math.h
// displacementEdgeLevel) at this distance: pixels per world unit across the view at the canonical
// chord's midpoint, from the points alone, so both windows on the edge agree. Band-limited: the
// detail and the texels crossed are those of the mip level the view shows there (heightMapLod), the
// level the evaluation samples. The surface pass counts the edges raised and the largest such level (the stats).
float raiseForDisplacement(float level, vec3 p[4], int e, PatchData pd) {
    float detail = pd.detail[e];
    if (detail <= 0.0 || (frame.modes.z & kKeepHeightLevels) != 0u) return level;
    float pxPerUnit = pixelsPerUnit(frame.lodViewProj, 0.5 * (p[0] + p[3]), frame.viewport.y);
    if (pxPerUnit <= 0.0) return level;
    float lod = heightMapLod(frame.heightLod.x, pxPerUnit, frame.heightLod.y);
    precise float scaled = detailAtLod(pd, e, lod) * abs(displacementScaleBias(pd).x);
    precise float texels = pd.texels[e] * exp2(-lod);
    precise float d = min(displacementEdgeLevel(scaled, texels, pxPerUnit, kDisplacementTolerancePx), frame.inner.z);
    if (d > level && draw.drawMode == kDrawShaded) {
        atomicAdd(counters.displacedEdges, 1u);
        atomicMax(counters.displacementLevel, uint(ceil(d)));
    }
    return max(level, d);
}

// Plane k of the deciding camera's frustum (core/gpu/patch_math.h frustumPlane).
vec4 frustumPlane(int k) { return frustumPlane(frame.lodViewProj, k); }
#endif

// DESIGN §3 rounding under this frame's partitioning.
float roundLevel(float f) { return roundLevel(f, frame.modes.x); }

// True when the edge through control points a, b, c, d (their pool indices inIdx[]) runs against
// its canonical direction.
bool reversedEdge(int a, int b, int c, int d) {
    return edgeReversed(uint(inIdx[a]), uint(inIdx[b]), uint(inIdx[c]), uint(inIdx[d]));
}

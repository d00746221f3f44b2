// The interface between the renderer and the shaders, written once for both (core/gpu/glsl_cpp.h):
// the per-frame uniform block (std140), the per-patch storage buffer entries and counters (std430)
// and the per-draw push constants. In C++ these are structs in pw::gpu that the renderer fills; in
// GLSL (shaders/common.glsl includes this file) they are the blocks `frame`, `patches`, `counters`
// and `draw`. Mode fields take the named constants of core/gpu/patch_math.h.
#ifndef PW_GPU_INTERFACE_H
#define PW_GPU_INTERFACE_H

#include "core/gpu/patch_math.h"

PW_BEGIN_NAMESPACE

// binding 0: per-frame constants (camera, tessellation settings, display settings).
PW_BLOCK(layout(set = 0, binding = 0, std140) uniform Frame, FrameUniforms) {
    mat4 viewProj;  // world -> clip (Vulkan: y down, depth 0..1)
    mat4 view;      // world -> eye
    vec4 eye;       // xyz camera position
    vec4 lightDir;  // xyz direction towards the light, w: normal overlay length
    vec4 viewport;  // xy size in pixels, zw the pane's top-left corner in the target
    vec4 outer;     // uniform outer levels (u0, v0, u1, v1)
    vec4 inner;     // xy uniform inner levels, z max level, w target pixels per segment
    vec4 dist;      // x d0 (full level), y d1 (level 1), z curvature colour scale, w zebra stripes
    uvec4 modes;    // x spacing (kSpacing*), y adaptive (kAdaptive*), z cull bits (kCull*), w shading (kShading*)
    uvec4 sel;      // x hovered point, y selected point (kNoPoint = none)
    // View rays: the direction from the eye through NDC (x, y) is rayZ + x rayX + y rayY (the
    // fragment shader's view vector, so no world position travels as a varying).
    vec4 rayX;
    vec4 rayY;
    vec4 rayZ;
    vec4 isoline;  // isoline domain (curves, isocurves): x lines, y segments
    // Displacement (the -DDISPLACE evaluation shaders, DESIGN §11): x scale, y bias (the document's),
    // z mapping (0 the window's parameters, 1 planar), w 1 for a Z-up document (planar over x-y,
    // else x-z).
    vec4 displace;
    vec4 planar;  // planar mapping: xy the rectangle's corner, zw 1 / its size
    // Curvature combs (shaders/comb.tese): x tooth length per unit curvature (model units²; a tooth
    // is −x·κN), y teeth per curve or isocurve.
    vec4 comb;
    // Distance mode: x curve (kCurve*), y where distance is measured (kFrom*); lodDist xy the pow2
    // curve's exponents at d0 and d1.
    uvec4 distModes;
    vec4 lodDist;
    // The camera that decides adaptive levels and culling: the view's own, unless a debug camera
    // draws the picture from elsewhere; then w is 1 and culled patches are drawn greyed instead of dropped.
    mat4 lodViewProj;
    vec4 lodEye;
    // Band-limited displacement (core/gpu/patch_math.h heightMapLod): x the map's texels per world
    // unit (0: the full-resolution map everywhere), y the coarsest mip level used.
    vec4 heightLod;
}
PW_END_BLOCK(frame)

// binding 1: per-patch tessellation overrides, indexed by patchBase + gl_PrimitiveID.
struct PatchData {
    vec4 outer PW_INIT(0.0f);  // per edge: the fixed level, or the least level (core/tess/edge_levels.hpp)
    vec4 inner PW_INIT(0.0f);  // xy own inner levels, z > 0.5: they apply; w: the fixed edges' bit mask
    // Displacement: the map rectangle of the window under the patch mapping (u, v) -> mix(xy, zw);
    // its own scale and bias (z > 0.5: they apply, else the document's); per edge (u0, v0, u1, v1)
    // the map's detail (core/model/height_map.hpp, before |scale|) and the texels the edge crosses.
    vec4 uvRect PW_INIT(0.0f);
    vec4 disp PW_INIT(0.0f);
    vec4 detail PW_INIT(0.0f);
    vec4 texels PW_INIT(0.0f);
    // Per edge, the detail at the map's mip levels 1..8 as fractions of `detail` (level 0), two
    // half floats a word: x levels 1 and 2, y 3 and 4, z 5 and 6, w 7 and 8 (the lower half first).
    uvec4 coarserDetail[4] PW_INIT(uvec4(0u));
    // Trimming (core/gpu/trim_math.h): x the first segment in binding 7, y their count, z flags.
    uvec4 trim PW_INIT(uvec4(0u));
};

// bindings 4-6, storage, read by the merged blocks of net windows only (shaders/merged.tesc,
// surface.tese -DMERGED): the pool (xyz, weight), the windows' 16 pool indices, this frame's blocks.
// binding 7, storage, read by the fragment shader: the trimmed windows' v-monotone trim segments
// (shaders/trim.glsl).

// binding 2: statistics the shaders write (patches culled this frame).
PW_BLOCK(layout(set = 0, binding = 2, std430) buffer Counters, GpuCounters) {
    uint culled;
    uint displacedEdges;     // window edges whose level the height map's detail raised (surface pass)
    uint displacementLevel;  // the largest such level
    uint pad2;
}
PW_END_BLOCK(counters)

// Per draw: the basis matrix (rows for t^3, t^2, t, 1 stored row-major, so weights = basis * T).
PW_BLOCK(layout(push_constant) uniform Draw, DrawPush) {
    mat4 basis PW_INIT(1.0f);
    uint patchBase PW_INIT(0u);     // index of the first patch of this draw
    uint basisKind PW_INIT(0u);     // kBasis*
    uint drawMode PW_INIT(0u);      // kDraw*
    uint isoDirection PW_INIT(0u);  // isocurve overlay: 0 lines along u, 1 along v
    vec4 color PW_INIT(1.0f);       // flat colour
}
PW_END_BLOCK(draw)

PW_END_NAMESPACE

#ifdef __cplusplus
static_assert(sizeof(pw::gpu::FrameUniforms) == 3 * 64 + 19 * 16);
static_assert(sizeof(pw::gpu::PatchData) == 176);
static_assert(sizeof(pw::gpu::GpuCounters) == 16);
static_assert(sizeof(pw::gpu::DrawPush) == 96);
#endif

#endif  // PW_GPU_INTERFACE_H

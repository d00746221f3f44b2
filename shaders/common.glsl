// Shared declarations of the Patchwork shaders: the per-frame uniform block, the per-draw push
// constants and the per-patch storage buffers. Mirrors render/gpu_types.hpp (std140 / std430).

// binding 0: per-frame constants (camera, tessellation settings, display settings).
layout(set = 0, binding = 0, std140) uniform Frame {
    mat4 viewProj;   // world -> clip (Vulkan: y down, depth 0..1)
    mat4 view;       // world -> eye
    vec4 eye;        // xyz camera position
    vec4 lightDir;   // xyz light direction (towards the light), w: normal overlay length
    vec4 viewport;   // xy size in pixels, zw the pane's top-left corner in the target
    vec4 outer;      // uniform outer levels (u0, v0, u1, v1)
    vec4 inner;      // xy uniform inner levels, z max level, w target pixels per segment
    vec4 dist;       // x d0 (full level), y d1 (level 1), z curvature colour scale, w zebra stripes
    uvec4 modes;     // x spacing (0 equal, 1 odd, 2 even, 3 pow2), y adaptive, z cull bits, w shading
    uvec4 sel;       // x hovered point, y selected point (0xffffffff = none)
    vec4 rayX, rayY, rayZ;  // direction from the eye through NDC (x, y): rayZ + x rayX + y rayY
    vec4 isoline;    // isoline domain (curves, isocurves): x lines, y segments
} frame;

// binding 1: per-patch tessellation overrides, indexed by patchBase + gl_PrimitiveID.
struct PatchData {
    vec4 outer;
    vec4 inner;  // xy inner levels, z > 0.5: override active
};
layout(set = 0, binding = 1, std430) readonly buffer Patches { PatchData patches[]; };

// binding 2: statistics written by the shaders (patches culled this frame).
layout(set = 0, binding = 2, std430) buffer Counters { uint culled; uint pad0, pad1, pad2; } counters;

// Per draw: basis matrix (rows for t^3, t^2, t, 1 stored row-major, so weights = basis * T).
layout(push_constant) uniform Draw {
    mat4 basis;
    uint patchBase;  // index of the first patch of this draw
    uint basisKind;  // 0 Bézier, 1 B-spline, 2 Catmull-Rom
    uint drawMode;   // 0 shaded, 1 flat colour (wireframe), 2 plain mesh
    uint isoDirection;  // isocurve overlay: 0 lines along u, 1 along v
    vec4 color;      // flat colour
} draw;

#version 450
#extension GL_GOOGLE_include_directive : require
// A CPU-tessellated mesh drawn as plain triangles with the surface's fragment shading (reference
// for tests and the benchmark). Varyings as the evaluation shader's (-DFULL_VARYINGS or lean).
#include "common.glsl"
layout(location = 0) in vec3 inPos;
layout(location = 1) in vec3 inNormal;
layout(location = 1) out vec3 outNormal;
layout(location = 5) flat out float outCulled;  // never: a plain mesh has no culled patches
layout(location = 6) out float outWire;  // a plain mesh draws no wireframe
#ifdef FULL_VARYINGS
layout(location = 2) in vec2 inUV;
layout(location = 2) out vec2 outUV;
layout(location = 3) flat out uint outPatch;
layout(location = 4) out vec2 outCurv;
#endif
void main() {
    outNormal = inNormal;
    outCulled = 0.0;
    outWire = 1.0;
#ifdef FULL_VARYINGS
    outUV = inUV;
    outPatch = draw.patchBase;
    outCurv = vec2(0.0);
#endif
    gl_Position = frame.viewProj * vec4(inPos, 1.0);
}

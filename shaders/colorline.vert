#version 450
#extension GL_GOOGLE_include_directive : require
// Lines with a colour per vertex (patch boundaries coloured by continuity).
#include "common.glsl"
layout(location = 0) in vec3 inPos;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec4 outColor;
void main() {
    gl_Position = frame.viewProj * vec4(inPos, 1.0);
    gl_Position.z -= 2e-6 * gl_Position.w;  // pull towards the eye so lines on the surface win the depth test
    gl_PointSize = 1.0;
    outColor = inColor;
}

#version 450
#extension GL_GOOGLE_include_directive : require
// Normal-vector overlay: each tessellated vertex (point-mode evaluation) becomes a short line.
#include "common.glsl"
layout(points) in;
layout(line_strip, max_vertices = 2) out;
layout(location = 0) in vec3 inPos[];
layout(location = 1) in vec3 inNormal[];
layout(location = 0) out vec4 outColor;
void main() {
    vec3 p = inPos[0];
    gl_Position = frame.viewProj * vec4(p, 1.0);
    outColor = draw.color;
    EmitVertex();
    gl_Position = frame.viewProj * vec4(p + inNormal[0] * frame.lightDir.w, 1.0);
    outColor = draw.color;
    EmitVertex();
    EndPrimitive();
}

#version 450
#extension GL_GOOGLE_include_directive : require
// Control grid: pool points as lines or points; the hovered and selected points are highlighted.
#include "common.glsl"
layout(location = 0) in vec4 inPoint;  // the pool: xyz position, w weight
layout(location = 0) out vec4 outColor;
void main() {
    gl_Position = frame.viewProj * vec4(inPoint.xyz, 1.0);
    uint id = uint(gl_VertexIndex);
    vec4 c = draw.color;
    float size = 5.0;
    if (draw.drawMode == kDrawGridPoints) {  // points
        if (id == frame.sel.y) { c = vec4(1.0, 0.55, 0.1, 1.0); size = 10.0; }
        else if (id == frame.sel.x) { c = vec4(1.0, 1.0, 0.3, 1.0); size = 9.0; }
    }
    gl_PointSize = size;
    outColor = c;
}

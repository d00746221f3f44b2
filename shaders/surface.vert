#version 450
// Control points straight from the pool; the pool index travels along for canonical seams.
layout(location = 0) in vec3 inPos;
layout(location = 0) out int outIdx;
void main() {
    gl_Position = vec4(inPos, 1.0);
    outIdx = gl_VertexIndex;
}

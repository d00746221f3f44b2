#version 450
// A block of merged windows (shaders/merged.tesc) is a patch of one control point: its index in
// the block list, which the draw's first vertex offsets.
layout(location = 0) out int outBlock;
void main() { outBlock = gl_VertexIndex; }

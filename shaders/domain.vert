#version 450
// The domain view draws one patch of one control point; the control point carries nothing.
void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }

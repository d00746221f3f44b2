// Push constants of the domain view (render/domain_view.cpp, DomainPush): the levels the control
// shader writes, the map from domain coordinates to clip space, and the colour of the pass.
layout(push_constant) uniform DomainPush {
    vec4 outer;      // requested outer levels (quad: u0, v0, u1, v1; triangle: u0, v0, w0; isoline: lines, segments)
    vec4 inner;      // xy requested inner levels; z = 1: pow2 emulation (next power of two, equal spacing)
    vec4 transform;  // clip = domain * xy + zw (domain coordinates: x right, y up, in [0,1]^2)
    vec4 color;      // colour of this pass
    vec4 point;      // x point size (point-size variants only)
} dp;

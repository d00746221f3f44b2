#version 450
#extension GL_GOOGLE_include_directive : require
// Domain view: the tessellation coordinate itself is the position, so the picture is exactly the
// pattern the fixed tessellator generated. Built per domain (-DDOMAIN=quads|triangles|isolines) and
// partitioning (-DSPACING=...), with -DPOINT_SIZE for the vertex-dot pass and -DCAPTURE for
// vector figures.
#include "domain_common.glsl"

#ifdef POINT_SIZE
layout(DOMAIN, SPACING, point_mode) in;  // the vertex dots: each domain point once
#else
layout(DOMAIN, SPACING, ccw) in;
#endif
layout(location = 0) out vec4 outColor;
#ifdef CAPTURE  // figures and captures: each primitive's gl_TessCoord.xy, 8 bytes a vertex
layout(location = 1, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 8) out vec2 outDomain;
#endif

void main() {
#ifdef TRIANGLE_DOMAIN
    // Barycentric (u, v, w): the corner u = 1 bottom left, v = 1 bottom right, w = 1 on top, so
    // the edge u = 0 is on the right, v = 0 on the left and w = 0 at the bottom.
    const vec2 cu = vec2(0.0, 0.0), cv = vec2(1.0, 0.0), cw = vec2(0.5, 0.8660254);
    vec2 p = gl_TessCoord.x * cu + gl_TessCoord.y * cv + gl_TessCoord.z * cw;
#else
    // Quad: u right, v up. Isolines: u along each line, v from line to line.
    vec2 p = gl_TessCoord.xy;
#endif
    gl_Position = vec4(p * dp.transform.xy + dp.transform.zw, 0.0, 1.0);
    outColor = dp.color;
#ifdef CAPTURE
    outDomain = gl_TessCoord.xy;  // as the tessellator made it (core/tess/tess_pattern.hpp)
#endif
#ifdef POINT_SIZE
    gl_PointSize = dp.point.x;
#endif
}

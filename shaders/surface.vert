#version 450
#extension GL_GOOGLE_include_directive : require
// Control points straight from the pool (xyz the position, w the weight), handed on in the
// homogeneous form of core/gpu/rational_math.h (w·P, w − 1); the pool index travels along for
// canonical seams.
#include "core/gpu/rational_math.h"
layout(location = 0) in vec4 inPoint;
layout(location = 0) out int outIdx;
void main() {
    gl_Position = homogeneousPoint(inPoint.xyz, inPoint.w);
    outIdx = gl_VertexIndex;
}

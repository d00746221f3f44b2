// The push constants of the domain view (render/domain/domain_view.cpp), written once for C++ and GLSL
// (core/gpu/glsl_cpp.h): in C++ the struct pw::gpu::DomainPush, in GLSL (shaders/domain_common.glsl)
// the block `dp`.
#ifndef PW_DOMAIN_INTERFACE_H
#define PW_DOMAIN_INTERFACE_H

#include "core/gpu/patch_math.h"

PW_BEGIN_NAMESPACE

PW_BLOCK(layout(push_constant) uniform DomainPushBlock, DomainPush) {
    vec4 outer;      // requested outer levels (quad: u0, v0, u1, v1; triangle: u0, v0, w0; isoline: lines, segments)
    vec4 inner;      // xy requested inner levels; z = 1: pow2 emulation (next power of two, equal spacing)
    vec4 transform;  // clip = domain * xy + zw (domain coordinates: x right, y up, in [0,1]^2)
    vec4 color;      // colour of this pass
    vec4 point;      // x point size (point-size variants only)
}
PW_END_BLOCK(dp)

PW_END_NAMESPACE

#ifdef __cplusplus
static_assert(sizeof(pw::gpu::DomainPush) == 80);
#endif

#endif  // PW_DOMAIN_INTERFACE_H

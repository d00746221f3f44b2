// The colour of a tessellation level, written once for `--shading level` (shaders/surface.frag) and
// its legend (render/figures/level_legend.cpp): log2 of the level over 1..64 through the viridis
// ramp (dark violet at 1, yellow at 64; readable in grey and by colour-blind viewers), so each
// doubling of the level is one equal step of colour.
#ifndef PW_LEVEL_COLOUR_H
#define PW_LEVEL_COLOUR_H

#include "core/gpu/glsl_cpp.h"

PW_BEGIN_NAMESPACE

PW_FN vec3 levelColour(float level) {
    const float t = clamp(log2(max(level, 1.0f)) / 6.0f, 0.0f, 1.0f) * 4.0f;
    const vec3 c0 = vec3(0.267f, 0.005f, 0.329f), c1 = vec3(0.229f, 0.322f, 0.546f), c2 = vec3(0.128f, 0.567f, 0.551f),
               c3 = vec3(0.369f, 0.789f, 0.383f), c4 = vec3(0.993f, 0.906f, 0.144f);
    if (t < 1.0f) return mix(c0, c1, t);
    if (t < 2.0f) return mix(c1, c2, t - 1.0f);
    if (t < 3.0f) return mix(c2, c3, t - 2.0f);
    return mix(c3, c4, min(t - 3.0f, 1.0f));
}

PW_END_NAMESPACE

#endif

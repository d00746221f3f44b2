#include "core/tess/tess_levels.hpp"

#include <algorithm>
#include <cmath>

#include "core/gpu/patch_math.h"
#include "core/tess/tess_domain.hpp"

namespace pw::render {

int roundedSegments(float f, Spacing spacing) {
    // The control shader's rounding, then the tessellator's (core/gpu/patch_math.h, core/tess/tess_domain.hpp).
    return segmentCount(gpu::roundLevel(f, uint32_t(spacing)), tessellatorSpacing(spacing));
}

int maxSegments(const TessSettings& tess, float overrideMax, float deviceMax) {
    float m = 1.0f;
    if (tess.adaptive != AdaptiveMode::None) {
        m = std::min({tess.maxLevel, deviceMax, 64.0f});
    } else {
        for (float f : tess.outer) m = std::max(m, f);
        for (float f : tess.inner) m = std::max(m, f);
    }
    m = std::max(m, overrideMax);
    return roundedSegments(m, tess.spacing);
}

uint32_t patchesPerDraw(int maxLevel, uint32_t vertexBudget) {
    if (vertexBudget == 0) return UINT32_MAX;
    const int l = std::max(maxLevel, 1);
    return std::max<uint32_t>(1u, vertexBudget / uint32_t((l + 2) * (l + 2)));
}

}  // namespace pw::render

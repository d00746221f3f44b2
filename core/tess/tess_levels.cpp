#include "core/tess/tess_levels.hpp"

#include <algorithm>
#include <cmath>

#include "core/gpu/patch_math.h"
#include "core/tess/tess_domain.hpp"

namespace pw {
inline namespace tess {

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

FrameLoad frameLoad(const Document& doc, const TessSettings& tess) {
    FrameLoad l;
    float overrideMax = 0.0f;
    for (const Patch& p : doc.patches) {
        ++l.patches;
        if (p.tessOverride)
            for (float f : *p.tessOverride) overrideMax = std::max(overrideMax, f);
    }
    for (const Surface& s : doc.surfaces) {
        const uint32_t step = netStep(s.basis);
        l.patches += netWindowCount(s.rows, s.closedV, step) * netWindowCount(s.cols, s.closedU, step);
    }
    for (const TrianglePatch& t : doc.triangles) {
        ++l.patches;
        if (t.tessOverride)
            for (float f : *t.tessOverride) overrideMax = std::max(overrideMax, f);
    }
    l.segments = maxSegments(tess, overrideMax);
    l.evaluations = l.patches * uint64_t(l.segments + 1) * uint64_t(l.segments + 1);
    return l;
}

uint32_t patchesPerDraw(int maxLevel, uint32_t vertexBudget) {
    if (vertexBudget == 0) return UINT32_MAX;
    const int l = std::max(maxLevel, 1);
    return std::max<uint32_t>(1u, vertexBudget / uint32_t((l + 2) * (l + 2)));
}

}  // namespace tess
}  // namespace pw

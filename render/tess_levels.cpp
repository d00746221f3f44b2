#include "render/tess_levels.hpp"

#include <algorithm>
#include <cmath>

namespace pw::render {

int roundedSegments(float f, Spacing spacing) {
    if (!(f == f)) f = 1.0f;
    switch (spacing) {
        case Spacing::Equal: return std::clamp(int(std::ceil(f)), 1, 64);
        case Spacing::FractionalOdd: {
            int n = int(std::ceil(std::clamp(f, 1.0f, 63.0f)));
            if (n % 2 == 0) ++n;
            return std::min(n, 63);
        }
        case Spacing::FractionalEven: {
            int n = int(std::ceil(std::clamp(f, 2.0f, 64.0f)));
            if (n % 2 == 1) ++n;
            return std::min(n, 64);
        }
        case Spacing::Pow2: {
            const int c = std::clamp(int(std::ceil(f)), 1, 64);
            int p = 1;
            while (p < c) p *= 2;
            return p;
        }
    }
    return 1;
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

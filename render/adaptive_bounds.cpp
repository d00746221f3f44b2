#include "render/adaptive_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "render/tess_levels.hpp"

namespace pw::render {

std::vector<uint8_t> adaptiveLevelBounds(const SurfaceScene& s, const TessSettings& tess, const ViewMatrices& vm,
                                         float viewportW, float viewportH, float maxLevel) {
    std::vector<uint8_t> out(s.windowCount, uint8_t(roundedSegments(maxLevel, tess.spacing)));
    if (tess.adaptive != AdaptiveMode::Distance && tess.adaptive != AdaptiveMode::ScreenSpace) return out;
    std::vector<uint32_t> kind(s.windowCount, 0);
    for (const BasisRun& r : s.runs)
        for (uint32_t w = r.first; w < r.first + r.count; ++w) kind[w] = r.basisKind;
    const float d0 = tess.distanceNear, d1 = tess.distanceFar;
    for (uint32_t w = 0; w < s.windowCount; ++w) {
        const uint32_t* idx = &s.cpuIndices[size_t(w) * 16];
        const int nearRow = kind[w] == 0 ? 0 : 1, farRow = 3 - nearRow;
        auto slot = [&](int e, int k) {
            if (e == 0) return k * 4 + nearRow;
            if (e == 1) return nearRow * 4 + k;
            if (e == 2) return k * 4 + farRow;
            return farRow * 4 + k;
        };
        float level = 1.0f;
        for (int e = 0; e < 4; ++e) {
            glm::vec3 p[4];
            for (int k = 0; k < 4; ++k) p[k] = s.cpuPoints[idx[slot(e, k)]];
            float l = maxLevel;
            if (tess.adaptive == AdaptiveMode::Distance) {
                const float d = glm::distance(vm.eye, 0.5f * (p[0] + p[3]));
                l = maxLevel * std::clamp((d1 - d) / std::max(d1 - d0, 1e-6f), 0.0f, 1.0f);
            } else {
                bool behind = false;
                glm::vec2 px[4];
                for (int k = 0; k < 4; ++k) {
                    const glm::vec4 c = vm.viewProj * glm::vec4(p[k], 1.0f);
                    behind = behind || c.w <= 1e-6f;
                    px[k] = (glm::vec2(c.x, c.y) / std::max(c.w, 1e-6f) * 0.5f + 0.5f) * glm::vec2(viewportW, viewportH);
                }
                if (!behind)
                    l = (glm::distance(px[0], px[1]) + glm::distance(px[1], px[2]) + glm::distance(px[2], px[3])) /
                        std::max(tess.targetPixels, 0.5f);
            }
            level = std::max(level, std::clamp(l, 1.0f, maxLevel));
        }
        level = std::max(level, s.overrideLevel[w]);
        out[w] = uint8_t(std::min(64, roundedSegments(level, tess.spacing) + 1));
    }
    return out;
}

}  // namespace pw::render

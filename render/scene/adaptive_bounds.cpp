#include "render/scene/adaptive_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "core/gpu/patch_math.h"
#include "core/tess/tess_levels.hpp"

namespace pw::render {
inline namespace scene {

namespace {

// The segments an edge of raw level `l` gets, when the control shader's float arithmetic (which may
// differ from this in the last bits) cannot round it differently; 0 when it could.
int certainSegments(float l, Spacing spacing, float maxLevel) {
    if (!std::isfinite(l)) return 0;
    const float slack = 1e-3f * std::max(1.0f, l);
    const int lo = roundedSegments(std::clamp(l - slack, 1.0f, maxLevel), spacing);
    const int hi = roundedSegments(std::clamp(l + slack, 1.0f, maxLevel), spacing);
    return lo == hi ? lo : 0;
}

}  // namespace

std::vector<uint8_t> adaptiveLevelBounds(const SurfaceScene& s, const TessSettings& tess, const ViewMatrices& vm, float viewportW,
                                         float viewportH, float maxLevel, std::vector<DirectionLevels>* uniform) {
    std::vector<uint8_t> out(s.windowCount, uint8_t(roundedSegments(maxLevel, tess.spacing)));
    if (uniform) uniform->assign(s.windowCount, DirectionLevels{});
    if (tess.adaptive == AdaptiveMode::None) return out;
    std::vector<uint32_t> kind(s.windowCount, 0);
    for (const BasisRun& r : s.runs)
        for (uint32_t w = r.first; w < r.first + r.count; ++w) kind[w] = r.basisKind;
    const glm::vec2 viewport(viewportW, viewportH);
    const glm::vec2 exps(tess.distanceExponents[0], tess.distanceExponents[1]);
    const bool fromCentre = tess.adaptive == AdaptiveMode::Distance && tess.distanceFrom != DistanceFrom::Edges;
    for (uint32_t w = 0; w < s.windowCount; ++w) {
        const uint32_t* idx = &s.cpuIndices[size_t(w) * 16];
        const int depth = kind[w] == gpu::kBasisBezier ? 0 : 1;  // as the control shader's edgeSlot
        float level = 1.0f;
        int certain[4] = {0, 0, 0, 0};  // the segments each edge certainly gets; 0 when uncertain
        for (int e = 0; e < 4; ++e) {
            uint32_t pool[4];
            for (int k = 0; k < 4; ++k) pool[k] = idx[gpu::quadEdgeSlot(e, k, depth)];
            const bool rev = gpu::edgeReversed(pool[0], pool[1], pool[2], pool[3]);
            glm::vec3 p[4];
            for (int k = 0; k < 4; ++k) p[k] = s.cpuPoints[pool[rev ? 3 - k : k]];
            const float l =
                gpu::adaptiveEdgeLevel(p[0], p[1], p[2], p[3], uint32_t(tess.adaptive), maxLevel, vm.eye, tess.distanceNear,
                                       tess.distanceFar, uint32_t(tess.distanceCurve), exps, vm.viewProj, viewport, tess.targetPixels);
            level = std::max(level, std::clamp(l, 1.0f, maxLevel));
            if (uniform) certain[e] = certainSegments(l, tess.spacing, maxLevel);
        }
        if (fromCentre) {  // the control shader's netCentre: the mean of the 16 control points
            glm::vec3 c(0.0f);
            for (int k = 0; k < 16; ++k) c += s.cpuPoints[idx[k]];
            const float l = gpu::distanceLevel(glm::distance(vm.eye, c / 16.0f), maxLevel, tess.distanceNear, tess.distanceFar,
                                               uint32_t(tess.distanceCurve), exps);
            level = std::max(level, std::clamp(l, 1.0f, maxLevel));
            certain[0] = 0;  // the inner levels come from elsewhere than the edges
        }
        level = std::max(level, s.overrideLevel[w]);
        out[w] = uint8_t(std::min(64, roundedSegments(level, tess.spacing) + 1));
        // Inner levels are the larger opposite edges': equal opposite edges make one level along
        // each direction (edges 1 and 3 run along u, 0 and 2 along v).
        if (uniform && s.overrideLevel[w] == 0.0f && certain[0] > 0 && certain[0] == certain[2] && certain[1] > 0 &&
            certain[1] == certain[3])
            (*uniform)[w] = DirectionLevels{uint8_t(certain[1]), uint8_t(certain[0])};
    }
    return out;
}

}  // namespace scene
}  // namespace pw::render

// CPU side of the tessellation-level rules (DESIGN §3) used for batching and reporting: the number
// of segments a requested level becomes under each spacing, and patches per draw (DESIGN §4).
#pragma once

#include <cstdint>

#include "core/model/document.hpp"

namespace pw {
inline namespace tess {

// Segments on an edge with requested level f: equal ceil(f) in [1,64]; fractional_odd next odd >= f
// in [1,63]; fractional_even next even >= f in [2,64]; pow2 next power of two in [1,64].
int roundedSegments(float f, Spacing spacing);

// The largest number of segments any edge of any patch can get with these settings
// (adaptive: bounded by the max level).
int maxSegments(const TessSettings& tess, float overrideMax, float deviceMax = 64.0f);

// What a frame at these settings asks of the tessellator at most: the patches (single patches, net
// windows and Bézier triangles) and the evaluation vertices at the largest level any can get.
struct FrameLoad {
    uint64_t patches = 0, evaluations = 0;
    int segments = 1;  // the largest level, rounded
};
FrameLoad frameLoad(const Document& doc, const TessSettings& tess);
// Past this a CPU implementation (lavapipe) draws a frame in more than about a fifth of a second
// (~0.1 µs an evaluation vertex, besides ~15 µs a patch, which no choice of levels removes): the
// editor draws such a document screen-adaptive unless asked for full detail.
inline constexpr uint64_t kCpuInteractiveEvaluations = 2'000'000;
inline bool heavyForCpu(const FrameLoad& l) { return l.evaluations > kCpuInteractiveEvaluations; }

// Evaluation vertices per vkCmdDraw on CPU implementations: lavapipe's tessellator slows down past
// a few thousand and renders wrong pixels past 65 535 (DESIGN §4). GPUs get no limit (0).
inline constexpr uint32_t kCpuDrawVertexBudget = 4096;

// Patches per vkCmdDraw so that patches x (L+2)^2 <= vertexBudget evaluation vertices;
// vertexBudget 0 = unlimited (one draw per basis run).
uint32_t patchesPerDraw(int maxLevel, uint32_t vertexBudget = kCpuDrawVertexBudget);

}  // namespace tess
}  // namespace pw

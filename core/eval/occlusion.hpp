// Which control points the surface hides from the eye, pure (no Vulkan): box selection takes only
// the points you can see (Blender's solid mode; X-ray selects through). The shown windows and
// Bézier triangles are tessellated on the CPU and rasterised into a depth buffer of the view.
#pragma once

#include <cstdint>
#include <vector>

#include "core/model/camera_math.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace eval {

// The points of `candidates` that no shown surface lies in front of, in a width x height view.
// Each window is a `level` x `level` grid, each triangle its barycentric grid; a point on the
// surface itself (a corner, a flat patch's inner points) counts as seen: the surface must lie in
// front of it by more than 1 % of the model size, at every pixel next to its own.
std::vector<uint32_t> unoccludedPoints(const Document& doc, const Camera& cam, int width, int height,
                                       const std::vector<uint32_t>& candidates, int level = 8);

}  // namespace eval
}  // namespace pw

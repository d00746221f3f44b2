// Editor picking maths, pure (no Vulkan): the ray under the mouse, the nearest projected control
// point within a pixel radius, box selection, ray–surface picking of patches (CPU tessellation),
// and the drag helpers (move in the view plane, along an axis, grid snapping).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "core/model/camera_math.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace select {

struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 dir{0.0, 0.0, -1.0};  // unit length
};

// The ray through pixel (x, y) (origin top-left, y down) of a width x height viewport. Perspective:
// from the eye; orthographic: from the near plane, along the view direction.
Ray rayThroughPixel(const Camera& cam, double x, double y, int width, int height);

// Projected pixel positions of every pool point (nullopt behind the camera).
std::vector<std::optional<glm::dvec2>> projectPoints(const Camera& cam, const std::vector<Vec3>& points, int width, int height);

// Nearest pool point whose projection lies within `radiusPx` of (x, y); ties go to the point
// nearer the eye. -1 when none. Only points used by some patch, surface or triangle count when `used` is
// given (a mask the size of the pool).
int pickPoint(const Camera& cam, const std::vector<Vec3>& points, double x, double y, int width, int height, double radiusPx,
              const std::vector<bool>* used = nullptr);

// Pool points whose projections fall inside the pixel rectangle spanned by a and b.
std::vector<uint32_t> pointsInBox(const Camera& cam, const std::vector<Vec3>& points, glm::dvec2 a, glm::dvec2 b, int width, int height,
                                  const std::vector<bool>* used = nullptr);

// Mask of pool points referenced by a patch, a surface or a triangle.
std::vector<bool> usedPointMask(const Document& doc);

// Ray–triangle (Möller–Trumbore); the distance along the ray, or nullopt.
std::optional<double> intersectTriangle(const Ray& ray, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

struct SurfaceHit {
    int instance = -1;  // index into expandPatches(doc)
    int patch = -1;     // Document::patches index or -1 (surface window)
    int surface = -1;
    int triangle = -1;        // Document::triangles index or -1 (then instance is -1 too)
    double t = 0.0;           // distance along the ray
    double u = 0.0, v = 0.0;  // window parameters, or a triangle's barycentric u, v
};
// Nearest hit of the ray with the surface: each window tessellated as a `level` x `level` grid,
// each Bézier triangle as its barycentric grid at `level`; hidden items are not hit. `skip` (a pool mask): windows and
// triangles with a control point in it are not hit (what a transform moves, when snapping).
std::optional<SurfaceHit> pickSurface(const Document& doc, const Ray& ray, int level = 12, const std::vector<bool>* skip = nullptr);

// Distance in pixels from p to the segment a-b (the join tool's edges, the gizmo's arrows).
double segmentDistance(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b);

// Where the ray meets the plane through `point` with normal `normal` (nullopt when parallel or behind).
std::optional<glm::dvec3> intersectPlane(const Ray& ray, const glm::dvec3& point, const glm::dvec3& normal);

// How a direction through `at` shows on screen: pixels per world unit along it (a 2-D vector, y
// down) and pixels per world unit across the view there. The axis drag's rate bound and the move
// gizmo's arrows both use it. nullopt when `at` is behind the camera.
struct AxisOnScreen {
    glm::dvec2 alongPx{0.0};
    double acrossPx = 0.0;
};
std::optional<AxisOnScreen> axisOnScreen(const Camera& cam, int width, int height, const glm::dvec3& at, const glm::dvec3& axis);

// True when any of the pool indices `idx` is set in `mask` (indices past its end count as unset).
template <class Idx>
bool usesAnyPoint(const Idx& idx, const std::vector<bool>& mask) {
    for (uint32_t p : idx)
        if (p < mask.size() && mask[p]) return true;
    return false;
}

// Point on the line (origin, axis) closest to the ray.
glm::dvec3 closestPointOnAxis(const Ray& ray, const glm::dvec3& origin, const glm::dvec3& axis);

// Rounds each component of v to a multiple of step (step <= 0: unchanged).
glm::dvec3 snapToGrid(const glm::dvec3& v, double step);

// A "nice" grid step (1, 2 or 5 × 10^k) about a tenth of the model size.
double niceGridStep(double modelSize);

}  // namespace select
}  // namespace pw

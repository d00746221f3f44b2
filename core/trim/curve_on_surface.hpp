// Curves laid on surfaces (issue 64): a document curve mapped into a surface's (u, v) domain
// (closest points, or along a direction) and made a trim loop there; a curve projected onto a
// surface as a new 3D curve.
#pragma once

#include <optional>
#include <vector>

#include "core/model/document.hpp"
#include "core/trim/surface_domain.hpp"

namespace pw {
inline namespace trim {

inline constexpr int kCurveSamplesPerSegment = 48;

// Points along the curve, kCurveSamplesPerSegment per segment (rational segments included); a
// closed curve does not repeat its first point.
std::vector<Vec3> sampleCurve(const Document& doc, const BezierCurve& c);
// Each point's place in the surface's domain: the closest point, or where the line through it
// along `direction` (not zero) meets the surface. Throws EditError naming the curve when a point
// misses the surface.
std::vector<UV> pointsToDomain(const DomainSurface& s, const std::vector<Vec3>& points, const Vec3& direction, const std::string& what);

// A trim loop from a curve's points in the domain: a closed curve in the domain, or one that runs
// once round a closed direction of a net (then it is closed along the domain's boundary round the
// smaller part, which is its inside). Fitted by cubic segments within 2e-6 of the domain: with
// `perSegment` samples a segment (sampleCurve's), segment by segment at the samples' own parameters
// (exact where the domain map is affine; corners kept), else one C2 fit. Oriented for `hole`.
// Throws EditError when the points do not make a loop (an open curve).
TrimLoop loopFromDomainPoints(const std::vector<UV>& uv, bool closedCurve, bool closedU, bool closedV, bool hole, const std::string& what,
                              int perSegment = 0);

// The trim loop that curve `curve` makes on surface `s` (live: the loop keeps `curve`, `direction`, `hole`).
TrimLoop loopFromCurve(const Document& doc, const SurfaceRef& s, uint32_t curve, const Vec3& direction, bool hole);

}  // namespace trim
}  // namespace pw

// Cubic Bézier curves (BezierCurve in document.hpp): evaluation by de Casteljau's construction,
// exact at the ends (t = 0 gives the first point, t = 1 the last, bit for bit), and uniform samples
// for export. The GPU draws the same curves through the isoline tessellator (shaders/curve.tese).
#pragma once

#include <array>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace eval {

// The point at parameter t in [0, 1].
Vec3 evaluateCurve(const std::array<Vec3, 4>& p, double t);
// The derivative dp/dt.
Vec3 curveTangent(const std::array<Vec3, 4>& p, double t);
// The four control points of segment s of a curve, from the document's pool.
std::array<Vec3, 4> curvePoints(const Document& doc, const BezierCurve& c, size_t s = 0);
// segments + 1 points at t = i / segments (segments >= 1).
std::vector<Vec3> sampleCurve(const std::array<Vec3, 4>& p, int segments);
// The same for every segment of a curve of the document, one after the other (a segment's first
// sample is the previous one's last, kept once): n * segments + 1 points, rational where its
// points have weights, exact at every segment's ends.
std::vector<Vec3> sampleCurve(const Document& doc, const BezierCurve& c, int segments);

}  // namespace eval
}  // namespace pw

// Curves to build surfaces from (issue 39): C2 cubic splines through points, clamped uniform
// cubic B-splines from control points, and exact rational circles and arcs, each as a chain of
// cubic Bézier segments (BezierCurve in core/model/document.hpp). The spline arithmetic works on
// homogeneous points (w·P, w), so the same interpolation serves lofts through rational sections.
#pragma once

#include <cstdint>
#include <glm/vec4.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/base/math_types.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace construct {

using HPoint = glm::dvec4;  // homogeneous: (w·x, w·y, w·z, w)
inline HPoint homogeneous(const Vec3& p, double w = 1.0) { return HPoint(p * w, w); }
inline Vec3 euclidean(const HPoint& h) { return Vec3(h) / h.w; }

// A composite cubic Bézier chain: 3n + 1 homogeneous control points; closed when the last is the
// first (then only n segments, the chain ends where it starts).
struct CurveShape {
    std::vector<HPoint> points;
    bool closed = false;
    size_t segments() const { return points.size() >= 4 ? (points.size() - 1) / 3 : 0; }
};

// The Bézier points of the C2 cubic spline that takes values q[i] at parameters t[i] (strictly
// increasing; closed: one more parameter, where the spline is back at q[0]). Ends of an open
// spline are natural (no second derivative), or clamped to the derivative startD / endD where one
// is given. 2 values and no derivative give the straight segment. 3n + 1 points.
std::vector<HPoint> splineThrough(const std::vector<HPoint>& q, const std::vector<double>& t, bool closed,
                                  const std::optional<HPoint>& startD = std::nullopt, const std::optional<HPoint>& endD = std::nullopt);
// Chord-length parameters of points (closed: back to the first); EditError when two consecutive
// points coincide.
std::vector<double> chordParameters(const std::vector<Vec3>& p, bool closed);

// `curve-through`: the C2 cubic through the points (2 or more) at chord-length parameters.
CurveShape curveThrough(const std::vector<Vec3>& points, bool closed = false);
// `curve-control`: the clamped uniform cubic B-spline of these control points (4 or more), as
// Bézier segments (Boehm's knot insertion to full multiplicity): one segment per knot span.
CurveShape curveControl(const std::vector<Vec3>& controls);
// `add-arc`: the exact arc of radius r about `center` from direction e1 towards e2 (unit,
// orthogonal) through `degrees` in (0, 360]: rational quadratic arcs of at most 90° (middle
// weight cos(θ/2)) raised to cubics; 360° gives the closed circle of four quarters.
CurveShape arcCurve(const Vec3& center, const Vec3& e1, const Vec3& e2, double r, double degrees);

// Adds the shape as a new curve (its points to the pool, the closing index shared); returns its
// index. EditError when the document is full.
uint32_t addCurveShape(Document& doc, const CurveShape& shape, const std::string& name);

}  // namespace construct
}  // namespace pw

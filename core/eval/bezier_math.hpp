// The evaluation of a bicubic Bézier patch at one (u, v) as a lecture shows it (issue 41, "the
// math on screen"): the Bernstein weights of the 16 control points, the tensor product's 4 + 4
// factors, the de Casteljau construction of every row in u and of the column through the rows'
// points in v, and the point with its tangents and normal. Rational patches run de Casteljau on
// the homogeneous points (each step drawn projected), their weights are w·B / Σ w·B. The editor's
// Bézier math overlay and `render --math` draw the same diagram (bezierMathDiagram).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/base/math_types.hpp"

namespace pw {
inline namespace eval {

// One de Casteljau pyramid over four points at t: two intermediate levels and the point.
struct CasteljauSteps {
    std::array<Vec3, 3> first{};   // lerps of the control polygon
    std::array<Vec3, 2> second{};  // lerps of those: the tangent segment at the point
    Vec3 point{0.0};
};

struct BezierMath {
    double u = 0.0, v = 0.0;
    std::array<double, 4> bu{}, bv{};      // B_j(u) and B_i(v)
    std::array<double, 16> weights{};      // of net point i * 4 + j: B_i(v) B_j(u) (rational: w·B / Σ w·B); they sum to 1
    std::array<CasteljauSteps, 4> rows{};  // row i (net points i*4 .. i*4+3) at u
    CasteljauSteps column;                 // the rows' points at v
    Vec3 point{0.0}, du{0.0}, dv{0.0}, normal{0.0};
};

// `weights`: the patch's point weights, or none (polynomial). (u, v) within [0, 1].
BezierMath bezierMath(const Net16& net, const std::optional<Weights16>& weights, double u, double v);

// The diagram both front ends draw: strokes and dots in model coordinates, each with a role that
// fixes its colour and weight, and labels (a control point's weight, the evaluated point).
struct MathDiagram {
    enum class Role { Net, RowStep, Row, ColumnStep, Column, Point, TangentU, TangentV, Normal };
    struct Stroke {
        Vec3 a{0.0}, b{0.0};
        Role role = Role::Net;
    };
    struct Dot {
        Vec3 p{0.0};
        double radius = 1.0;  // times the front end's base dot size
        Role role = Role::Net;
        std::string label;  // drawn beside the dot; empty: none
    };
    std::vector<Stroke> strokes;
    std::vector<Dot> dots;
    std::vector<std::string> legend;  // the lines of the side box: u, v, the 4 + 4 factors, point, tangents, normal
    std::vector<Role> legendRoles;    // each line's colour: B(u) the rows', B(v) the column's, the arrows' their own
};
// The tangent and normal arrows are a quarter of the net's bounding-box diagonal long (the tangents
// keep their ratio, the longer one that long).
MathDiagram bezierMathDiagram(const Net16& net, const BezierMath& m);
std::array<unsigned char, 4> mathColor(MathDiagram::Role role);  // RGBA
// Stroke width and control-point dot radius in pixels beside labels `textPixels` high (set for
// 13-pixel text, the interface font's base size, and grown with the text).
float mathStrokeWidth(MathDiagram::Role role, float textPixels);
float mathDotRadius(float textPixels);

}  // namespace eval
}  // namespace pw

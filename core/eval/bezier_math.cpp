#include "core/eval/bezier_math.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/vec4.hpp>

#include "core/eval/patch_eval.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace eval {

namespace {

// Homogeneous point (w·P, w).
using Homog = glm::dvec4;

Vec3 projectHomog(const Homog& h) { return Vec3(h) / h.w; }

CasteljauSteps casteljauSteps(const std::array<Homog, 4>& p, double t, Homog& out) {
    CasteljauSteps s;
    const Homog a = glm::mix(p[0], p[1], t), b = glm::mix(p[1], p[2], t), c = glm::mix(p[2], p[3], t);
    const Homog d = glm::mix(a, b, t), e = glm::mix(b, c, t);
    out = glm::mix(d, e, t);
    s.first = {projectHomog(a), projectHomog(b), projectHomog(c)};
    s.second = {projectHomog(d), projectHomog(e)};
    s.point = projectHomog(out);
    return s;
}

std::array<double, 4> bernsteinAt(double t) {
    const double s = 1.0 - t;
    return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

std::string fixedText(double x, int digits = 3) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f", digits, std::abs(x) < 0.5 * std::pow(10.0, -digits) ? 0.0 : x);
    return buf;
}

std::string vecText(const Vec3& p) { return "(" + fixedText(p.x) + ", " + fixedText(p.y) + ", " + fixedText(p.z) + ")"; }

std::string factorList(const std::array<double, 4>& b) {
    return fixedText(b[0]) + "  " + fixedText(b[1]) + "  " + fixedText(b[2]) + "  " + fixedText(b[3]);
}

}  // namespace

BezierMath bezierMath(const Net16& net, const std::optional<Weights16>& weights, double u, double v) {
    BezierMath m;
    m.u = u;
    m.v = v;
    m.bu = bernsteinAt(u);
    m.bv = bernsteinAt(v);
    double total = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const double w = weights ? (*weights)[size_t(i * 4 + j)] : 1.0;
            m.weights[size_t(i * 4 + j)] = w * m.bv[size_t(i)] * m.bu[size_t(j)];
            total += m.weights[size_t(i * 4 + j)];
        }
    for (double& w : m.weights) w /= total;
    std::array<Homog, 4> column{};
    for (int i = 0; i < 4; ++i) {
        std::array<Homog, 4> row{};
        for (int j = 0; j < 4; ++j) {
            const double w = weights ? (*weights)[size_t(i * 4 + j)] : 1.0;
            row[size_t(j)] = Homog(net[size_t(i * 4 + j)] * w, w);
        }
        m.rows[size_t(i)] = casteljauSteps(row, u, column[size_t(i)]);
    }
    Homog point{};
    m.column = casteljauSteps(column, v, point);
    const SurfacePoint sp = evaluateWindow(WindowNet{net, weights}, Basis::Bezier, 0.5, u, v);
    m.point = sp.p;
    m.du = sp.du;
    m.dv = sp.dv;
    m.normal = sp.n;
    return m;
}

MathDiagram bezierMathDiagram(const Net16& net, const BezierMath& m) {
    using Role = MathDiagram::Role;
    Bounds box;
    for (const Vec3& q : net) box.add(q);
    const double arrow = 0.25 * std::max(box.diagonal(), 1e-9);
    MathDiagram d;
    const auto stroke = [&](const Vec3& a, const Vec3& b, Role r) { d.strokes.push_back({a, b, r}); };
    // The control net, each point sized by and labelled with its weight.
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const size_t k = size_t(i * 4 + j);
            if (j < 3) stroke(net[k], net[k + 1], Role::Net);
            if (i < 3) stroke(net[k], net[k + 4], Role::Net);
            d.dots.push_back({net[k], 0.6 + 2.4 * std::sqrt(m.weights[k]), Role::Net, fixedText(m.weights[k])});
        }
    // Each row's de Casteljau pyramid in u, then the column through the rows' points in v.
    const auto pyramid = [&](const CasteljauSteps& s, Role step, Role result) {
        stroke(s.first[0], s.first[1], step);
        stroke(s.first[1], s.first[2], step);
        stroke(s.second[0], s.second[1], step);
        for (const Vec3& p : s.first) d.dots.push_back({p, 0.5, step, {}});
        for (const Vec3& p : s.second) d.dots.push_back({p, 0.6, step, {}});
        d.dots.push_back({s.point, 0.9, result, {}});
    };
    for (const CasteljauSteps& r : m.rows) pyramid(r, Role::RowStep, Role::Row);
    for (int i = 0; i < 3; ++i) stroke(m.rows[size_t(i)].point, m.rows[size_t(i + 1)].point, Role::Column);
    pyramid(m.column, Role::ColumnStep, Role::Column);
    // The point, its tangents (their ratio kept) and the unit normal.
    const double longest = std::max({glm::length(m.du), glm::length(m.dv), 1e-300});
    stroke(m.point, m.point + m.du * (arrow / longest), Role::TangentU);
    stroke(m.point, m.point + m.dv * (arrow / longest), Role::TangentV);
    stroke(m.point, m.point + m.normal * arrow, Role::Normal);
    d.dots.push_back({m.point, 1.6, Role::Point, "S(" + fixedText(m.u, 2) + ", " + fixedText(m.v, 2) + ")"});
    d.legend = {"u = " + fixedText(m.u) + "   v = " + fixedText(m.v),
                "B(u) = " + factorList(m.bu),
                "B(v) = " + factorList(m.bv),
                "S = " + vecText(m.point),
                "dS/du = " + vecText(m.du),
                "dS/dv = " + vecText(m.dv),
                "n = " + vecText(m.normal)};
    d.legendRoles = {Role::Point, Role::Row, Role::Column, Role::Point, Role::TangentU, Role::TangentV, Role::Normal};
    return d;
}

std::array<unsigned char, 4> mathColor(MathDiagram::Role role) {
    using Role = MathDiagram::Role;
    switch (role) {
        case Role::Net:
            return {255, 150, 40, 255};
        case Role::RowStep:
            return {90, 200, 255, 200};
        case Role::Row:
            return {90, 200, 255, 255};
        case Role::ColumnStep:
            return {255, 90, 220, 220};
        case Role::Column:
            return {255, 90, 220, 255};
        case Role::Point:
            return {255, 255, 255, 255};
        case Role::TangentU:
            return {240, 60, 50, 255};
        case Role::TangentV:
            return {60, 210, 80, 255};
        case Role::Normal:
            return {70, 120, 255, 255};
    }
    return {255, 255, 255, 255};
}

namespace {

constexpr float kMathBaseTextPixels = 13.0f;

// Stroke width for 13-pixel text.
float baseStrokeWidth(MathDiagram::Role role) {
    using Role = MathDiagram::Role;
    switch (role) {
        case Role::Net:
            return 1.5f;
        case Role::RowStep:
            return 1.0f;
        case Role::ColumnStep:
            return 2.0f;
        case Role::Column:
            return 2.5f;
        case Role::TangentU:
        case Role::TangentV:
        case Role::Normal:
            return 3.0f;
        default:
            return 1.5f;
    }
}

}  // namespace

float mathStrokeWidth(MathDiagram::Role role, float textPixels) { return baseStrokeWidth(role) * textPixels / kMathBaseTextPixels; }
float mathDotRadius(float textPixels) { return 3.0f * textPixels / kMathBaseTextPixels; }

}  // namespace eval
}  // namespace pw

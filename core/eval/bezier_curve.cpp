#include "core/eval/bezier_curve.hpp"

#include <algorithm>

#include "core/eval/rational_eval.hpp"

namespace pw {
inline namespace eval {

Vec3 evaluateCurve(const std::array<Vec3, 4>& p, double t) {
    if (t <= 0.0) return p[0];
    if (t >= 1.0) return p[3];
    const Vec3 a = glm::mix(p[0], p[1], t), b = glm::mix(p[1], p[2], t), c = glm::mix(p[2], p[3], t);
    const Vec3 d = glm::mix(a, b, t), e = glm::mix(b, c, t);
    return glm::mix(d, e, t);
}

Vec3 curveTangent(const std::array<Vec3, 4>& p, double t) {
    const double s = 1.0 - t;
    return 3.0 * (s * s * (p[1] - p[0]) + 2.0 * s * t * (p[2] - p[1]) + t * t * (p[3] - p[2]));
}

std::array<Vec3, 4> curvePoints(const Document& doc, const BezierCurve& c, size_t s) {
    const std::array<uint32_t, 4> i = curveSegment(c, s);
    return {doc.points.at(i[0]), doc.points.at(i[1]), doc.points.at(i[2]), doc.points.at(i[3])};
}

std::vector<Vec3> sampleCurve(const std::array<Vec3, 4>& p, int segments) {
    segments = std::max(segments, 1);
    std::vector<Vec3> out(size_t(segments) + 1);
    for (int i = 0; i <= segments; ++i) out[size_t(i)] = evaluateCurve(p, double(i) / double(segments));
    return out;
}

std::vector<Vec3> sampleCurve(const Document& doc, const BezierCurve& c, int segments) {
    segments = std::max(segments, 1);
    std::vector<Vec3> out;
    out.reserve(curveSegmentCount(c) * size_t(segments) + 1);
    for (size_t s = 0; s < curveSegmentCount(c); ++s) {
        const std::array<uint32_t, 4> i = curveSegment(c, s);
        const std::array<Vec3, 4> p = curvePoints(doc, c, s);
        const std::array<double, 4> w{pointWeight(doc, i[0]), pointWeight(doc, i[1]), pointWeight(doc, i[2]), pointWeight(doc, i[3])};
        const bool rational = w != std::array<double, 4>{1.0, 1.0, 1.0, 1.0};
        for (int k = s == 0 ? 0 : 1; k <= segments; ++k) {
            const double t = double(k) / double(segments);
            out.push_back(k == 0 ? p[0] : k == segments ? p[3] : rational ? evaluateRationalCurve(p, w, t).p : evaluateCurve(p, t));
        }
    }
    return out;
}

}  // namespace eval
}  // namespace pw

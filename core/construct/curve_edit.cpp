#include "core/construct/curve_edit.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/construct/curves.hpp"

namespace pw {
inline namespace construct {

namespace {

HPoint at(const Document& doc, uint32_t i) { return homogeneous(doc.points[i], pointWeight(doc, i)); }

uint32_t add(Document& doc, const HPoint& h) {
    doc.points.push_back(euclidean(h));
    const uint32_t i = uint32_t(doc.points.size() - 1);
    if (h.w != 1.0) setPointWeight(doc, i, h.w);
    return i;
}

BezierCurve& curveOf(Document& doc, uint32_t c) {
    if (c >= doc.curves.size()) throw EditError("curve c" + std::to_string(c) + " does not exist");
    return doc.curves[c];
}

}  // namespace

void insertCurvePoint(Document& doc, uint32_t c, double t) {
    BezierCurve& cv = curveOf(doc, c);
    const size_t n = curveSegmentCount(cv);
    const double seg = std::floor(t), f = t - seg;
    if (!(t > 0.0 && t < double(n)) || f <= 1e-9 || f >= 1.0 - 1e-9)
        throw EditError("T must be inside a segment of c" + std::to_string(c) + ": between 0 and " + std::to_string(n) +
                        ", not at a whole number (a segment end)");
    if (doc.points.size() + 5 > limits::kMaxPoints) throw EditError("the document is full");
    const size_t s = size_t(seg);
    const std::array<uint32_t, 4> i = curveSegment(cv, s);
    const HPoint p0 = at(doc, i[0]), p1 = at(doc, i[1]), p2 = at(doc, i[2]), p3 = at(doc, i[3]);
    const HPoint a = glm::mix(p0, p1, f), b = glm::mix(p1, p2, f), d = glm::mix(p2, p3, f);
    const HPoint ab = glm::mix(a, b, f), bd = glm::mix(b, d, f), m = glm::mix(ab, bd, f);
    // p0 a ab m bd d p3, all but the ends new points: the old inner ones may be another item's too
    // (a patch edge the curve was made from, a surface built on the curve), which must not move.
    const std::array<uint32_t, 5> made{add(doc, a), add(doc, ab), add(doc, m), add(doc, bd), add(doc, d)};
    cv.idx.erase(cv.idx.begin() + long(3 * s + 1), cv.idx.begin() + long(3 * s + 3));
    cv.idx.insert(cv.idx.begin() + long(3 * s + 1), made.begin(), made.end());
}

void removeCurvePoint(Document& doc, uint32_t c, size_t k) {
    BezierCurve& cv = curveOf(doc, c);
    const size_t n = curveSegmentCount(cv);
    const bool closed = curveClosed(cv);
    if (n < 2) throw EditError("c" + std::to_string(c) + " has one segment; it has no on-curve point to remove between two");
    if (closed ? k >= n : (k == 0 || k >= n))
        throw EditError("c" + std::to_string(c) + "'s on-curve points between segments are 1.." + std::to_string(n - 1) +
                        (closed ? " (and 0, where it closes)" : "") + ", not " + std::to_string(k));
    if (closed && k == 0) {  // the closing point: rotate the chain so it is an inner one
        std::vector<uint32_t> idx(cv.idx.begin() + 3, cv.idx.end());
        idx.insert(idx.end(), cv.idx.begin() + 1, cv.idx.begin() + 4);
        cv.idx = std::move(idx);
        k = n - 1;
    }
    const std::array<uint32_t, 4> l = curveSegment(cv, k - 1), r = curveSegment(cv, k);
    const HPoint a0 = at(doc, l[0]), a1 = at(doc, l[1]), a3 = at(doc, l[3]), b2 = at(doc, r[2]), b3 = at(doc, r[3]);
    // Where the point sits in the merged segment: a split at f leaves m - ab = f (bd - ab) and
    // bd - m = (1 - f) (bd - ab) on either side of it (homogeneous), so the two tangent legs give f
    // back exactly; for other joints it is the nearest such reading.
    // A retracted handle (a leg of length 0) says nothing: then the chords of the two segments do.
    const double la = glm::length(a3 - at(doc, l[2])), lb = glm::length(at(doc, r[1]) - a3);
    const double ca = glm::length(a3 - a0), cb = glm::length(b3 - a3), scale = 1e-9 * (1.0 + glm::length(a3));
    double f = 0.5;
    if (la > scale && lb > scale)
        f = la / (la + lb);
    else if (ca + cb > 0.0)
        f = std::clamp(ca / (ca + cb), 0.05, 0.95);
    // A split at f has a1 = mix(p0, p1, f) and b2 = mix(p2, p3, f): solve for p1 and p2.
    const HPoint p1 = a0 + (a1 - a0) / f, p2 = b3 + (b2 - b3) / (1.0 - f);
    if (!(p1.w > 0.0 && p2.w > 0.0)) throw EditError("the merged segment's weights would not be positive");
    for (const HPoint& h : {p1, p2})
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(h[a] / h.w) || std::abs(h[a] / h.w) > limits::kMaxCoordinate)
                throw EditError("the merged segment would reach beyond the coordinate limit of 1e9");
    // a0 P1 P2 b3: new inner points (the old ones may be another item's too); the removed point and
    // the inner points of both segments leave the chain.
    const uint32_t i1 = add(doc, p1), i2 = add(doc, p2);
    cv.idx.erase(cv.idx.begin() + long(3 * k - 2), cv.idx.begin() + long(3 * k + 3));
    cv.idx.insert(cv.idx.begin() + long(3 * k - 2), {i1, i2});
}

}  // namespace construct
}  // namespace pw

#include "core/construct/curves.hpp"

#include <cmath>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace pw {
inline namespace construct {

namespace {

// Solves the tridiagonal system a[i] x[i-1] + b[i] x[i] + c[i] x[i+1] = r[i] (Thomas' algorithm;
// the systems here are diagonally dominant).
std::vector<HPoint> solveTridiagonal(const std::vector<double>& a, std::vector<double> b, const std::vector<double>& c,
                                     std::vector<HPoint> r) {
    const size_t n = b.size();
    for (size_t i = 1; i < n; ++i) {
        const double m = a[i] / b[i - 1];
        b[i] -= m * c[i - 1];
        r[i] -= m * r[i - 1];
    }
    std::vector<HPoint> x(n);
    x[n - 1] = r[n - 1] / b[n - 1];
    for (size_t i = n - 1; i-- > 0;) x[i] = (r[i] - c[i] * x[i + 1]) / b[i];
    return x;
}

// The same with the corner terms of a cyclic system: row 0 has a[0] at column n-1, row n-1 has
// c[n-1] at column 0 (Sherman–Morrison, n >= 3).
std::vector<HPoint> solveCyclic(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c,
                                const std::vector<HPoint>& r) {
    const size_t n = b.size();
    const double alpha = c[n - 1], beta = a[0], gamma = -b[0];
    std::vector<double> bb = b;
    bb[0] = b[0] - gamma;
    bb[n - 1] = b[n - 1] - alpha * beta / gamma;
    std::vector<HPoint> x = solveTridiagonal(a, bb, c, r);
    std::vector<HPoint> u(n, HPoint(0.0));
    u[0] = HPoint(gamma);
    u[n - 1] = HPoint(alpha);
    const std::vector<HPoint> z = solveTridiagonal(a, bb, c, u);
    // z is the same for all four components (u is uniform); take x's factor per component.
    const HPoint fact = (x[0] + beta * x[n - 1] / gamma) / (HPoint(1.0) + z[0] + beta * z[n - 1] / gamma);
    for (size_t i = 0; i < n; ++i) x[i] -= fact * z[i];
    return x;
}

// Exact sine and cosine at multiples of 90°.
void sinCosDeg(double deg, double& s, double& c) {
    const double q = deg / 90.0;
    if (q == std::round(q)) {
        const int k = int(std::fmod(std::fmod(q, 4.0) + 4.0, 4.0));
        static const double kC[4] = {1, 0, -1, 0}, kS[4] = {0, 1, 0, -1};
        s = kS[k], c = kC[k];
        return;
    }
    s = std::sin(deg * M_PI / 180.0), c = std::cos(deg * M_PI / 180.0);
}

}  // namespace

std::vector<double> chordParameters(const std::vector<Vec3>& p, bool closed) {
    std::vector<double> t{0.0};
    const size_t n = p.size();
    for (size_t i = 0; i + (closed ? 0 : 1) < n; ++i) {
        const double d = glm::length(p[(i + 1) % n] - p[i]);
        if (!(d > 1e-12 * (1.0 + glm::length(p[i]))))
            throw EditError("points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) + " coincide");
        t.push_back(t.back() + d);
    }
    return t;
}

std::vector<HPoint> splineThrough(const std::vector<HPoint>& q, const std::vector<double>& t, bool closed,
                                  const std::optional<HPoint>& startD, const std::optional<HPoint>& endD) {
    const size_t m = q.size();
    const size_t segs = closed ? m : m - 1;
    std::vector<double> h(segs);
    for (size_t i = 0; i < segs; ++i) h[i] = t[i + 1] - t[i];
    const auto Q = [&](size_t i) { return q[i % m]; };
    std::vector<HPoint> d;  // the derivative at every value
    if (!closed && m == 2 && !startD && !endD) {
        d = {(q[1] - q[0]) / h[0], (q[1] - q[0]) / h[0]};
    } else {
        const size_t n = m;  // unknowns: one derivative per value
        std::vector<double> a(n, 0.0), b(n, 0.0), c(n, 0.0);
        std::vector<HPoint> r(n);
        for (size_t i = 0; i < n; ++i) {
            if (!closed && i == 0 && startD) {
                b[i] = 1.0, r[i] = *startD;
            } else if (!closed && i == n - 1 && endD) {
                b[i] = 1.0, r[i] = *endD;
            } else if (!closed && i == 0) {
                b[i] = 2.0, c[i] = 1.0, r[i] = 3.0 * (q[1] - q[0]) / h[0];
            } else if (!closed && i == n - 1) {
                a[i] = 1.0, b[i] = 2.0, r[i] = 3.0 * (q[i] - q[i - 1]) / h[i - 1];
            } else {
                const double hp = h[(i + segs - 1) % segs], hi = h[i % segs];
                a[i] = hi, b[i] = 2.0 * (hp + hi), c[i] = hp;
                r[i] = 3.0 * (hi / hp * (Q(i) - Q(i + m - 1)) + hp / hi * (Q(i + 1) - Q(i)));
            }
        }
        d = closed ? solveCyclic(a, b, c, r) : solveTridiagonal(a, b, c, r);
    }
    std::vector<HPoint> out;
    out.reserve(3 * segs + 1);
    for (size_t i = 0; i < segs; ++i) {
        out.push_back(Q(i));
        out.push_back(Q(i) + h[i] / 3.0 * d[i]);
        out.push_back(Q(i + 1) - h[i] / 3.0 * d[(i + 1) % d.size()]);
    }
    out.push_back(Q(segs));
    return out;
}

CurveShape curveThrough(const std::vector<Vec3>& points, bool closed) {
    if (points.size() < (closed ? 3u : 2u))
        throw EditError(std::string("a curve through points needs at least ") + (closed ? "3 (closed)" : "2") + " points");
    std::vector<HPoint> q;
    for (const Vec3& p : points) q.push_back(homogeneous(p));
    CurveShape s;
    s.points = splineThrough(q, chordParameters(points, closed), closed);
    s.closed = closed;
    return s;
}

CurveShape curveControl(const std::vector<Vec3>& controls) {
    if (controls.size() < 4) throw EditError("a cubic B-spline needs at least 4 control points");
    const size_t m = controls.size() - 1;
    const int spans = int(m) - 2;
    std::vector<double> U{0, 0, 0, 0};
    for (int k = 1; k < spans; ++k) U.push_back(k);
    for (int k = 0; k < 4; ++k) U.push_back(spans);
    std::vector<HPoint> P;
    for (const Vec3& c : controls) P.push_back(homogeneous(c));
    // Boehm: raise every interior knot to multiplicity 3 (the Bézier points of each span).
    for (int knot = 1; knot < spans; ++knot)
        for (int times = 0; times < 2; ++times) {
            const double u = knot;
            size_t k = 0;
            while (k + 1 < U.size() && U[k + 1] <= u) ++k;  // U[k] <= u < U[k + 1]
            std::vector<HPoint> Q(P.size() + 1);
            for (size_t i = 0; i < Q.size(); ++i) {
                if (i + 3 <= k)
                    Q[i] = P[i];
                else if (i > k)
                    Q[i] = P[i - 1];
                else {
                    const double a = (u - U[i]) / (U[i + 3] - U[i]);
                    Q[i] = (1.0 - a) * P[i - 1] + a * P[i];
                }
            }
            U.insert(U.begin() + long(k) + 1, u);
            P = std::move(Q);
        }
    CurveShape s;
    s.points = std::move(P);
    return s;
}

CurveShape arcCurve(const Vec3& center, const Vec3& e1, const Vec3& e2, double r, double degrees) {
    if (!(r > 0.0) || !(r <= limits::kMaxCoordinate)) throw EditError("the radius must be a positive number up to 1e9");
    if (!(degrees > 0.0) || !(degrees <= 360.0)) throw EditError("the angle must be in (0, 360] degrees");
    const int k = std::max(1, int(std::ceil(degrees / 90.0 - 1e-9)));
    const double step = degrees / k;
    double sh = 0.0, ch = 1.0;
    sinCosDeg(step / 2.0, sh, ch);
    const auto at = [&](double deg, double radius) {
        double s = 0.0, c = 1.0;
        sinCosDeg(deg, s, c);
        return center + radius * (c * e1 + s * e2);
    };
    CurveShape out;
    for (int i = 0; i < k; ++i) {
        const HPoint h0 = homogeneous(at(i * step, r)), h2 = homogeneous(at((i + 1) * step, r));
        const HPoint h1 = homogeneous(at((i + 0.5) * step, r / ch), ch);
        if (i == 0) out.points.push_back(h0);
        out.points.push_back((h0 + 2.0 * h1) / 3.0);
        out.points.push_back((2.0 * h1 + h2) / 3.0);
        out.points.push_back(h2);
    }
    out.closed = degrees == 360.0;
    return out;
}

uint32_t addCurveShape(Document& doc, const CurveShape& shape, const std::string& name) {
    const size_t n = shape.points.size();
    if (n < 4 || (n - 1) % 3 != 0) throw EditError("a curve needs 3n + 1 control points");
    if (doc.points.size() + n > limits::kMaxPoints || doc.curves.size() >= limits::kMaxPatches)
        throw EditError("the document is full (the curve needs " + std::to_string(n) + " points)");
    BezierCurve c;
    c.name = name.empty() ? "curve " + std::to_string(doc.curves.size()) : name;
    for (size_t i = 0; i < n; ++i) {
        if (shape.closed && i + 1 == n) {
            c.idx.push_back(c.idx.front());
            break;
        }
        const HPoint& h = shape.points[i];
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(h[a] / h.w) || std::abs(h[a] / h.w) > limits::kMaxCoordinate)
                throw EditError("the curve reaches beyond the coordinate limit of 1e9");
        doc.points.push_back(euclidean(h));
        c.idx.push_back(uint32_t(doc.points.size() - 1));
        if (h.w != 1.0) setPointWeight(doc, c.idx.back(), h.w);
    }
    doc.curves.push_back(std::move(c));
    return uint32_t(doc.curves.size() - 1);
}

}  // namespace construct
}  // namespace pw

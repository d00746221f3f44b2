#include "core/trim/curve_on_surface.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/trim/curve_fit.hpp"
#include "core/trim/trim_loops.hpp"

namespace pw {
inline namespace trim {

namespace {

constexpr double kUvFitTolerance = 2e-6;

std::string fmtUv(UV p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "(%.4g, %.4g)", p[0], p[1]);
    return buf;
}

void appendLine(std::vector<UV>& out, UV a, UV b) {
    // A straight piece as a cubic segment (the last point already in `out` is a).
    out.push_back({a[0] + (b[0] - a[0]) / 3.0, a[1] + (b[1] - a[1]) / 3.0});
    out.push_back({a[0] + 2.0 * (b[0] - a[0]) / 3.0, a[1] + 2.0 * (b[1] - a[1]) / 3.0});
    out.push_back(b);
}

// One cubic through q.front() and q.back() closest to the points between, at parameters t_k = k/(n-1)
// (the samples' own, so a curve whose map into the domain is affine comes back exactly); halved
// while it strays more than kUvFitTolerance. Appends the segment's points after its first.
struct SegmentFit {
    UV p1{}, p2{};
    double dev = 0.0;
};
SegmentFit fitAt(const std::vector<UV>& q, const std::vector<double>& ts) {
    const size_t n = q.size();
    const UV p0 = q.front(), p3 = q.back();
    double a11 = 0, a12 = 0, a22 = 0, r1[2] = {0, 0}, r2[2] = {0, 0};
    for (size_t k = 0; k < n; ++k) {
        const double t = ts[k], s = 1.0 - t;
        const double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t, b3 = t * t * t;
        a11 += b1 * b1, a12 += b1 * b2, a22 += b2 * b2;
        for (int d = 0; d < 2; ++d) {
            const double rhs = q[k][size_t(d)] - b0 * p0[size_t(d)] - b3 * p3[size_t(d)];
            r1[d] += b1 * rhs, r2[d] += b2 * rhs;
        }
    }
    const double det = a11 * a22 - a12 * a12;
    UV p1 = p0, p2 = p3;
    if (std::abs(det) > 1e-300)
        for (int d = 0; d < 2; ++d) {
            p1[size_t(d)] = (a22 * r1[d] - a12 * r2[d]) / det;
            p2[size_t(d)] = (a11 * r2[d] - a12 * r1[d]) / det;
        }
    double dev = 0.0;
    for (size_t k = 0; k < n; ++k) {
        const double t = ts[k], s = 1.0 - t;
        for (int d = 0; d < 2; ++d) {
            const double v =
                s * s * s * p0[size_t(d)] + 3 * s * s * t * p1[size_t(d)] + 3 * s * t * t * p2[size_t(d)] + t * t * t * p3[size_t(d)];
            dev = std::max(dev, std::abs(v - q[k][size_t(d)]));
        }
    }
    return {p1, p2, dev};
}

// One cubic through q.front() and q.back() closest to the points between: first at the samples'
// own parameters t_k = k/(n-1) (so a curve whose map into the domain is affine comes back exactly),
// else at chord-length parameters (a rational arc, whose parameters no cubic shares); halved while
// it strays more than kUvFitTolerance. Appends the segment's points after its first.
void fitSegment(const std::vector<UV>& q, std::vector<UV>& out, int depth = 0) {
    const size_t n = q.size();
    std::vector<double> ts(n);
    for (size_t k = 0; k < n; ++k) ts[k] = double(k) / double(n - 1);
    SegmentFit f = fitAt(q, ts);
    if (f.dev > kUvFitTolerance) {
        std::vector<double> chord(n, 0.0);
        for (size_t k = 1; k < n; ++k) chord[k] = chord[k - 1] + std::hypot(q[k][0] - q[k - 1][0], q[k][1] - q[k - 1][1]);
        if (chord.back() > 0.0) {
            for (double& c : chord) c /= chord.back();
            // Then a few rounds of moving each parameter to its point's nearest place on the fit.
            for (int round = 0; round < 4; ++round) {
                const SegmentFit g = fitAt(q, chord);
                if (g.dev < f.dev) f = g;
                for (size_t k = 1; k + 1 < n; ++k) {
                    const double t = chord[k], s = 1.0 - t;
                    double p[2], d1[2];
                    for (int d = 0; d < 2; ++d) {
                        const double a = q.front()[size_t(d)], b = g.p1[size_t(d)], c = g.p2[size_t(d)], e = q.back()[size_t(d)];
                        p[d] = s * s * s * a + 3 * s * s * t * b + 3 * s * t * t * c + t * t * t * e;
                        d1[d] = 3 * (s * s * (b - a) + 2 * s * t * (c - b) + t * t * (e - c));
                    }
                    const double dd = d1[0] * d1[0] + d1[1] * d1[1];
                    if (dd > 0.0) chord[k] = std::clamp(t + ((q[k][0] - p[0]) * d1[0] + (q[k][1] - p[1]) * d1[1]) / dd, 0.0, 1.0);
                }
            }
        }
    }
    const double dev = f.dev;
    const UV p1 = f.p1, p2 = f.p2, p3 = q.back();
    if (dev > kUvFitTolerance && n >= 9 && depth < 3) {
        const size_t mid = n / 2;
        fitSegment(std::vector<UV>(q.begin(), q.begin() + long(mid) + 1), out, depth + 1);
        fitSegment(std::vector<UV>(q.begin() + long(mid), q.end()), out, depth + 1);
        return;
    }
    out.push_back(p1);
    out.push_back(p2);
    out.push_back(p3);
}

std::vector<UV> fitUv(const std::vector<UV>& pts, bool closed) {
    std::vector<Vec3> v;
    for (const UV& p : pts)
        if (v.empty() || glm::length(Vec3(p[0], p[1], 0.0) - v.back()) > 1e-12) v.emplace_back(p[0], p[1], 0.0);
    if (closed && v.size() > 1 && glm::length(v.front() - v.back()) <= 1e-12) v.pop_back();
    const CurveFit f = fitCubicChainWithin(v, closed, kUvFitTolerance, closed ? 4 : 2, 96);
    std::vector<UV> out;
    for (const Vec3& p : f.bezier) out.push_back({p.x, p.y});
    return out;
}

}  // namespace

std::vector<Vec3> sampleCurve(const Document& doc, const BezierCurve& c) {
    std::vector<Vec3> out;
    const size_t n = curveSegmentCount(c);
    const bool closed = curveClosed(c);
    for (size_t s = 0; s < n; ++s) {
        const auto seg = curveSegment(c, s);
        std::array<Vec3, 4> p;
        std::array<double, 4> w;
        for (size_t k = 0; k < 4; ++k) {
            p[k] = doc.points[seg[k]];
            w[k] = pointWeight(doc, seg[k]);
        }
        const int last = (s + 1 == n && !closed) ? kCurveSamplesPerSegment : kCurveSamplesPerSegment - 1;
        for (int k = 0; k <= last; ++k) out.push_back(evaluateRationalCurve(p, w, double(k) / kCurveSamplesPerSegment).p);
    }
    return out;
}

std::vector<UV> pointsToDomain(const DomainSurface& s, const std::vector<Vec3>& points, const Vec3& direction, const std::string& what) {
    std::vector<UV> out;
    std::optional<UV> guess;
    const bool along = glm::length(direction) > 0.0;
    for (const Vec3& p : points) {
        if (along) {
            const std::optional<UV> uv = s.alongDirection(p, direction, guess);
            if (!uv)
                throw EditError(what + " misses the surface along the direction at (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                                ", " + std::to_string(p.z) + ")");
            guess = uv;
        } else {
            guess = s.closest(p, guess);
            // A point whose nearest place is on an open edge of the surface, off it: the curve leaves the surface.
            const UV q = *guess;
            const bool onEdge =
                (!s.closedU() && (q[0] <= 1e-12 || q[0] >= 1.0 - 1e-12)) || (!s.closedV() && (q[1] <= 1e-12 || q[1] >= 1.0 - 1e-12));
            if (onEdge && glm::length(s.evaluate(q).p - p) > 1e-6 * s.size())
                throw EditError(what + " runs off the surface's edge near (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
                                std::to_string(p.z) + ")");
        }
        out.push_back(*guess);
    }
    return out;
}

TrimLoop loopFromDomainPoints(const std::vector<UV>& uvIn, bool closedCurve, bool closedU, bool closedV, bool hole, const std::string& what,
                              int perSegment) {
    if (!closedCurve)
        throw EditError(what + " is open: a trim needs a closed curve (close it, or use split-by with a curve that crosses the surface)");
    if (uvIn.size() < 3) throw EditError(what + " has too few points to bound an area");
    // Unwrapped along the closed directions, so a curve round a tube is one continuous path.
    std::vector<UV> uv{uvIn.front()};
    for (size_t i = 1; i <= uvIn.size(); ++i) {
        UV p = uvIn[i % uvIn.size()];
        const UV& prev = uv.back();
        for (int d = 0; d < 2; ++d) {
            const bool closed = d == 0 ? closedU : closedV;
            if (closed) p[size_t(d)] += std::round(prev[size_t(d)] - p[size_t(d)]);
        }
        uv.push_back(p);
    }
    const int ku = int(std::lround(uv.back()[0] - uv.front()[0])), kv = int(std::lround(uv.back()[1] - uv.front()[1]));
    TrimLoop loop;
    loop.hole = hole;
    if (ku == 0 && kv == 0) {
        for (const UV& p : uv)
            if (p[0] < -1e-9 || p[0] > 1 + 1e-9 || p[1] < -1e-9 || p[1] > 1 + 1e-9)
                throw EditError(what + " crosses the net's seam at " + fmtUv(p) + ": a trim loop there would need two pieces");
        if (perSegment > 0 && (uv.size() - 1) % size_t(perSegment) == 0) {
            // Segment by segment, each from its own samples: corners stay corners, and a curve the
            // domain maps affinely (a flat patch) comes back exact.
            loop.uv = {uv.front()};
            for (size_t s = 0; s + 1 < uv.size(); s += size_t(perSegment))
                fitSegment(std::vector<UV>(uv.begin() + long(s), uv.begin() + long(s) + perSegment + 1), loop.uv);
            loop.uv.back() = loop.uv.front();
        } else {
            uv.pop_back();
            loop.uv = fitUv(uv, true);
        }
    } else if (std::abs(ku) + std::abs(kv) == 1) {
        // Runs once round a closed direction: `a` is that direction (0 = u), `b` the other.
        const size_t a = ku != 0 ? 0 : 1, b = 1 - a;
        if ((a == 0 ? ku : kv) < 0) std::reverse(uv.begin(), uv.end());  // now it ends one turn past its start
        // Start where the path first crosses the seam at an integer k.
        const double k = std::ceil(uv.front()[a]);
        size_t j = 0;
        while (j + 1 < uv.size() && !(uv[j][a] <= k && uv[j + 1][a] > k)) ++j;
        if (j + 1 >= uv.size()) throw EditError(what + " does not cross the net's seam cleanly");
        auto at = [&](const UV& p, const UV& q, double x) {
            const double t = (x - p[a]) / (q[a] - p[a]);
            UV r{};
            r[a] = x;
            r[b] = p[b] + t * (q[b] - p[b]);
            return r;
        };
        std::vector<UV> path{at(uv[j], uv[j + 1], k)};
        for (size_t i = j + 1; i < uv.size(); ++i) path.push_back(uv[i]);
        for (size_t i = 1; i <= j; ++i) path.push_back({a == 0 ? uv[i][0] + 1.0 : uv[i][0], a == 1 ? uv[i][1] + 1.0 : uv[i][1]});
        UV end = path.front();
        end[a] += 1.0;
        path.push_back(end);
        for (UV& p : path) p[a] -= k;
        for (const UV& p : path)
            if (p[a] < -1e-9 || p[a] > 1 + 1e-9 || p[b] < -1e-9 || p[b] > 1 + 1e-9)
                throw EditError(what + " runs round the net but back across its seam near " + fmtUv(p));
        // The part between the path and b = 0: ∫ b da along the path.
        double below = 0.0;
        for (size_t i = 1; i < path.size(); ++i) below += 0.5 * (path[i][b] + path[i - 1][b]) * (path[i][a] - path[i - 1][a]);
        const double side = below <= 0.5 ? 0.0 : 1.0;  // the smaller part is the inside
        loop.uv = fitUv(path, false);
        const UV last = loop.uv.back(), first = loop.uv.front();
        UV c1{}, c2{};
        c1[a] = 1.0;
        c1[b] = side;
        c2[a] = 0.0;
        c2[b] = side;
        appendLine(loop.uv, last, c1);
        appendLine(loop.uv, c1, c2);
        appendLine(loop.uv, c2, first);
    } else {
        throw EditError(what + " winds round the net more than once");
    }
    orientLoop(loop, hole);
    return loop;
}

TrimLoop loopFromCurve(const Document& doc, const SurfaceRef& s, uint32_t curve, const Vec3& direction, bool hole) {
    if (curve >= doc.curves.size()) throw EditError("curve c" + std::to_string(curve) + " does not exist");
    const DomainSurface surface(doc, s);
    const BezierCurve& c = doc.curves[curve];
    const std::string what = "curve c" + std::to_string(curve);
    std::vector<Vec3> samples = sampleCurve(doc, c);
    // A curve that ends where it starts (a polyline drawn round) is closed too.
    bool closed = curveClosed(c);
    if (!closed && samples.size() > 2 && glm::length(samples.back() - samples.front()) <= 1e-9 * surface.size()) {
        samples.pop_back();
        closed = true;
    }
    const std::vector<UV> uv = pointsToDomain(surface, samples, direction, what);
    TrimLoop loop = loopFromDomainPoints(uv, closed, surface.closedU(), surface.closedV(), hole, what, kCurveSamplesPerSegment);
    loop.curve = int32_t(curve);
    loop.direction = {direction.x, direction.y, direction.z};
    return loop;
}

}  // namespace trim
}  // namespace pw

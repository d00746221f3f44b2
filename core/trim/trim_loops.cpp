#include "core/trim/trim_loops.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/gpu/trim_math.h"
#include "core/trim/gauss_legendre.hpp"
#include "core/trim/surface_domain.hpp"

namespace pw {
inline namespace trim {

std::array<glm::dvec2, 4> loopSegment(const TrimLoop& loop, size_t s) {
    std::array<glm::dvec2, 4> b;
    for (size_t k = 0; k < 4; ++k) b[k] = glm::dvec2(loop.uv[3 * s + k][0], loop.uv[3 * s + k][1]);
    return b;
}
size_t segmentCount(const TrimLoop& loop) { return loop.uv.size() >= 4 ? (loop.uv.size() - 1) / 3 : 0; }

namespace {

using P2 = glm::dvec2;

constexpr double kDomainSlack = 1e-9;  // how far a loop may stray past [0, 1]² (rounding)
constexpr int kCheckSamples = 24;      // polyline points per segment for the crossing checks

std::string at(P2 p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "(%.4g, %.4g)", p.x, p.y);
    return buf;
}

// Segments a-b and c-d cross or touch (a loop may not touch itself or another loop either); two
// segments on one line only where they overlap.
bool segmentsCross(P2 a, P2 b, P2 c, P2 d) {
    auto orient = [](P2 p, P2 q, P2 r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
    const double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c), d4 = orient(a, b, d);
    if (d1 == 0 && d2 == 0) {  // collinear: overlapping along the line?
        const P2 dir = b - a;
        const double ta = 0.0, tb = glm::dot(dir, dir), tc = glm::dot(c - a, dir), td = glm::dot(d - a, dir);
        return std::max(ta, std::min(tc, td)) < std::min(tb, std::max(tc, td));
    }
    return ((d1 >= 0 && d2 <= 0) || (d1 <= 0 && d2 >= 0)) && ((d3 >= 0 && d4 <= 0) || (d3 <= 0 && d4 >= 0));
}

struct Box {
    P2 lo{1e300}, hi{-1e300};
    void add(P2 p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    bool overlaps(const Box& o) const { return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y; }
};

// The first crossing between two closed polylines (or of one with itself when a == b), if any.
std::optional<P2> firstCrossing(const std::vector<P2>& a, const std::vector<P2>& b, bool self) {
    const size_t na = a.size(), nb = b.size();
    // Chunks of 16 edges with boxes, so most pairs are skipped.
    const size_t chunk = 16;
    auto boxes = [&](const std::vector<P2>& p) {
        std::vector<Box> out((p.size() + chunk - 1) / chunk);
        for (size_t i = 0; i < p.size(); ++i) {
            out[i / chunk].add(p[i]);
            out[i / chunk].add(p[(i + 1) % p.size()]);
        }
        return out;
    };
    const std::vector<Box> ba = boxes(a), bb = boxes(b);
    for (size_t ci = 0; ci < ba.size(); ++ci)
        for (size_t cj = self ? ci : 0; cj < bb.size(); ++cj) {
            if (!ba[ci].overlaps(bb[cj])) continue;
            for (size_t i = ci * chunk; i < std::min(na, (ci + 1) * chunk); ++i)
                for (size_t j = cj * chunk; j < std::min(nb, (cj + 1) * chunk); ++j) {
                    if (self && (j <= i + 1 || (i == 0 && j == na - 1))) continue;  // neighbours share a point
                    if (segmentsCross(a[i], a[(i + 1) % na], b[j], b[(j + 1) % nb])) return a[i];
                }
        }
    return std::nullopt;
}

P2 derivative(const std::array<P2, 4>& b, double t) {
    const double s = 1.0 - t;
    return 3.0 * (s * s * (b[1] - b[0]) + 2.0 * s * t * (b[2] - b[1]) + t * t * (b[3] - b[2]));
}
P2 point(const std::array<P2, 4>& b, double t) {
    const double s = 1.0 - t;
    return s * s * s * b[0] + 3.0 * s * s * t * b[1] + 3.0 * s * t * t * b[2] + t * t * t * b[3];
}

}  // namespace

TrimLoop circleLoop(UV centre, double r, bool hole) {
    const double k = 0.5522847498 * r;
    const UV p[4] = {{centre[0] + r, centre[1]}, {centre[0], centre[1] + r}, {centre[0] - r, centre[1]}, {centre[0], centre[1] - r}};
    const UV t[4] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}};  // counter-clockwise tangents
    TrimLoop l;
    for (int i = 0; i < 4; ++i) {
        const UV a = p[i], b = p[(i + 1) % 4], ta = t[i], tb = t[(i + 1) % 4];
        if (i == 0) l.uv.push_back(a);
        l.uv.push_back({a[0] + k * ta[0], a[1] + k * ta[1]});
        l.uv.push_back({b[0] - k * tb[0], b[1] - k * tb[1]});
        l.uv.push_back(b);
    }
    l.uv.back() = l.uv.front();
    orientLoop(l, hole);
    return l;
}

std::array<glm::dvec2, 4> cubicPiece(const std::array<glm::dvec2, 4>& b, double t0, double t1) {
    auto lerp = [](P2 a, P2 c, double t) { return a + (c - a) * t; };
    auto split = [&](const std::array<P2, 4>& c, double t, bool right) {
        const P2 a1 = lerp(c[0], c[1], t), a2 = lerp(c[1], c[2], t), a3 = lerp(c[2], c[3], t);
        const P2 b1 = lerp(a1, a2, t), b2 = lerp(a2, a3, t), m = lerp(b1, b2, t);
        return right ? std::array<P2, 4>{m, b2, a3, c[3]} : std::array<P2, 4>{c[0], a1, b1, m};
    };
    std::array<P2, 4> r = t0 > 0.0 ? split(b, t0, true) : b;
    if (t1 < 1.0) r = split(r, (t1 - t0) / (1.0 - t0), false);
    return r;
}

glm::dvec2 loopPoint(const TrimLoop& loop, size_t segment, double t) { return point(loopSegment(loop, segment), t); }

std::vector<glm::dvec2> loopPolyline(const TrimLoop& loop, int perSegment) {
    std::vector<P2> out;
    for (size_t s = 0; s < segmentCount(loop); ++s) {
        const auto b = loopSegment(loop, s);
        for (int k = 0; k < perSegment; ++k) out.push_back(point(b, double(k) / perSegment));
    }
    return out;
}

double signedUvArea(const TrimLoop& loop) {
    // ∮ u dv: a degree-5 polynomial per segment, exact with 8 Gauss points.
    double a = 0.0;
    for (size_t s = 0; s < segmentCount(loop); ++s) {
        const auto b = loopSegment(loop, s);
        for (int k = 0; k < 8; ++k) a += kGaussW[k] * point(b, kGaussX[k]).x * derivative(b, kGaussX[k]).y;
    }
    return a;
}

void orientLoop(TrimLoop& loop, bool hole) {
    loop.hole = hole;
    if ((signedUvArea(loop) < 0.0) != hole) std::reverse(loop.uv.begin(), loop.uv.end());
}

bool hasOuterLoop(const std::vector<TrimLoop>& loops) {
    // The loop enclosing the most is outermost; checked loops nest with turns alternating, so it
    // turns like every outermost loop.
    double best = 0.0, sign = 0.0;
    for (const TrimLoop& l : loops) {
        const double a = signedUvArea(l);
        if (std::abs(a) > best) best = std::abs(a), sign = a;
    }
    return sign > 0.0;
}

std::string trimLoopProblem(const TrimLoop& loop) {
    const size_t n = loop.uv.size();
    if (n < 4 || (n - 1) % 3 != 0) return "has " + std::to_string(n) + " points; a loop of cubic segments has 3n + 1 (4, 7, 10, …)";
    for (const UV& p : loop.uv)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return "has a point that is not a finite number";
    const P2 first(loop.uv.front()[0], loop.uv.front()[1]), last(loop.uv.back()[0], loop.uv.back()[1]);
    if (glm::length(first - last) > 1e-9) return "is not closed: it starts at " + at(first) + " and ends at " + at(last);
    const std::vector<P2> poly = loopPolyline(loop, kCheckSamples);
    for (const P2& p : poly)
        if (p.x < -kDomainSlack || p.y < -kDomainSlack || p.x > 1.0 + kDomainSlack || p.y > 1.0 + kDomainSlack)
            return "leaves the domain [0, 1]² at " + at(p);
    if (const auto x = firstCrossing(poly, poly, true)) return "crosses itself near " + at(*x);
    if (std::abs(signedUvArea(loop)) < 1e-12) return "encloses no area";
    return "";
}

std::string trimLoopsProblem(const std::vector<TrimLoop>& loops) {
    std::vector<std::vector<P2>> polys;
    for (size_t i = 0; i < loops.size(); ++i) {
        if (const std::string why = trimLoopProblem(loops[i]); !why.empty()) return "trim loop " + std::to_string(i) + " " + why;
        polys.push_back(loopPolyline(loops[i], kCheckSamples));
    }
    for (size_t i = 0; i < polys.size(); ++i)
        for (size_t j = i + 1; j < polys.size(); ++j)
            if (const auto x = firstCrossing(polys[i], polys[j], false))
                return "trim loops " + std::to_string(i) + " and " + std::to_string(j) + " cross near " + at(*x);
    // Nesting: each loop turns against the loop right round it (a hole in an outer loop, an island
    // in a hole), and the outermost loops all turn one way.
    std::vector<double> area(loops.size());
    for (size_t i = 0; i < loops.size(); ++i) area[i] = signedUvArea(loops[i]);
    auto inside = [&](const std::vector<P2>& poly, P2 p) {
        bool in = false;
        for (size_t k = 0, n = poly.size(); k < n; ++k) {
            const P2 a = poly[k], b = poly[(k + 1) % n];
            if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x)) in = !in;
        }
        return in;
    };
    std::optional<bool> outermostTurn;
    for (size_t i = 0; i < loops.size(); ++i) {
        std::optional<size_t> parent;  // the smallest loop round loop i
        for (size_t j = 0; j < loops.size(); ++j)
            if (j != i && std::abs(area[j]) > std::abs(area[i]) && inside(polys[j], polys[i][0]) &&
                (!parent || std::abs(area[j]) < std::abs(area[*parent])))
                parent = j;
        const bool ccw = area[i] > 0.0;
        if (parent && (area[*parent] > 0.0) == ccw)
            return "trim loop " + std::to_string(i) + (ccw ? " keeps its inside, inside loop " : " is a hole inside hole ") +
                   std::to_string(*parent) +
                   (ccw ? ", which keeps its own: an island belongs in a hole" : ": an island belongs between them");
        if (!parent) {
            if (outermostTurn && *outermostTurn != ccw)
                return "trim loop " + std::to_string(i) +
                       (ccw ? " keeps its inside beside holes that keep everything else: cut the holes first, inside it"
                            : " is a hole outside the loops that keep their inside: it cuts nothing");
            outermostTurn = ccw;
        }
    }
    return "";
}

std::vector<TrimSegment> monotoneSegments(const std::vector<TrimLoop>& loops) {
    std::vector<TrimSegment> out;
    for (const TrimLoop& loop : loops)
        for (size_t s = 0; s < segmentCount(loop); ++s) {
            const auto b = loopSegment(loop, s);
            // v'(t)/3 = a t² + b t + c: the roots inside (0, 1) split the segment.
            const double d0 = b[1].y - b[0].y, d1 = b[2].y - b[1].y, d2 = b[3].y - b[2].y;
            const double qa = d0 - 2.0 * d1 + d2, qb = 2.0 * (d1 - d0), qc = d0;
            std::vector<double> ts{0.0};
            auto addRoot = [&](double t) {
                if (t > 1e-9 && t < 1.0 - 1e-9) ts.push_back(t);
            };
            if (std::abs(qa) < 1e-14) {
                if (std::abs(qb) > 1e-14) addRoot(-qc / qb);
            } else {
                const double disc = qb * qb - 4.0 * qa * qc;
                if (disc >= 0.0) {
                    const double r = std::sqrt(disc);
                    addRoot((-qb - r) / (2.0 * qa));
                    addRoot((-qb + r) / (2.0 * qa));
                }
            }
            std::sort(ts.begin(), ts.end());
            ts.push_back(1.0);
            for (size_t k = 0; k + 1 < ts.size(); ++k) {
                const auto piece = cubicPiece(b, ts[k], ts[k + 1]);
                if (piece[0].y == piece[3].y) continue;  // flat in v: no ray crosses it
                out.push_back({piece});
            }
        }
    return out;
}

bool trimKeeps(const std::vector<TrimSegment>& segments, bool outer, glm::dvec2 uv) {
    uint32_t crossings = outer ? 0u : 1u;
    for (const TrimSegment& s : segments) crossings += gpu::trimCrossing<double>(uv, s.b[0], s.b[1], s.b[2], s.b[3]);
    return (crossings & 1u) != 0u;
}

double trimmedArea(const DomainSurface& surface, const std::vector<TrimLoop>& loops) {
    if (loops.empty()) return surface.area();
    double a = hasOuterLoop(loops) ? 0.0 : surface.area();
    AreaStrips strips(surface);
    // ∮ F dv with F(u, v) = ∫₀ᵘ J(s, v) ds: ∫∫ J over what each loop encloses, signed by its turn.
    for (const TrimLoop& loop : loops)
        for (size_t s = 0; s < segmentCount(loop); ++s) {
            const auto b = loopSegment(loop, s);
            // Up to 8 parts of 8 Gauss points, one per 1/16 of a window the segment spans: a long
            // loop of short segments (a CAD face's outline, thousands of them) needs no more.
            Box box;
            for (const P2& p : b) box.add(p);
            const double span = std::max((box.hi.x - box.lo.x) * surface.windowsU(), (box.hi.y - box.lo.y) * surface.windowsV());
            const int parts = std::clamp(int(std::ceil(16.0 * span)), 1, 8);
            for (int p = 0; p < parts; ++p)
                for (int k = 0; k < 8; ++k) {
                    const double t = (p + kGaussX[k]) / parts;
                    const P2 q = point(b, t);
                    const double dv = derivative(b, t).y;
                    if (dv == 0.0) continue;
                    a += kGaussW[k] / parts * strips.at({q.x, q.y}) * dv;
                }
        }
    return a;
}

WindowTrim windowTrim(const std::vector<TrimSegment>& netSegments, bool outer, uint32_t r, uint32_t c, uint32_t wu, uint32_t wv) {
    WindowTrim w;
    bool crossesWindow = false;
    for (const TrimSegment& s : netSegments) {
        TrimSegment m;
        Box box;
        for (int k = 0; k < 4; ++k) {
            m.b[size_t(k)] = P2(s.b[size_t(k)].x * wu - c, s.b[size_t(k)].y * wv - r);
            box.add(m.b[size_t(k)]);
        }
        if (box.hi.y < 0.0 || box.lo.y > 1.0 || box.hi.x < 0.0) continue;  // never crosses a ray from inside the window
        if (box.lo.x <= 1.0) crossesWindow = true;
        w.segments.push_back(m);
    }
    if (!crossesWindow) {
        // No segment reaches into the window: every point of it has the centre's parity.
        const bool kept = trimKeeps(w.segments, outer, {0.5, 0.5});
        w.segments.clear();
        w.flags = kept ? 0u : gpu::kTrimAllGone;  // wholly kept: no test; wholly gone: not tessellated
        return w;
    }
    // Sorted by their lowest v: a fragment stops at the first segment that starts above it.
    std::sort(w.segments.begin(), w.segments.end(),
              [](const TrimSegment& a, const TrimSegment& b) { return std::min(a.b[0].y, a.b[3].y) < std::min(b.b[0].y, b.b[3].y); });
    w.flags = gpu::kTrimTest | (outer ? 0u : gpu::kTrimBaseKept);
    return w;
}

std::optional<WindowTrim> WindowTrims::of(const PatchInstance& w) {
    if (w.patch >= 0) {
        const std::vector<TrimLoop>& loops = doc_.patches[size_t(w.patch)].trims;
        if (loops.empty()) return std::nullopt;
        return windowTrim(monotoneSegments(loops), hasOuterLoop(loops), 0, 0, 1, 1);
    }
    if (w.surface < 0) return std::nullopt;
    const Surface& n = doc_.surfaces[size_t(w.surface)];
    if (n.trims.empty()) return std::nullopt;
    if (net_ != w.surface) {  // a net's windows come one after another
        split_ = {monotoneSegments(n.trims), hasOuterLoop(n.trims)};
        net_ = w.surface;
    }
    const uint32_t step = netStep(n.basis);
    return windowTrim(split_.segments, split_.outer, w.windowRow / step, w.windowCol / step,
                      uint32_t(netWindowCount(n.cols, n.closedU, step)), uint32_t(netWindowCount(n.rows, n.closedV, step)));
}

}  // namespace trim
}  // namespace pw

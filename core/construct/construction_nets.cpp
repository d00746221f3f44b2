// Revolve, extrude, loft and edge surface nets (core/construct/construction_nets.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/base/errors.hpp"
#include "core/construct/construction_nets.hpp"
#include "core/model/basis.hpp"
#include "core/model/construction_refs.hpp"

namespace pw {
inline namespace construct {

namespace {
Vec3 vec(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }
}  // namespace

namespace {

// A revolve's profile may touch its axis (a closed bottom, a sphere's poles) but not cross it: the
// surface would turn inside out where it passes, folding over itself (issue 73; CAD tools refuse
// such a profile too). Sampled along the curve in the plane of the axis and the profile's farthest
// point; throws naming the place it crosses.
std::string pointText(const Vec3& p) {
    char text[160];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
    return text;
}

void refuseAxisCrossing(const CurveShape& profile, const Vec3& o, const Vec3& a, double size) {
    const size_t n = profile.points.size();
    if (n < 4) return;
    Vec3 e(0.0);
    double far = 0.0;
    for (const HPoint& h : profile.points) {
        const Vec3 p = euclidean(h) - o, r = p - glm::dot(p, a) * a;
        if (glm::length(r) > far) far = glm::length(r), e = r / glm::length(r);
    }
    if (!(far > 0.0)) return;
    const double eps = 1e-9 * (1.0 + size);
    const size_t segments = profile.closed ? n / 3 : (n - 1) / 3;
    constexpr int kSteps = 32;
    int lastSign = 0;
    Vec3 lastPoint(0.0);
    double lastS = 0.0;
    for (size_t sgm = 0; sgm < segments; ++sgm)
        for (int k = 0; k <= kSteps; ++k) {
            const BasisWeights b = bernsteinWeights(double(k) / kSteps, double(kSteps - k) / kSteps);
            HPoint h(0.0), d(0.0);
            for (int i = 0; i < 4; ++i) {
                h += b.w[i] * profile.points[(3 * sgm + size_t(i)) % n];
                d += b.dw[i] * profile.points[(3 * sgm + size_t(i)) % n];
            }
            const Vec3 p = euclidean(h), r = p - o - glm::dot(p - o, a) * a;
            // Where the profile runs along its circle of revolution (its tangent has no part in the
            // plane of the axis) the surface has no tangent plane: it folds onto itself there.
            const Vec3 tangent = (Vec3(d) - double(d.w) * p) / double(h.w);
            const double rl = glm::length(r);
            if (rl > 1e-6 * (1.0 + size) && glm::length(tangent) > 0.0) {
                const Vec3 round = glm::cross(a, r / rl);
                const Vec3 meridian = tangent - glm::dot(tangent, round) * round;
                if (glm::length(meridian) <= 1e-6 * glm::length(tangent))
                    throw EditError("the profile runs round the axis at " + pointText(p) +
                                    " (along the circle it would be turned on); its revolve would fold onto itself there");
            }
            const double s = glm::dot(r, e);
            const int sign = s > eps ? 1 : s < -eps ? -1 : 0;
            if (sign != 0 && lastSign != 0 && sign != lastSign) {
                const Vec3 at = lastPoint + (p - lastPoint) * (lastS / (lastS - s));
                const Vec3 off = at - o - glm::dot(at - o, a) * a;
                if (glm::length(off) <= 0.01 * far + eps)
                    throw EditError("the profile crosses the axis at " + pointText(at) +
                                    "; its revolve would turn inside out there. Keep the profile on one side of the axis "
                                    "(it may end on it)");
            }
            if (sign != 0) lastSign = sign, lastS = s, lastPoint = p;
        }
}

}  // namespace

ConstructedNet revolveNet(const Document& doc, const Construction& c) {
    if (c.inputs.size() != 1) throw EditError("revolve takes one profile");
    const CurveShape profile = inputShape(doc, c.inputs[0]);
    const Vec3 axisIn = vec(c.vector);
    if (!(glm::length(axisIn) > 0.0)) throw EditError("the axis has no direction");
    const Vec3 a = glm::normalize(axisIn), o = vec(c.origin);
    // Any unit e1 normal to the axis; the arcs are built in (e1, e2) and mapped per profile point.
    const CurveShape arc = arcCurve(Vec3(0.0), Vec3(1, 0, 0), Vec3(0, 1, 0), 1.0, c.degrees);
    ConstructedNet net;
    net.rows = uint32_t(profile.points.size());
    net.cols = uint32_t(arc.points.size());
    net.closedU = arc.closed;
    net.closedV = profile.closed;
    net.smoothU = true;
    net.points.resize(size_t(net.rows) * net.cols);
    double farthest = 0.0, size = 0.0;
    for (uint32_t i = 0; i < net.rows; ++i) {
        const double wp = profile.points[i].w;
        const Vec3 p = euclidean(profile.points[i]);
        const double h = glm::dot(p - o, a);
        const Vec3 r = p - o - h * a, b = glm::cross(a, r);
        farthest = std::max(farthest, glm::length(r));
        size = std::max(size, glm::length(p - o));
        for (uint32_t j = 0; j < net.cols; ++j) {
            const double wa = arc.points[j].w;
            const Vec3 q = euclidean(arc.points[j]);
            net.points[size_t(i) * net.cols + j] = homogeneous(o + h * a + q.x * r + q.y * b, wp * wa);
        }
    }
    if (!(farthest > 1e-12 * (1.0 + size))) throw EditError("the profile lies on the axis; there is nothing to revolve");
    refuseAxisCrossing(profile, o, a, size);
    return net;
}

ConstructedNet extrudeNet(const Document& doc, const Construction& c) {
    if (c.inputs.size() != 1) throw EditError("extrude takes one profile");
    const CurveShape profile = inputShape(doc, c.inputs[0]);
    const Vec3 d = vec(c.vector);
    if (!(glm::length(d) > 0.0)) throw EditError("the extrusion has no length");
    ConstructedNet net;
    net.rows = 4;
    net.cols = uint32_t(profile.points.size());
    net.closedU = profile.closed;
    net.points.resize(size_t(net.rows) * net.cols);
    for (uint32_t i = 0; i < 4; ++i)
        for (uint32_t j = 0; j < net.cols; ++j)
            net.points[size_t(i) * net.cols + j] = homogeneous(euclidean(profile.points[j]) + (i / 3.0) * d, profile.points[j].w);
    return net;
}

ConstructedNet loftNet(const Document& doc, const Construction& c) {
    const size_t m = c.inputs.size();
    if (m < (c.closed ? 3u : 2u))
        throw EditError(c.closed ? "a closed loft needs at least 3 sections" : "a loft needs at least 2 sections");
    std::vector<CurveShape> sections;
    for (const CurveInput& in : c.inputs) sections.push_back(inputShape(doc, in));
    for (size_t s = 1; s < m; ++s) {
        if (sections[s].segments() != sections[0].segments())
            throw EditError("sections " + curveInputName(c.inputs[0]) + " (" + segmentsWord(sections[0].segments()) + ") and " +
                            curveInputName(c.inputs[s]) + " (" + segmentsWord(sections[s].segments()) +
                            ") differ; loft sections need the same number of segments");
        if (sections[s].closed != sections[0].closed)
            throw EditError("sections " + curveInputName(c.inputs[0]) + " and " + curveInputName(c.inputs[s]) +
                            " differ: one is closed, the other open");
    }
    const size_t cols = sections[0].points.size();
    // Chord-length parameters between consecutive sections: the mean distance of their points.
    std::vector<double> t{0.0};
    for (size_t s = 0; s + (c.closed ? 0 : 1) < m; ++s) {
        double d = 0.0;
        for (size_t j = 0; j < cols; ++j) d += glm::length(euclidean(sections[(s + 1) % m].points[j]) - euclidean(sections[s].points[j]));
        d /= double(cols);
        if (!(d > 0.0))
            throw EditError("sections " + curveInputName(c.inputs[s]) + " and " + curveInputName(c.inputs[(s + 1) % m]) + " coincide");
        t.push_back(t.back() + d);
    }
    ConstructedNet net;
    net.cols = uint32_t(cols);
    net.closedU = sections[0].closed;
    net.closedV = c.closed;
    // G1 and G2 ends against an edge section (A0 the edge, A1, A2 the patch's rows inward): the
    // join's own conditions with the stored α (β2 = 0),
    //   G1: B1 = B0 + α (A0 - A1),   G2: also B2 = 2 B1 - B0 + α² (A2 - 2 A1 + A0).
    // G1 clamps the column's end derivative (3 w α (A0 - A1) / h); G2 fixes the whole end span (its
    // four points), and the spline through the other sections starts from that span's end
    // derivative, so the surface is C1 (not C2) at the section next to a G2 end.
    std::array<std::array<std::vector<HPoint>, 2>, 2> rows;  // [end][depth - 1]
    for (int e = 0; e < 2 && !c.closed; ++e)
        if (c.ends[size_t(e)] != Continuity::C0) {
            const CurveInput& in = c.inputs[e == 0 ? 0 : m - 1];
            rows[size_t(e)][0] = inputTangentRow(doc, in, 1);
            rows[size_t(e)][1] = inputTangentRow(doc, in, 2);
            if (rows[size_t(e)][0].empty())
                throw EditError(std::string(e == 0 ? "start" : "end") + "=" + std::string(continuityName(c.ends[size_t(e)])) +
                                " needs a patch edge as the " + (e == 0 ? "first" : "last") + " section; " + curveInputName(in) +
                                " is a curve");
        }
    const bool g2[2] = {!c.closed && c.ends[0] == Continuity::G2, !c.closed && c.ends[1] == Continuity::G2};
    const size_t s0 = g2[0] ? 1 : 0, s1 = g2[1] ? m - 2 : m - 1;  // the sections the C2 spline runs through
    if (g2[0] || g2[1])
        if (m < 2 + size_t(g2[0]) + size_t(g2[1]) || s1 <= s0)
            throw EditError("a loft with G2 at " + std::string(g2[0] && g2[1] ? "both ends" : "an end") + " needs " +
                            std::to_string(2 + int(g2[0]) + int(g2[1])) + " sections or more (the end span is the edge's own)");
    std::vector<std::vector<HPoint>> columns(cols);
    for (size_t j = 0; j < cols; ++j) {
        std::vector<HPoint> q;
        for (const CurveShape& s : sections) q.push_back(s.points[j]);
        std::array<std::optional<HPoint>, 2> d;
        std::array<std::array<HPoint, 2>, 2> span{};  // a G2 end span's inner points, from its section on
        for (int e = 0; e < 2; ++e) {
            if (rows[size_t(e)][0].empty()) continue;
            const HPoint& a0 = q[e == 0 ? 0 : m - 1];
            const Vec3 A0 = euclidean(a0), A1 = euclidean(rows[size_t(e)][0][j]);
            const double alpha = c.endAlpha[size_t(e)], h = e == 0 ? t[1] - t[0] : t[m - 1] - t[m - 2];
            if (!g2[e]) {
                d[size_t(e)] = HPoint((e == 0 ? 3.0 : -3.0) * a0.w * alpha * (A0 - A1) / h, 0.0);
                continue;
            }
            const Vec3 A2 = euclidean(rows[size_t(e)][1][j]);
            const Vec3 b1 = A0 + alpha * (A0 - A1), b2 = 2.0 * b1 - A0 + alpha * alpha * (A2 - 2.0 * A1 + A0);
            span[size_t(e)] = {homogeneous(b1, a0.w), homogeneous(b2, a0.w)};
            // The spline beyond starts (or ends) with this span's derivative at its far section.
            const HPoint& far = q[e == 0 ? 1 : m - 2];
            d[size_t(e)] = (e == 0 ? 3.0 : -3.0) * (far - span[size_t(e)][1]) / h;
        }
        const std::vector<HPoint> inner(q.begin() + long(s0), q.begin() + long(s1) + 1);
        const std::vector<double> ti(t.begin() + long(s0), t.begin() + long(s1) + 1);
        std::vector<HPoint> col;
        if (g2[0]) col = {q[0], span[0][0], span[0][1]};
        const std::vector<HPoint> mid = splineThrough(inner, c.closed ? t : ti, c.closed, d[0], d[1]);
        col.insert(col.end(), mid.begin(), mid.end());
        if (g2[1]) col.insert(col.end(), {span[1][1], span[1][0], q[m - 1]});
        columns[j] = std::move(col);
    }
    net.rows = uint32_t(columns[0].size());
    net.points.resize(size_t(net.rows) * net.cols);
    for (uint32_t i = 0; i < net.rows; ++i)
        for (uint32_t j = 0; j < net.cols; ++j) {
            const HPoint& h = columns[j][i];
            if (!(h.w > 0.0))
                throw EditError("the sections' weights differ too much to loft (a weight between them would not be positive)");
            net.points[size_t(i) * net.cols + j] = h;
        }
    // The sections are rows 3k of the net: the surface shares their points (an edge's patch is joined).
    net.shared.assign(net.points.size(), -1);
    for (size_t k = 0; k < m; ++k) {
        const std::vector<uint32_t> idx = curveInputPoints(doc, c.inputs[k]);
        for (size_t j = 0; j < cols; ++j) net.shared[3 * k * cols + j] = idx[j];
    }
    return net;
}

namespace {
struct Side {
    std::vector<HPoint> p;
    std::vector<uint32_t> idx;
    std::string name;
    std::vector<HPoint> inner;  // a patch edge's tangent row (the surface leaves it G1), else empty
    void reverse() {
        std::reverse(p.begin(), p.end());
        std::reverse(idx.begin(), idx.end());
        std::reverse(inner.begin(), inner.end());
    }
    Vec3 start() const { return euclidean(p.front()); }
    Vec3 end() const { return euclidean(p.back()); }
};
}  // namespace

ConstructedNet edgeSurfaceNet(const Document& doc, const Construction& c) {
    const size_t n = c.inputs.size();
    if (n < 2 || n > 4) throw EditError("an edge surface takes 2, 3 or 4 curves or edges");
    std::vector<Side> sides;
    double size = 0.0;
    for (const CurveInput& in : c.inputs) {
        const CurveShape s = inputShape(doc, in);
        if (s.closed) throw EditError(curveInputName(in) + " is closed; an edge surface's sides are open curves");
        sides.push_back({s.points, curveInputPoints(doc, in), curveInputName(in), inputTangentRow(doc, in)});
        for (const HPoint& h : s.points) size = std::max(size, glm::length(euclidean(h)));
    }
    const double tol = 1e-9 * (1.0 + size);
    const auto meet = [&](const Vec3& a, const Vec3& b) { return glm::length(a - b) <= tol; };
    Side bottom = sides[0], top, left, right;
    if (n == 2) {
        top = sides[1];
        // Ruled: the second runs the way the first does (its start nearer the first's start).
        if (glm::length(top.start() - bottom.start()) + glm::length(top.end() - bottom.end()) >
            glm::length(top.end() - bottom.start()) + glm::length(top.start() - bottom.end()))
            top.reverse();
    } else {
        // A loop: each side starts where the one before ends.
        std::vector<Side> chain{bottom};
        std::vector<bool> used(n, false);
        used[0] = true;
        for (size_t k = 1; k < n; ++k) {
            bool found = false;
            for (size_t i = 1; i < n && !found; ++i) {
                if (used[i]) continue;
                Side s = sides[i];
                if (!meet(s.start(), chain.back().end())) s.reverse();
                if (!meet(s.start(), chain.back().end())) continue;
                chain.push_back(s);
                used[i] = found = true;
            }
            if (!found)
                throw EditError("no side starts where " + chain.back().name + " ends; the curves must form a closed loop, end to end");
        }
        if (!meet(chain.back().end(), chain.front().start()))
            throw EditError(chain.back().name + " ends " + std::to_string(glm::length(chain.back().end() - chain.front().start())) +
                            " from where " + chain.front().name + " starts; the curves must form a closed loop");
        right = chain[1];
        top = chain[2];
        top.reverse();  // along u, as the bottom
        if (n == 4) {
            left = chain[3];
            left.reverse();  // along v, as the right
        } else {             // three sides: the fourth collapsed to the bottom's start
            left.p.assign(right.p.size(), bottom.p.front());
            left.idx.assign(right.idx.size(), bottom.idx.front());
            left.name = bottom.name;
            left.inner.clear();
        }
        if (right.p.size() != left.p.size())
            throw EditError("sides " + right.name + " and " + left.name + " have different numbers of segments (" +
                            segmentsWord((right.p.size() - 1) / 3) + ", " + segmentsWord((left.p.size() - 1) / 3) + ")");
    }
    if (top.p.size() != bottom.p.size())
        throw EditError("sides " + bottom.name + " and " + top.name + " have different numbers of segments (" +
                        segmentsWord((bottom.p.size() - 1) / 3) + ", " + segmentsWord((top.p.size() - 1) / 3) + ")");
    ConstructedNet net;
    net.cols = uint32_t(bottom.p.size());
    net.rows = n == 2 ? 4u : uint32_t(right.p.size());
    if (n == 2) {  // ruled: the straight lines between the sides, as a Coons patch of straight sides
        for (uint32_t i = 0; i < 4; ++i) {
            left.p.push_back(glm::mix(bottom.p.front(), top.p.front(), i / 3.0));
            right.p.push_back(glm::mix(bottom.p.back(), top.p.back(), i / 3.0));
        }
    }
    net.points.resize(size_t(net.rows) * net.cols);
    net.shared.assign(net.points.size(), -1);
    const uint32_t R = net.rows - 1, C = net.cols - 1;
    const HPoint c00 = bottom.p.front(), c01 = bottom.p.back(), c10 = top.p.front(), c11 = top.p.back();
    for (uint32_t i = 0; i <= R; ++i)
        for (uint32_t j = 0; j <= C; ++j) {
            const double u = double(j) / C, v = double(i) / R;
            const size_t g = size_t(i) * net.cols + j;
            HPoint h;
            if (i == 0) {
                h = bottom.p[j];
                net.shared[g] = bottom.idx[j];
            } else if (i == R) {
                h = top.p[j];
                net.shared[g] = top.idx[j];
            } else if (j == 0) {
                h = left.p[i];
                if (n > 2) net.shared[g] = left.idx[i];
            } else if (j == C) {
                h = right.p[i];
                if (n > 2) net.shared[g] = right.idx[i];
            } else {
                h = (1.0 - v) * bottom.p[j] + v * top.p[j] + (1.0 - u) * left.p[i] + u * right.p[i] -
                    ((1.0 - u) * (1.0 - v) * c00 + u * (1.0 - v) * c01 + (1.0 - u) * v * c10 + u * v * c11);
                if (!(h.w > 0.0))
                    throw EditError("the sides' weights differ too much for an edge surface (a weight inside would not be positive)");
            }
            net.points[g] = h;
        }
    // A side that is a patch edge: the row next to it continues the patch across, B1 = 2 B0 - A1
    // (G1 with α = 1). Only the rows' inner points where 3 or 4 sides meet at corners (their ends
    // are the neighbouring sides'; addConstruction() joins G1 only where the corners agree).
    const auto across = [&](const Side& s, uint32_t fromRow, uint32_t fromCol, int dr, int dc, bool alongRow) {
        if (s.inner.empty()) return;
        const uint32_t len = alongRow ? net.cols : net.rows;
        for (uint32_t k = (n == 2 ? 0 : 1); k + (n == 2 ? 0 : 1) < len; ++k) {
            const uint32_t i = alongRow ? fromRow : k, j = alongRow ? k : fromCol;
            const HPoint& b0 = net.points[size_t(i) * net.cols + j];
            const Vec3 p = 2.0 * euclidean(b0) - euclidean(s.inner[k]);
            net.points[size_t(int(i) + dr) * net.cols + uint32_t(int(j) + dc)] = homogeneous(p, b0.w);
        }
    };
    across(bottom, 0, 0, 1, 0, true);
    across(top, R, 0, -1, 0, true);
    if (n > 2) {
        across(right, 0, C, 0, -1, false);
        if (n == 4) across(left, 0, 0, 0, 1, false);
    }
    return net;
}

}  // namespace construct
}  // namespace pw

// Sweeps along one and two rails (core/construct/construction_nets.hpp).
#include <algorithm>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/construct/construction_nets.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/construction_refs.hpp"

namespace pw {
inline namespace construct {

namespace {

// The rail with every segment split into `pieces` equal parameter pieces (de Casteljau, homogeneous):
// the same curve, more control points for the sweep's frames to sit on.
CurveShape subdivided(const CurveShape& rail, uint32_t pieces) {
    if (pieces <= 1) return rail;
    CurveShape out;
    out.closed = rail.closed;
    out.points.push_back(rail.points.front());
    for (size_t s = 0; s < rail.segments(); ++s) {
        std::array<HPoint, 4> q{rail.points[3 * s], rail.points[3 * s + 1], rail.points[3 * s + 2], rail.points[3 * s + 3]};
        for (uint32_t k = pieces; k > 1; --k) {  // split off the first 1/k of what is left
            const double f = 1.0 / double(k);
            const HPoint a = glm::mix(q[0], q[1], f), b = glm::mix(q[1], q[2], f), d = glm::mix(q[2], q[3], f);
            const HPoint ab = glm::mix(a, b, f), bd = glm::mix(b, d, f), m = glm::mix(ab, bd, f);
            out.points.insert(out.points.end(), {a, ab, m});
            q = {m, bd, d, q[3]};
        }
        out.points.insert(out.points.end(), {q[1], q[2], q[3]});
    }
    return out;
}

struct Sweep1 {
    ConstructedNet net;
    double deviation = 0.0;  // largest distance between the net and the exact sweep at mid-segments
};

// Sweep1: the profile carried along the rail by rotation-minimising frames (double reflection,
// Wang et al. 2008) sampled densely along the rail. At every segment end of the rail (rows 3s) the
// net's row is exactly the profile moved with its frame; in between each profile point follows
// the Hermite cubic of its exact path (so a straight rail gives the exact translational sweep, and
// the error shrinks as h^4 when segments are split). `measure` compares the net with the exact
// sweep at every segment's middle (the iso-curve's control points against the profile there).
Sweep1 sweep1(const Document& doc, const Construction& c, bool measure) {
    if (c.inputs.size() != 2) throw EditError("sweep1 takes a rail and a profile");
    const CurveShape rail = subdivided(inputShape(doc, c.inputs[0]), std::max<uint32_t>(1, c.split));
    const CurveShape profile = inputShape(doc, c.inputs[1]);
    const size_t rows = rail.points.size(), segs = rail.segments();
    constexpr int kSub = 8;              // frame steps per third of a segment
    const auto railAt = [&](double s) {  // s in [0, segs]: position and unit tangent
        const size_t k = std::min(size_t(s), segs - 1);
        std::array<Vec3, 4> p;
        std::array<double, 4> w;
        for (size_t a = 0; a < 4; ++a) p[a] = euclidean(rail.points[3 * k + a]), w[a] = rail.points[3 * k + a].w;
        const CurveJet j = evaluateRationalCurve(p, w, s - double(k));
        return std::pair<Vec3, Vec3>{j.p, glm::length(j.d1) > 0.0 ? glm::normalize(j.d1) : Vec3(0.0)};
    };
    auto [x, t] = railAt(0.0);
    if (t == Vec3(0.0)) throw EditError("the rail " + curveInputName(c.inputs[0]) + " has no direction at its start");
    const Vec3 t0 = t;
    Vec3 r = glm::cross(t, std::abs(t.z) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0));
    r = glm::normalize(r);
    const Vec3 r0 = r, b0 = glm::cross(t0, r0), x0 = x;
    using Frame = std::array<Vec3, 3>;
    std::vector<Frame> frames{{t, r, glm::cross(t, r)}};  // one per rail control point
    std::vector<std::pair<Vec3, Frame>> mids;             // the rail point and frame at each segment's middle
    for (size_t i = 1; i < rows; ++i)
        for (int k = 1; k <= kSub; ++k) {
            const auto [x1, t1] = railAt((double(i - 1) + double(k) / kSub) / 3.0);
            if (t1 == Vec3(0.0)) throw EditError("the rail " + curveInputName(c.inputs[0]) + " stops (no direction) along its way");
            const Vec3 v1 = x1 - x;
            const double c1 = glm::dot(v1, v1);
            Vec3 rl = r, tl = t;
            if (c1 > 0.0) rl = r - (2.0 / c1) * glm::dot(v1, r) * v1, tl = t - (2.0 / c1) * glm::dot(v1, t) * v1;
            const Vec3 v2 = t1 - tl;
            const double c2 = glm::dot(v2, v2);
            r = c2 > 0.0 ? rl - (2.0 / c2) * glm::dot(v2, rl) * v2 : rl;
            r = glm::normalize(r - glm::dot(r, t1) * t1);
            x = x1, t = t1;
            if (k == kSub) frames.push_back({t, r, glm::cross(t, r)});
            if (measure && (i - 1) % 3 == 1 && k == kSub / 2) mids.push_back({x, {t, r, glm::cross(t, r)}});
        }
    double twist = 0.0;  // a closed rail's frames turn back by this angle per segment
    if (rail.closed) {   // the frames turn by some angle around the loop: take it back evenly
        const Frame& e = frames.back();
        const double phi = std::atan2(glm::dot(glm::cross(e[1], r0), t0), glm::dot(e[1], r0));
        twist = phi * 3.0 / double(rows - 1);
        const auto turn = [&](Frame& f, double at) {
            const double a = phi * at / double(rows - 1), ca = std::cos(a), sa = std::sin(a);
            const Vec3 rr = ca * f[1] + sa * f[2];
            f = {f[0], rr, glm::cross(f[0], rr)};
        };
        for (size_t i = 0; i < rows; ++i) turn(frames[i], double(i));
        for (size_t s = 0; s < mids.size(); ++s) turn(mids[s].second, 3.0 * double(s) + 1.5);
    }
    Sweep1 out;
    ConstructedNet& net = out.net;
    net.rows = uint32_t(rows);
    net.cols = uint32_t(profile.points.size());
    net.closedU = profile.closed;
    net.closedV = rail.closed;
    net.points.resize(size_t(net.rows) * net.cols);
    std::vector<Vec3> local(net.cols);  // the profile's points in the first frame
    for (uint32_t j = 0; j < net.cols; ++j) {
        const Vec3 d = euclidean(profile.points[j]) - x0;
        local[j] = Vec3(glm::dot(d, t0), glm::dot(d, r0), glm::dot(d, b0));
    }
    // Rows 3s: the profile in the frame at segment end s, exact. Rows between: each profile point's
    // path as the cubic Hermite of the exact sweep at the segment's ends, P ± P'/3, where P' = C' +
    // x T' + y R' + z B' and the rotation-minimising frame turns only about the normal plane:
    // T' = (C'' - (C''·T) T) / |C'|, R' = -(R·T') T (+ the closed rail's twist), B' = -(B·T') T.
    const auto place = [&](const Vec3& at, const Frame& f, const Vec3& l) { return at + l.x * f[0] + l.y * f[1] + l.z * f[2]; };
    const auto hermite = [&](size_t seg, double at, size_t row, double sign) {  // row 3s (at = 0) or 3s + 3 (at = 1)
        std::array<Vec3, 4> cp;
        std::array<double, 4> w;
        for (size_t a = 0; a < 4; ++a) cp[a] = euclidean(rail.points[3 * seg + a]), w[a] = rail.points[3 * seg + a].w;
        const CurveJet jet = evaluateRationalCurve(cp, w, at);  // derivatives in this segment's parameter
        const Frame& f = frames[row];
        const double speed = glm::length(jet.d1);
        const Vec3 dT = speed > 0.0 ? (jet.d2 - glm::dot(jet.d2, f[0]) * f[0]) / speed : Vec3(0.0);
        const Vec3 dR = -glm::dot(f[1], dT) * f[0] + twist * f[2], dB = -glm::dot(f[2], dT) * f[0] - twist * f[1];
        for (uint32_t j = 0; j < net.cols; ++j) {
            const Vec3 p = place(jet.p, f, local[j]);
            const Vec3 dp = jet.d1 + local[j].x * dT + local[j].y * dR + local[j].z * dB;
            const double wj = profile.points[j].w;
            net.points[row * net.cols + j] = homogeneous(p, wj);
            net.points[size_t(int64_t(row) + int64_t(sign)) * net.cols + j] = homogeneous(p + sign * dp / 3.0, wj);
        }
    };
    for (size_t seg = 0; seg < segs; ++seg) {
        hermite(seg, 0.0, 3 * seg, 1.0);
        hermite(seg, 1.0, 3 * seg + 3, -1.0);
    }
    for (size_t s = 0; s < mids.size(); ++s)
        for (uint32_t j = 0; j < net.cols; ++j) {
            std::array<HPoint, 4> q;
            for (size_t a = 0; a < 4; ++a) q[a] = net.points[(3 * s + a) * net.cols + j];
            const HPoint half = (q[0] + 3.0 * q[1] + 3.0 * q[2] + q[3]) / 8.0;  // the column at v = 1/2
            const auto& [at, f] = mids[s];
            const Vec3 exact = at + local[j].x * f[0] + local[j].y * f[1] + local[j].z * f[2];
            out.deviation = std::max(out.deviation, glm::length(euclidean(half) - exact));
        }
    return out;
}

}  // namespace

ConstructedNet sweep1Net(const Document& doc, const Construction& c) { return sweep1(doc, c, false).net; }

uint32_t sweep1Pieces(const Document& doc, Construction c, double tolerance) {
    const size_t segs = c.inputs.empty() ? 1 : std::max<size_t>(1, inputShape(doc, c.inputs[0]).segments());
    for (uint32_t pieces = 1;; pieces *= 2) {
        c.split = pieces;
        const bool room = pieces < kMaxSweepPieces && 3 * segs * 2 * pieces + 1 <= limits::kMaxNetSide;
        if (!room || sweep1(doc, c, true).deviation <= tolerance) return pieces;
    }
}

// Sweep2: the profile between two rails. At rail control point i the profile is placed by the
// similarity that takes its chord (start to end) onto the rails' chord R1_i → R2_i and its plane
// square to the rails' direction there, so the net's first and last columns are the rails' own
// points (shared: the surface holds both rails exactly) and row 3s, at each segment end of the
// rails, is the profile moved and scaled to span them.
ConstructedNet sweep2Net(const Document& doc, const Construction& c) {
    if (c.inputs.size() != 3) throw EditError("sweep2 takes two rails and a profile");
    CurveShape r1 = inputShape(doc, c.inputs[0]), r2 = inputShape(doc, c.inputs[1]), profile = inputShape(doc, c.inputs[2]);
    std::vector<uint32_t> i1 = curveInputPoints(doc, c.inputs[0]), i2 = curveInputPoints(doc, c.inputs[1]);
    const std::string n1 = curveInputName(c.inputs[0]), n2 = curveInputName(c.inputs[1]), np = curveInputName(c.inputs[2]);
    if (r1.segments() != r2.segments())
        throw EditError("rails " + n1 + " (" + segmentsWord(r1.segments()) + ") and " + n2 + " (" + segmentsWord(r2.segments()) +
                        ") differ; sweep2's rails need the same number of segments");
    if (r1.closed != r2.closed) throw EditError("rails " + n1 + " and " + n2 + " differ: one is closed, the other open");
    if (profile.closed) throw EditError("the profile " + np + " is closed; sweep2's profile runs from one rail to the other");
    const auto at = [](const CurveShape& s, size_t i) { return euclidean(s.points[i]); };
    const size_t rows = r1.points.size();
    if (r1.closed && glm::dot(at(r1, 1) - at(r1, 0), at(r2, 1) - at(r2, 0)) < 0.0) {  // closed rails turning opposite ways
        std::reverse(r2.points.begin(), r2.points.end());
        std::reverse(i2.begin(), i2.end());
    }
    if (!r1.closed && glm::length(at(r2, 0) - at(r1, 0)) + glm::length(at(r2, rows - 1) - at(r1, rows - 1)) >
                          glm::length(at(r2, rows - 1) - at(r1, 0)) + glm::length(at(r2, 0) - at(r1, rows - 1))) {
        std::reverse(r2.points.begin(), r2.points.end());
        std::reverse(i2.begin(), i2.end());
    }
    const Vec3 ps = euclidean(profile.points.front()), pe = euclidean(profile.points.back());
    if (glm::length(ps - at(r2, 0)) + glm::length(pe - at(r1, 0)) < glm::length(ps - at(r1, 0)) + glm::length(pe - at(r2, 0)))
        std::reverse(profile.points.begin(), profile.points.end());
    // The rails' direction at control point i, from the mean of the two control polygons.
    const size_t last = r1.closed ? rows - 1 : rows;  // distinct points (closed: the last is the first)
    const auto mid = [&](size_t i) { return 0.5 * (at(r1, i % last) + at(r2, i % last)); };
    const auto direction = [&](size_t i) {
        if (r1.closed) return mid(i + 1) - mid(i + last - 1);
        return mid(std::min(i + 1, rows - 1)) - mid(i == 0 ? 0 : i - 1);
    };
    struct Frame {
        Vec3 e1, e2, e3;
        double scale;
    };
    std::vector<Frame> frames(rows);
    Vec3 prevE2(0.0);
    for (size_t i = 0; i < rows; ++i) {
        const Vec3 d = at(r2, i) - at(r1, i);
        const double len = glm::length(d);
        if (!(len > 1e-12 * (1.0 + glm::length(at(r1, i)))))
            throw EditError("rails " + n1 + " and " + n2 + " meet at their point " + std::to_string(i) +
                            "; there is no room for the profile");
        const Vec3 e1 = d / len, t = direction(i);
        Vec3 e2 = t - glm::dot(t, e1) * e1;
        e2 = glm::length(e2) > 1e-12 * (1.0 + glm::length(t)) ? glm::normalize(e2) : prevE2;
        if (glm::length(e2) == 0.0) throw EditError("the rails run along the line between them; sweep2 needs them side by side");
        frames[i] = {e1, e2, glm::cross(e1, e2), len};
        prevE2 = e2;
    }
    const Vec3 chord = pe - ps;
    const double plen = glm::length(chord);
    if (!(plen > 1e-12 * (1.0 + glm::length(ps)))) throw EditError("the profile " + np + " ends where it starts; it must span the rails");
    const Vec3 f1 = chord / plen, t0 = frames[0].e2;
    Vec3 f2 = t0 - glm::dot(t0, f1) * f1;
    if (!(glm::length(f2) > 1e-9)) f2 = glm::cross(f1, std::abs(f1.z) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0));  // chord along the rails
    f2 = glm::normalize(f2);
    const Vec3 f3 = glm::cross(f1, f2);
    ConstructedNet net;
    net.rows = uint32_t(rows);
    net.cols = uint32_t(profile.points.size());
    net.closedV = r1.closed;
    net.points.resize(size_t(net.rows) * net.cols);
    net.shared.assign(net.points.size(), -1);
    const double w0 = profile.points.front().w, w1 = profile.points.back().w;
    for (uint32_t j = 0; j < net.cols; ++j) {
        const Vec3 q = (euclidean(profile.points[j]) - ps) / plen;
        const double a = glm::dot(q, f1), b = glm::dot(q, f2), cc = glm::dot(q, f3);
        const double s = double(j) / double(net.cols - 1);
        for (uint32_t i = 0; i < net.rows; ++i) {
            const Frame& f = frames[i];
            const Vec3 p = at(r1, i) + f.scale * (a * f.e1 + b * f.e2 + cc * f.e3);
            // The profile's weights relative to its ends, times the rails' weights blended across.
            const double w = profile.points[j].w / ((1.0 - s) * w0 + s * w1) * ((1.0 - s) * r1.points[i].w + s * r2.points[i].w);
            net.points[size_t(i) * net.cols + j] = homogeneous(p, w);
        }
    }
    for (uint32_t i = 0; i < net.rows; ++i) {
        net.shared[size_t(i) * net.cols] = i1[i];
        net.shared[size_t(i) * net.cols + net.cols - 1] = i2[i];
    }
    return net;
}

}  // namespace construct
}  // namespace pw

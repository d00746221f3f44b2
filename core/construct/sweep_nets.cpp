// Sweeps along one and two rails (core/construct/construction_nets.hpp).
#include <algorithm>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/construct/construction_nets.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/construction_refs.hpp"

namespace pw {

// Sweep1: the profile carried along the rail by rotation-minimising frames (double reflection,
// Wang et al. 2008) sampled densely along the rail; net row i is the profile in frame i placed at
// rail control point i, so at every segment end of the rail (rows 3s) the net's row is exactly the
// profile moved with its frame, and a straight rail gives the exact translational sweep.
ConstructedNet sweep1Net(const Document& doc, const Construction& c) {
    if (c.inputs.size() != 2) throw EditError("sweep1 takes a rail and a profile");
    const CurveShape rail = inputShape(doc, c.inputs[0]), profile = inputShape(doc, c.inputs[1]);
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
    std::vector<std::array<Vec3, 3>> frames{{t, r, glm::cross(t, r)}};  // one per rail control point
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
        }
    if (rail.closed) {  // the frames turn by some angle around the loop: take it back evenly
        const std::array<Vec3, 3>& e = frames.back();
        const double phi = std::atan2(glm::dot(glm::cross(e[1], r0), t0), glm::dot(e[1], r0));
        for (size_t i = 0; i < rows; ++i) {
            const double a = phi * double(i) / double(rows - 1), ca = std::cos(a), sa = std::sin(a);
            std::array<Vec3, 3>& f = frames[i];
            const Vec3 rr = ca * f[1] + sa * f[2];
            f = {f[0], rr, glm::cross(f[0], rr)};
        }
    }
    ConstructedNet net;
    net.rows = uint32_t(rows);
    net.cols = uint32_t(profile.points.size());
    net.closedU = profile.closed;
    net.closedV = rail.closed;
    net.points.resize(size_t(net.rows) * net.cols);
    for (uint32_t j = 0; j < net.cols; ++j) {
        const Vec3 d = euclidean(profile.points[j]) - x0;
        const double a = glm::dot(d, t0), b = glm::dot(d, r0), cc = glm::dot(d, b0);
        for (uint32_t i = 0; i < net.rows; ++i) {
            const std::array<Vec3, 3>& f = frames[i];
            net.points[size_t(i) * net.cols + j] =
                homogeneous(euclidean(rail.points[i]) + a * f[0] + b * f[1] + cc * f[2], profile.points[j].w);
        }
    }
    return net;
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
    f2 = glm::length(f2) > 1e-9 ? glm::normalize(f2) : frames[0].e2;
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

}  // namespace pw

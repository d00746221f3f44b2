// The Gordon surface of a curve network (core/construct/construction_nets.hpp): U curves along u
// at increasing v, V curves along v at increasing u, each U curve one segment per span between V
// curves and each V curve one per span between U curves, meeting at their segment ends. The net is
// L_u + L_v - T in homogeneous coordinates: L_u lofts the U curves (C2 in v), L_v the V curves
// (C2 in u), T is the tensor-product spline through the meeting points at the same parameters; row
// 3k of the net is then U curve k and column 3l V curve l exactly (Gordon 1971), so every cell
// between two U and two V curves is one patch.
#include <algorithm>

#include "core/base/errors.hpp"
#include "core/construct/construction_nets.hpp"
#include "core/model/construction_refs.hpp"

namespace pw {
inline namespace construct {

namespace {

struct NetworkCurve {
    CurveShape shape;
    std::vector<uint32_t> idx;
    std::string name;
    void reverse() {
        std::reverse(shape.points.begin(), shape.points.end());
        std::reverse(idx.begin(), idx.end());
    }
    Vec3 at(size_t i) const { return euclidean(shape.points[i]); }
};

struct Network {
    std::vector<NetworkCurve> u, v;
};

// The curves of a network, oriented (U curves from the first V curve on, V curves from the first
// U curve on) and checked: open, the segment counts the other family asks, meeting at segment ends.
Network orientedNetwork(const Document& doc, const Construction& c) {
    if (c.split < 2 || c.inputs.size() < size_t(c.split) + 2)
        throw EditError("a network needs at least 2 curves each way: U curves, then / and the V curves");
    Network net;
    double size = 0.0;
    for (size_t k = 0; k < c.inputs.size(); ++k) {
        NetworkCurve nc{inputShape(doc, c.inputs[k]), curveInputPoints(doc, c.inputs[k]), curveInputName(c.inputs[k])};
        if (nc.shape.closed) throw EditError(nc.name + " is closed; a network's curves are open");
        for (const HPoint& h : nc.shape.points) size = std::max(size, glm::length(euclidean(h)));
        (k < c.split ? net.u : net.v).push_back(std::move(nc));
    }
    const size_t m = net.u.size(), n = net.v.size();
    for (const NetworkCurve& u : net.u)
        if (u.shape.segments() != n - 1)
            throw EditError("U curve " + u.name + " has " + segmentsWord(u.shape.segments()) + "; it needs " + segmentsWord(n - 1) +
                            ", one between each two of the " + std::to_string(n) + " V curves");
    for (const NetworkCurve& v : net.v)
        if (v.shape.segments() != m - 1)
            throw EditError("V curve " + v.name + " has " + segmentsWord(v.shape.segments()) + "; it needs " + segmentsWord(m - 1) +
                            ", one between each two of the " + std::to_string(m) + " U curves");
    // The corner where the first U and the first V curve meet: the nearest pair of their ends.
    NetworkCurve &u0 = net.u.front(), &v0 = net.v.front();
    double best = -1.0;
    int bu = 0, bv = 0;
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
            const double d = glm::length(u0.at(a ? u0.idx.size() - 1 : 0) - v0.at(b ? v0.idx.size() - 1 : 0));
            if (best < 0.0 || d < best) best = d, bu = a, bv = b;
        }
    if (bu) u0.reverse();
    if (bv) v0.reverse();
    for (size_t l = 1; l < n; ++l) {  // each V curve starts on the first U curve
        NetworkCurve& v = net.v[l];
        if (glm::length(v.at(v.idx.size() - 1) - u0.at(3 * l)) < glm::length(v.at(0) - u0.at(3 * l))) v.reverse();
    }
    for (size_t k = 1; k < m; ++k) {  // each U curve starts on the first V curve
        NetworkCurve& u = net.u[k];
        if (glm::length(u.at(u.idx.size() - 1) - v0.at(3 * k)) < glm::length(u.at(0) - v0.at(3 * k))) u.reverse();
    }
    const double tol = 1e-7 * (1.0 + size);
    for (size_t k = 0; k < m; ++k)
        for (size_t l = 0; l < n; ++l) {
            const double d = glm::length(net.u[k].at(3 * l) - net.v[l].at(3 * k));
            if (d > tol)
                throw EditError(net.u[k].name + " and " + net.v[l].name + " do not meet at their segment ends (" + std::to_string(d) +
                                " apart); each U curve must cross each V curve where both have a segment end");
        }
    return net;
}

// Chord-length parameters across a family: the mean distance between consecutive curves' points.
std::vector<double> familyParameters(const std::vector<NetworkCurve>& f) {
    std::vector<double> t{0.0};
    for (size_t k = 0; k + 1 < f.size(); ++k) {
        double d = 0.0;
        const size_t cnt = f[k].shape.points.size();
        for (size_t j = 0; j < cnt; ++j) d += glm::length(f[k + 1].at(j) - f[k].at(j));
        if (!(d > 0.0)) throw EditError(f[k].name + " and " + f[k + 1].name + " coincide");
        t.push_back(t.back() + d / double(cnt));
    }
    return t;
}

}  // namespace

ConstructedNet networkNet(const Document& doc, const Construction& c) {
    const Network nw = orientedNetwork(doc, c);
    const size_t m = nw.u.size(), n = nw.v.size();
    const size_t R = 3 * (m - 1) + 1, C = 3 * (n - 1) + 1;
    const std::vector<double> tv = familyParameters(nw.u), tu = familyParameters(nw.v);
    ConstructedNet net;
    net.rows = uint32_t(R);
    net.cols = uint32_t(C);
    net.points.assign(R * C, HPoint(0.0));
    // L_u: each column of the U curves' points, splined across in v.
    for (size_t j = 0; j < C; ++j) {
        std::vector<HPoint> q;
        for (const NetworkCurve& u : nw.u) q.push_back(u.shape.points[j]);
        const std::vector<HPoint> col = splineThrough(q, tv, false);
        for (size_t i = 0; i < R; ++i) net.points[i * C + j] += col[i];
    }
    // L_v: each row of the V curves' points, splined across in u.
    for (size_t i = 0; i < R; ++i) {
        std::vector<HPoint> q;
        for (const NetworkCurve& v : nw.v) q.push_back(v.shape.points[i]);
        const std::vector<HPoint> row = splineThrough(q, tu, false);
        for (size_t j = 0; j < C; ++j) net.points[i * C + j] += row[j];
    }
    // T: the meeting points splined in v, then every row of that in u.
    std::vector<std::vector<HPoint>> cols(n);
    for (size_t l = 0; l < n; ++l) {
        std::vector<HPoint> q;
        for (const NetworkCurve& u : nw.u) q.push_back(u.shape.points[3 * l]);
        cols[l] = splineThrough(q, tv, false);
    }
    for (size_t i = 0; i < R; ++i) {
        std::vector<HPoint> q;
        for (size_t l = 0; l < n; ++l) q.push_back(cols[l][i]);
        const std::vector<HPoint> row = splineThrough(q, tu, false);
        for (size_t j = 0; j < C; ++j) net.points[i * C + j] -= row[j];
    }
    net.shared.assign(R * C, -1);
    for (size_t l = 0; l < n; ++l)
        for (size_t i = 0; i < R; ++i) net.points[i * C + 3 * l] = nw.v[l].shape.points[i], net.shared[i * C + 3 * l] = nw.v[l].idx[i];
    for (size_t k = 0; k < m; ++k)
        for (size_t j = 0; j < C; ++j) net.points[3 * k * C + j] = nw.u[k].shape.points[j], net.shared[3 * k * C + j] = nw.u[k].idx[j];
    for (const HPoint& h : net.points)
        if (!(h.w > 0.0)) throw EditError("the curves' weights differ too much for a network (a weight inside would not be positive)");
    return net;
}

void makeNetworkCorners(Document& doc, const Construction& c) {
    const Network nw = orientedNetwork(doc, c);
    for (size_t l = 0; l < nw.v.size(); ++l) {
        const CurveInput& vin = c.inputs[c.split + l];
        for (size_t k = 0; k < nw.u.size(); ++k) {
            const uint32_t keep = nw.u[k].idx[3 * l], drop = nw.v[l].idx[3 * k];
            if (keep == drop) continue;
            const CurveInput& uin = c.inputs[k];
            // Re-point a curve at the other's point (a patch edge's points stay its patch's).
            const auto repoint = [&](const CurveInput& in, uint32_t from, uint32_t to) {
                if (in.curve < 0) return false;
                for (uint32_t& i : doc.curves[size_t(in.curve)].idx)
                    if (i == from) i = to;
                return true;
            };
            if (!repoint(vin, drop, keep)) repoint(uin, keep, drop);
        }
    }
}

}  // namespace construct
}  // namespace pw

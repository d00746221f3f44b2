#include "core/construct/constructions.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/construction_refs.hpp"

namespace pw {

namespace {

Vec3 vec(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

std::string segmentsWord(size_t n) { return std::to_string(n) + (n == 1 ? " segment" : " segments"); }

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
    std::vector<std::vector<HPoint>> columns(cols);
    for (size_t j = 0; j < cols; ++j) {
        std::vector<HPoint> q;
        for (const CurveShape& s : sections) q.push_back(s.points[j]);
        columns[j] = splineThrough(q, t, c.closed);
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
    return net;
}

struct Side {
    std::vector<HPoint> p;
    std::vector<uint32_t> idx;
    std::string name;
    void reverse() {
        std::reverse(p.begin(), p.end());
        std::reverse(idx.begin(), idx.end());
    }
    Vec3 start() const { return euclidean(p.front()); }
    Vec3 end() const { return euclidean(p.back()); }
};

ConstructedNet edgeSurfaceNet(const Document& doc, const Construction& c) {
    const size_t n = c.inputs.size();
    if (n < 2 || n > 4) throw EditError("an edge surface takes 2, 3 or 4 curves or edges");
    std::vector<Side> sides;
    double size = 0.0;
    for (const CurveInput& in : c.inputs) {
        const CurveShape s = inputShape(doc, in);
        if (s.closed) throw EditError(curveInputName(in) + " is closed; an edge surface's sides are open curves");
        sides.push_back({s.points, curveInputPoints(doc, in), curveInputName(in)});
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
    return net;
}

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

void checkNet(const ConstructedNet& net) {
    for (const HPoint& h : net.points)
        for (int a = 0; a < 3; ++a) {
            const double v = h[a] / h.w;
            if (!std::isfinite(v) || std::abs(v) > limits::kMaxCoordinate)
                throw EditError("the surface reaches beyond the coordinate limit of 1e9");
        }
}

// The window (pr, pc) of a net as 16 grid positions (row-major, row = v).
std::array<uint32_t, 16> window(const std::vector<uint32_t>& grid, uint32_t cols, uint32_t pr, uint32_t pc) {
    std::array<uint32_t, 16> w{};
    for (uint32_t i = 0; i < 4; ++i)
        for (uint32_t j = 0; j < 4; ++j) w[i * 4 + j] = grid[size_t(3 * pr + i) * cols + 3 * pc + j];
    return w;
}

// Writes the net into the construction's pool points; `moved` gets those whose position or weight changed.
void writeNet(Document& doc, const Construction& c, const ConstructedNet& net, std::vector<uint32_t>& moved) {
    for (size_t g = 0; g < c.grid.size(); ++g) {
        const uint32_t i = c.grid[g];
        const Vec3 p = euclidean(net.points[g]);
        const double w = net.points[g].w;
        if (doc.points[i] != p || pointWeight(doc, i) != w) {
            doc.points[i] = p;
            setPointWeight(doc, i, w);
            moved.push_back(i);
        }
    }
}

}  // namespace

CurveShape inputShape(const Document& doc, const CurveInput& in) {
    CurveShape s;
    if (in.curve >= 0) {
        if (size_t(in.curve) >= doc.curves.size()) throw EditError("curve c" + std::to_string(in.curve) + " does not exist");
        const BezierCurve& cv = doc.curves[size_t(in.curve)];
        for (uint32_t i : cv.idx) s.points.push_back(homogeneous(doc.points[i], pointWeight(doc, i)));
        s.closed = curveClosed(cv);
        return s;
    }
    if (in.patch >= doc.patches.size()) throw EditError("patch " + std::to_string(in.patch) + " does not exist");
    const Patch& p = doc.patches[in.patch];
    if (p.basis != Basis::Bezier) throw EditError("patch " + std::to_string(in.patch) + " is not a Bézier patch; its edge is no curve");
    for (int k = 0; k < 4; ++k) {
        const uint32_t i = p.idx[size_t(edgeSlot(in.edge, k))];
        s.points.push_back(homogeneous(doc.points[i], pointWeight(doc, i)));
    }
    return s;
}

ConstructedNet evaluateConstruction(const Document& doc, const Construction& c) {
    ConstructedNet net;
    switch (c.kind) {
        case ConstructionKind::Revolve:
            net = revolveNet(doc, c);
            break;
        case ConstructionKind::Extrude:
            net = extrudeNet(doc, c);
            break;
        case ConstructionKind::Loft:
            net = loftNet(doc, c);
            break;
        case ConstructionKind::EdgeSurface:
            net = edgeSurfaceNet(doc, c);
            break;
        case ConstructionKind::Sweep1:
            net = sweep1Net(doc, c);
            break;
    }
    checkNet(net);
    return net;
}

size_t addConstruction(Document& doc, Construction c, const std::string& name) {
    const ConstructedNet net = evaluateConstruction(doc, c);
    const uint32_t wr = (net.rows - 1) / 3, wc = (net.cols - 1) / 3;
    if (doc.points.size() + net.points.size() > limits::kMaxPoints || doc.patches.size() + size_t(wr) * wc > limits::kMaxPatches)
        throw EditError("the document is full (the surface needs " + std::to_string(size_t(wr) * wc) + " patches)");
    c.rows = net.rows, c.cols = net.cols;
    c.grid.assign(net.points.size(), 0);
    c.error.clear();
    for (uint32_t i = 0; i < net.rows; ++i)
        for (uint32_t j = 0; j < net.cols; ++j) {
            uint32_t& g = c.grid[size_t(i) * net.cols + j];
            if (!net.shared.empty() && net.shared[size_t(i) * net.cols + j] >= 0)
                g = uint32_t(net.shared[size_t(i) * net.cols + j]);
            else if (net.closedU && j == net.cols - 1)
                g = c.grid[size_t(i) * net.cols];
            else if (net.closedV && i == net.rows - 1)
                g = c.grid[j];
            else {
                g = uint32_t(doc.points.size());
                doc.points.push_back(Vec3(0.0));
            }
        }
    std::vector<uint32_t> moved;
    writeNet(doc, c, net, moved);
    const uint32_t first = uint32_t(doc.patches.size());
    for (uint32_t pr = 0; pr < wr; ++pr)
        for (uint32_t pc = 0; pc < wc; ++pc) {
            Patch p;
            p.idx = window(c.grid, net.cols, pr, pc);
            p.name = name + " " + std::to_string(pr * wc + pc);
            c.patches.push_back(uint32_t(doc.patches.size()));
            doc.patches.push_back(std::move(p));
        }
    // Joins along every seam between the windows: G1 (α = 1) where the construction makes it so,
    // C0 elsewhere (the surface there is as smooth as its inputs; the readout measures it).
    const auto at = [&](uint32_t pr, uint32_t pc) { return first + pr * wc + pc; };
    for (uint32_t pr = 0; pr < wr; ++pr)
        for (uint32_t pc = 0; pc < wc; ++pc) {
            if (pc + 1 < wc || (net.closedU && wc > 1))
                doc.joins.push_back(
                    Join{at(pr, pc), Edge::U1, at(pr, (pc + 1) % wc), Edge::U0, false, net.smoothU ? Continuity::G1 : Continuity::C0, 1.0});
            if (pr + 1 < wr || (net.closedV && wr > 1))
                doc.joins.push_back(Join{at(pr, pc), Edge::V1, at((pr + 1) % wr, pc), Edge::V0, false, Continuity::C0, 1.0});
        }
    // Patch edges used as sides: their patches are joined to the new ones (the points are shared).
    for (const CurveInput& in : c.inputs) {
        if (in.curve >= 0) continue;
        const std::vector<uint32_t> pts = curveInputPoints(doc, in);  // an edge: four
        const std::array<uint32_t, 4> e{pts[0], pts[1], pts[2], pts[3]};
        for (uint32_t n = 0; n < c.patches.size(); ++n)
            for (Edge mine : {Edge::U0, Edge::V0, Edge::U1, Edge::V1}) {
                std::array<uint32_t, 4> m{};
                for (int k = 0; k < 4; ++k) m[size_t(k)] = doc.patches[c.patches[n]].idx[size_t(edgeSlot(mine, k))];
                const bool same = m == e, reversed = m == reversedEdgePool(e);
                if ((same || reversed) && e.front() != e.back())
                    doc.joins.push_back(Join{in.patch, in.edge, c.patches[n], mine, reversed, Continuity::C0, 1.0});
            }
    }
    doc.constructions.push_back(std::move(c));
    return doc.constructions.size() - 1;
}

RerunReport rerunConstructions(Document& doc) {
    RerunReport report;
    for (size_t k = doc.constructions.size(); k-- > 0;) {
        const Construction& c = doc.constructions[k];
        const uint32_t wr = c.rows >= 4 ? (c.rows - 1) / 3 : 0, wc = c.cols >= 4 ? (c.cols - 1) / 3 : 0;
        bool intact = c.grid.size() == size_t(c.rows) * c.cols && c.patches.size() == size_t(wr) * wc;
        for (uint32_t n = 0; intact && n < c.patches.size(); ++n)
            intact = c.patches[n] < doc.patches.size() && doc.patches[c.patches[n]].idx == window(c.grid, c.cols, n / wc, n % wc);
        if (!intact) {
            report.baked.push_back(constructionLabel(doc, k));
            bakeConstruction(doc, k);
        }
    }
    for (size_t k = 0; k < doc.constructions.size(); ++k) {
        Construction& c = doc.constructions[k];
        try {
            const ConstructedNet net = evaluateConstruction(doc, c);
            if (net.rows != c.rows || net.cols != c.cols)
                throw EditError("the inputs now make a " + std::to_string((net.rows - 1) / 3) + " × " + std::to_string((net.cols - 1) / 3) +
                                " net of patches, the surface has " + std::to_string((c.rows - 1) / 3) + " × " +
                                std::to_string((c.cols - 1) / 3) + " (bake it, or undo the change of the input)");
            writeNet(doc, c, net, report.moved);
            c.error.clear();
        } catch (const EditError& e) {
            c.error = e.what();
            report.failed.push_back(constructionLabel(doc, k) + ": " + c.error);
        }
    }
    std::sort(report.moved.begin(), report.moved.end());
    report.moved.erase(std::unique(report.moved.begin(), report.moved.end()), report.moved.end());
    return report;
}

}  // namespace pw

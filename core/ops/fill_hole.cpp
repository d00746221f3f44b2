#include "core/ops/fill_hole.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "core/base/errors.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/model/topology.hpp"
#include "core/ops/corner_ops.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/ops/split_ops.hpp"
#include "core/ops/triangle_joins.hpp"

namespace pw {
inline namespace ops {

namespace {

// A patch edge walked from its point 0 (or from point 3 when `reversed`).
// A triangle fill's side may instead be a curve of one segment (`curve` >= 0; depth 0 only).
struct Seg {
    uint32_t patch = 0;
    Edge edge = Edge::U0;
    bool reversed = false;
    int32_t curve = -1;
    Seg flipped() const { return {patch, edge, !reversed, curve}; }
    uint32_t idx(const Document& d, int k, int depth = 0) const {
        if (curve >= 0) return d.curves[size_t(curve)].idx[size_t(reversed ? 3 - k : k)];
        return d.patches[patch].idx[size_t(edgeSlot(edge, reversed ? 3 - k : k, depth))];
    }
    Vec3 at(const Document& d, int k, int depth = 0) const { return d.points[idx(d, k, depth)]; }
};

std::string edgeLabel(uint32_t p, Edge e) { return std::to_string(p) + ":" + std::string(edgeName(e)); }

// An open (unjoined) Bézier patch edge from a to b, walked that way.
std::optional<Seg> openEdgeBetween(const Document& d, const Vec3& a, const Vec3& b, double tol) {
    for (uint32_t p = 0; p < d.patches.size(); ++p) {
        if (d.patches[p].basis != Basis::Bezier) continue;
        for (Edge e : {Edge::U0, Edge::V0, Edge::U1, Edge::V1}) {
            if (findJoin(d, p, e) >= 0) continue;
            const Seg s{p, e, false};
            if (glm::length(s.at(d, 0) - a) <= tol && glm::length(s.at(d, 3) - b) <= tol) return s;
            if (glm::length(s.at(d, 3) - a) <= tol && glm::length(s.at(d, 0) - b) <= tol) return s.flipped();
        }
    }
    return std::nullopt;
}

struct SideGeo {
    Vec3 start{0.0}, mid{0.0}, end{0.0};
    bool single = true;
    void flip() { std::swap(start, end); }
};

}  // namespace

std::string fillHole(Document& doc, const std::vector<HoleSide>& sides) {
    const size_t n = sides.size();
    if (n < 3 || n > 6) throw EditError("fill-hole needs 3 to 6 sides, got " + std::to_string(n));
    const double tol = 1e-6 * std::max(modelSize(doc), 1e-300);
    std::vector<SideGeo> geo(n);
    for (size_t k = 0; k < n; ++k) {
        const auto& edges = sides[k].edges;
        if (sides[k].curve >= 0)
            throw EditError("side " + std::to_string(k + 1) + " is curve c" + std::to_string(sides[k].curve) +
                            ": a fill of patches needs patch edges (P:u0, or P:u0+Q:v1); with `triangle` three sides of one cubic "
                            "each, edges or curves, make one Bézier triangle");
        if (edges.empty() || edges.size() > 2) throw EditError("side " + std::to_string(k + 1) + " needs one edge or two (P:e+Q:f)");
        std::array<Seg, 2> seg;
        for (size_t i = 0; i < edges.size(); ++i) {
            const auto [p, e] = edges[i];
            checkBezier(doc, p, "fill-hole");
            if (findJoin(doc, p, e) >= 0)
                throw EditError("edge " + edgeLabel(p, e) + " is joined already, so it is not the edge of a hole");
            checkPolynomial(doc, p, "fill-hole needs polynomial patches");
            seg[i] = Seg{p, e, false};
        }
        SideGeo& g = geo[k];
        if (edges.size() == 1) {
            std::array<Vec3, 4> pts;
            for (int i = 0; i < 4; ++i) pts[size_t(i)] = seg[0].at(doc, i);
            g = {pts[0], evaluateCurve(pts, 0.5), pts[3], true};
        } else {
            // The two edges meet end to end: orient them so the first ends where the second starts.
            bool met = false;
            for (int f0 = 0; f0 < 2 && !met; ++f0)
                for (int f1 = 0; f1 < 2 && !met; ++f1) {
                    const Seg s0 = f0 ? seg[0].flipped() : seg[0], s1 = f1 ? seg[1].flipped() : seg[1];
                    if (glm::length(s0.at(doc, 3) - s1.at(doc, 0)) <= tol)
                        g = {s0.at(doc, 0), s0.at(doc, 3), s1.at(doc, 3), false}, met = true;
                }
            if (!met)
                throw EditError("side " + std::to_string(k + 1) + ": edges " + edgeLabel(edges[0].first, edges[0].second) + " and " +
                                edgeLabel(edges[1].first, edges[1].second) + " do not meet end to end");
        }
    }
    // The sides in a loop, each walked towards the next.
    auto near = [&](const Vec3& a, const Vec3& b) { return glm::length(a - b) <= tol; };
    if (!near(geo[0].end, geo[1].start) && !near(geo[0].end, geo[1].end)) geo[0].flip();
    for (size_t k = 1; k < n; ++k) {
        if (near(geo[k].end, geo[k - 1].end)) geo[k].flip();
        if (!near(geo[k].start, geo[k - 1].end))
            throw EditError("sides " + std::to_string(k) + " and " + std::to_string(k + 1) +
                            " do not meet: the hole's sides must go round it in order");
    }
    if (!near(geo[n - 1].end, geo[0].start))
        throw EditError("the sides do not close a loop: side " + std::to_string(n) + " does not end where side 1 starts");

    // Split the sides of one edge at their middle (through their rings: no join is dropped).
    std::string note;
    size_t splitCount = 0;
    for (const SideGeo& g : geo) {
        if (!g.single) continue;
        const auto s = openEdgeBetween(doc, g.start, g.end, tol);
        if (!s) continue;  // cut already by an earlier side's ring
        const bool alongU = s->edge == Edge::V0 || s->edge == Edge::V1;
        splitCount += splitRing(doc, s->patch, alongU, 0.5).size();
    }
    // The 2n half sides: h[k][0] from side k's start to its middle, h[k][1] on to its end.
    std::vector<std::array<Seg, 2>> h(n);
    auto findHalves = [&]() {
        for (size_t k = 0; k < n; ++k)
            for (int half = 0; half < 2; ++half) {
                const auto s =
                    half == 0 ? openEdgeBetween(doc, geo[k].start, geo[k].mid, tol) : openEdgeBetween(doc, geo[k].mid, geo[k].end, tol);
                if (!s) throw EditError("side " + std::to_string(k + 1) + ": no open patch edge runs from its end to its middle");
                h[k][size_t(half)] = *s;
            }
    };
    findHalves();
    // Each fill patch's normal must agree with its neighbours': du runs along h[k][0] and dv back
    // along h[k-1][1] from the hole corner, so the loop must turn the right way.
    {
        const Seg& s = h[0][0];
        const Patch& S = doc.patches[s.patch];
        const int slot = edgeSlot(s.edge, s.reversed ? 3 : 0, 0);
        const Vec3 nS = evaluateNet(gatherNet(doc, S.idx), Basis::Bezier, 0.5, (slot % 4) / 3, (slot / 4) / 3).n;
        const Vec3 du = h[0][0].at(doc, 1) - h[0][0].at(doc, 0), dv = h[n - 1][1].at(doc, 2) - h[n - 1][1].at(doc, 3);
        if (glm::dot(glm::cross(du, dv), nS) < 0.0) {
            std::reverse(geo.begin(), geo.end());
            for (SideGeo& g : geo) g.flip();
            findHalves();
        }
    }
    // Seam k runs from side k's middle to the centre: its first leg continues the surrounding's
    // cross tangent there (G1 with it), the centre estimated from the middles and those legs.
    std::vector<Vec3> c1(n);
    Vec3 centroid(0.0);
    for (size_t k = 0; k < n; ++k) {
        c1[k] = 2.0 * h[k][0].at(doc, 3) - h[k][0].at(doc, 3, 1);
        centroid += geo[k].mid / double(n);
    }
    double reach = 0.0;
    for (size_t k = 0; k < n; ++k) reach += glm::length(geo[k].mid - centroid) / double(n);
    Vec3 ahead(0.0);
    for (size_t k = 0; k < n; ++k) {
        const Vec3 leg = c1[k] - geo[k].mid;
        ahead += (geo[k].mid + (glm::length(leg) > 0.0 ? reach * glm::normalize(leg) : Vec3(0.0))) / double(n);
    }
    const Vec3 centre = 0.5 * (centroid + ahead);
    const uint32_t ic = addPoint(doc, centre);
    std::vector<uint32_t> mid(n), s1(n), s2(n);
    for (size_t k = 0; k < n; ++k) {
        mid[k] = h[k][0].idx(doc, 3);  // the surroundings' own point: the fill shares their edges
        s1[k] = addPoint(doc, c1[k]);
        s2[k] = addPoint(doc, centre + (geo[k].mid - centre) / 3.0);
    }
    // Fill patch k at hole corner k (the start of side k): u along h[k][0], v back along h[k-1][1].
    const uint32_t first = uint32_t(doc.patches.size());
    for (size_t k = 0; k < n; ++k) {
        const size_t km = (k + n - 1) % n;
        const Seg a = h[k][0], b = h[km][1].flipped();
        auto mirror = [&](const Seg& s, int i) { return 2.0 * s.at(doc, i) - s.at(doc, i, 1); };
        Patch P;
        auto set = [&](int i, int j, uint32_t q) { P.idx[size_t(4 * j + i)] = q; };
        // The hole's edges are the surroundings' own points (a corner the two sides do not share,
        // a copy that the join merges).
        set(0, 0, a.idx(doc, 0) == b.idx(doc, 0) ? a.idx(doc, 0) : addPoint(doc, a.at(doc, 0)));
        for (int i = 1; i < 3; ++i) set(i, 0, a.idx(doc, i));
        for (int j = 1; j < 3; ++j) set(0, j, b.idx(doc, j));
        set(3, 0, mid[k]);
        set(0, 3, mid[km]);
        set(3, 1, s1[k]), set(3, 2, s2[k]), set(3, 3, ic);
        set(1, 3, s1[km]), set(2, 3, s2[km]);
        set(1, 1, addPoint(doc, 0.5 * (mirror(a, 1) + mirror(b, 1))));
        set(2, 1, addPoint(doc, mirror(a, 2)));
        set(1, 2, addPoint(doc, mirror(b, 2)));
        set(2, 2, addPoint(doc, doc.points[s2[k]] + doc.points[s2[km]] - centre));
        doc.patches.push_back(P);
    }
    // G1 to the surroundings, then to each other (the last seam closes the centre's corner).
    std::string corners;
    auto joinNote = [&](uint32_t a, Edge ea, uint32_t b, Edge eb) {
        std::string c;
        joinEdges(doc, a, ea, b, eb, Continuity::G1, &c);
        if (!c.empty()) corners += "; " + c;
    };
    try {
        for (size_t k = 0; k < n; ++k) {
            const size_t km = (k + n - 1) % n;
            joinNote(h[k][0].patch, h[k][0].edge, first + uint32_t(k), Edge::V0);
            joinNote(h[km][1].patch, h[km][1].edge, first + uint32_t(k), Edge::U0);
        }
    } catch (const EditError& e) {
        // Each side's fill seams continue the surroundings' seams at the hole corners and at the
        // side's middle, where their ratios must agree (DESIGN §14, corners).
        throw EditError(std::string(e.what()) +
                        "; a fill holds G1 when the seams meeting each side at its two ends have the same tangent ratio α (as on a "
                        "box rounded by blends): make those seams match, or fill a smaller hole");
    }
    // The seams between the fill's patches: C0 first, so that the centre's fan is whole when the
    // corner construction makes them G1 together (one at a time, plain G1 rows would turn two
    // edges at the centre opposite and collapse the patch between them).
    for (size_t k = 0; k < n; ++k) joinEdges(doc, first + uint32_t(k), Edge::U1, first + uint32_t((k + 1) % n), Edge::V1, Continuity::C0);
    corners += "; " + makeG1Corner(doc, first, 1, 1);
    note = "filled a " + std::to_string(n) + "-sided hole with " + std::to_string(n) + " patches (" + std::to_string(first) + ".." +
           std::to_string(first + n - 1) + "), G1 to its " + std::to_string(2 * n) + " edges";
    if (splitCount > 0) note += "; split " + std::to_string(splitCount) + " patches at the middle of its sides";
    return note + corners;
}

std::string fillHoleWithTriangle(Document& doc, const std::vector<HoleSide>& sides) {
    if (sides.size() != 3) throw EditError("one triangle fills a hole of 3 sides, got " + std::to_string(sides.size()));
    const double tol = 1e-6 * std::max(modelSize(doc), 1e-300);
    auto near = [&](const Vec3& a, const Vec3& b) { return glm::length(a - b) <= tol; };
    std::array<Seg, 3> seg;
    for (size_t k = 0; k < 3; ++k) {
        if (const int32_t c = sides[k].curve; c >= 0) {
            const std::string name = "curve c" + std::to_string(c);
            if (size_t(c) >= doc.curves.size()) throw EditError("no " + name);
            const BezierCurve& curve = doc.curves[size_t(c)];
            if (curveSegmentCount(curve) != 1 || curveClosed(curve))
                throw EditError(name + " has " + std::to_string(curveSegmentCount(curve)) +
                                " segments; a triangle's side is one cubic (split the hole's side so each is one segment)");
            for (uint32_t i : curve.idx)
                if (pointWeight(doc, i) != 1.0) throw EditError(name + " is rational; Bézier triangles take no weights");
            seg[k] = Seg{0, Edge::U0, false, c};
            continue;
        }
        if (sides[k].edges.size() != 1)
            throw EditError("side " + std::to_string(k + 1) +
                            ": a triangle's side is one patch edge (each of its edges is one cubic); fill without `triangle` for "
                            "sides of two edges");
        const auto [p, e] = sides[k].edges[0];
        checkBezier(doc, p, "fill-hole");
        if (findJoin(doc, p, e) >= 0) throw EditError("edge " + edgeLabel(p, e) + " is joined already, so it is not the edge of a hole");
        checkPolynomial(doc, p, "fill-hole needs polynomial patches");
        seg[k] = Seg{p, e, false};
    }
    // The sides in a loop, each walked towards the next.
    if (!near(seg[0].at(doc, 3), seg[1].at(doc, 0)) && !near(seg[0].at(doc, 3), seg[1].at(doc, 3))) seg[0] = seg[0].flipped();
    for (size_t k = 1; k < 3; ++k) {
        if (near(seg[k].at(doc, 3), seg[k - 1].at(doc, 3))) seg[k] = seg[k].flipped();
        if (!near(seg[k].at(doc, 0), seg[k - 1].at(doc, 3)))
            throw EditError("sides " + std::to_string(k) + " and " + std::to_string(k + 1) +
                            " do not meet: the hole's sides must go round it in order");
    }
    if (!near(seg[2].at(doc, 3), seg[0].at(doc, 0)))
        throw EditError("the sides do not close a loop: side 3 does not end where side 1 starts");
    // The triangle's boundary loop (corner u → v → w, its edges 2, 0, 1) turns counter-clockwise
    // about its normal; a neighbour's normal agrees when its own loop walks the seam the other way.
    // (Judged by the first side that is a patch edge; three curves keep the order they were given in.)
    for (size_t k = 0; k < 3; ++k) {
        if (seg[k].curve >= 0) continue;
        if (edgeLoopSign(seg[k].edge) * (seg[k].reversed ? -1 : 1) > 0) seg = {seg[2].flipped(), seg[1].flipped(), seg[0].flipped()};
        break;
    }
    TrianglePatch t;
    t.name = "corner fill";
    constexpr int kTriangleEdge[3] = {2, 0, 1};
    for (size_t k = 0; k < 3; ++k)
        for (int i = 0; i < 4; ++i) t.idx[size_t(triEdgeSlot(kTriangleEdge[k], i))] = seg[k].idx(doc, i);
    // The middle point from the boundary (the cubic precision rule: the edges' inner points' mean
    // E, pushed away from the corners' mean V by half of E − V); the joins then move it.
    Vec3 E(0.0), V(0.0);
    for (size_t k = 0; k < 3; ++k) {
        V += seg[k].at(doc, 0) / 3.0;
        E += (seg[k].at(doc, 1) + seg[k].at(doc, 2)) / 6.0;
    }
    t.idx[size_t(triSlot(1, 1, 1))] = addPoint(doc, E + 0.5 * (E - V));
    const uint32_t tri = uint32_t(doc.triangles.size());
    doc.triangles.push_back(t);
    size_t joined = 0;
    try {
        for (size_t k = 0; k < 3; ++k)
            if (seg[k].curve < 0)
                joinTriangleEdges(doc, seg[k].patch, seg[k].edge, tri, triangleEdge(kTriangleEdge[k]), Continuity::G1), ++joined;
    } catch (const EditError& e) {
        // One cubic triangle has a single point of its own (b111): it is G1 to three edges only where
        // the surroundings can give (DESIGN §14); blends pinned by their faces cannot.
        throw EditError(std::string(e.what()) +
                        "; one cubic triangle is G1 to three edges only where the patches round it can bend to meet it: fill "
                        "without `triangle` (three patches meeting G1 at a centre) where they cannot");
    }
    if (joined == 3) return "filled a 3-sided hole with triangle " + std::to_string(tri) + ", G1 to its 3 edges";
    return "filled a 3-sided hole with triangle " + std::to_string(tri) + ", G1 to its " + std::to_string(joined) + " patch edge" +
           (joined == 1 ? "" : "s") + ", through the points of its " + std::to_string(3 - joined) + " curve" + (joined == 2 ? "" : "s");
}

}  // namespace ops
}  // namespace pw

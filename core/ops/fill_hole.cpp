#include "core/ops/fill_hole.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>

#include "core/base/errors.hpp"
#include "core/construct/curve_edit.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/eval/fold_check.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/model/construction_refs.hpp"
#include "core/model/topology.hpp"
#include "core/ops/corner_ops.hpp"
#include "core/ops/fill_curves.hpp"
#include "core/ops/fitted_sides.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/ops/split_ops.hpp"
#include "core/ops/triangle_joins.hpp"
#include "core/solve/constraint_solver.hpp"

namespace pw {
inline namespace ops {

namespace {

// A patch edge walked from its point 0 (or from point 3 when `reversed`), or segment `segment`
// of a curve (`curve` >= 0; depth 0 only: a curve has no row beside it).
struct Seg {
    uint32_t patch = 0;
    Edge edge = Edge::U0;
    bool reversed = false;
    int32_t curve = -1;
    uint32_t segment = 0;
    Seg flipped() const { return {patch, edge, !reversed, curve, segment}; }
    uint32_t idx(const Document& d, int k, int depth = 0) const {
        if (curve >= 0) return d.curves[size_t(curve)].idx[3 * size_t(segment) + size_t(reversed ? 3 - k : k)];
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
            // The ends first: findJoin scans the joins, so it is asked only of an edge that fits
            // (per patch edge it made fill-hole beside a 4 096-patch grid take a second).
            const Seg s{p, e, false};
            const bool forward = glm::length(s.at(d, 0) - a) <= tol && glm::length(s.at(d, 3) - b) <= tol;
            const bool backward = !forward && glm::length(s.at(d, 3) - a) <= tol && glm::length(s.at(d, 0) - b) <= tol;
            if ((!forward && !backward) || findJoin(d, p, e) >= 0) continue;
            return forward ? s : s.flipped();
        }
    }
    return std::nullopt;
}

struct SideGeo {
    Vec3 start{0.0}, mid{0.0}, end{0.0};
    bool single = true;
    int32_t curve = -1;  // a side that is a curve of one segment
    void flip() { std::swap(start, end); }
};

// The tangent ratio at each end of each side (at its start, at its end), in the loop's order: the
// ratio at a hole corner makes the fill's leg there, which lies along the next side, continue the
// side's surrounding's cross leg (B1 = B0 + α (A0 − A1) at the corner). None for a curve side.
std::vector<std::optional<std::array<double, 2>>> sideRatios(const Document& doc, const std::vector<std::array<Seg, 2>>& h) {
    const size_t n = h.size();
    auto ratio = [&](const Seg& s, int end, const Seg& along, int from, int next) -> std::optional<double> {
        if (s.curve >= 0) return std::nullopt;
        const Vec3 across = s.at(doc, end) - s.at(doc, end, 1);
        const double a2 = glm::dot(across, across);
        if (a2 <= 0.0) return std::nullopt;
        return glm::dot(along.at(doc, next) - along.at(doc, from), across) / a2;
    };
    std::vector<std::optional<std::array<double, 2>>> out(n);
    for (size_t k = 0; k < n; ++k) {
        const size_t km = (k + n - 1) % n, kp = (k + 1) % n;
        const auto a = ratio(h[k][0], 0, h[km][1], 3, 2), b = ratio(h[k][1], 3, h[kp][0], 0, 1);
        if (a && b) out[k] = std::array<double, 2>{*a, *b};
    }
    return out;
}

// The fill; its sides fitted where their ends' ratios disagree and `mayFit` (`fittedOut` says so).
std::string fillHoleIn(Document& doc, const std::vector<HoleSide>& sides, bool mayFit, bool& fittedOut) {
    const size_t n = sides.size();
    if (n < 3 || n > 6) throw EditError("fill-hole needs 3 to 6 sides, got " + std::to_string(n));
    const double tol = 1e-6 * std::max(modelSize(doc), 1e-300);
    // A curve or an edge given twice would be split twice over.
    for (size_t k = 0; k < n; ++k)
        for (size_t m = 0; m < k; ++m) {
            const bool sameCurve = sides[k].curve >= 0 && sides[k].curve == sides[m].curve;
            bool sameEdge = false;
            for (const auto& e : sides[k].edges)
                sameEdge = sameEdge || std::find(sides[m].edges.begin(), sides[m].edges.end(), e) != sides[m].edges.end();
            if (sameCurve || sameEdge)
                throw EditError("sides " + std::to_string(m + 1) + " and " + std::to_string(k + 1) + " are the same " +
                                (sameCurve ? "curve" : "edge") + ": each side of a hole is given once");
        }
    std::vector<SideGeo> geo(n);
    for (size_t k = 0; k < n; ++k) {
        const auto& edges = sides[k].edges;
        if (const int32_t c = sides[k].curve; c >= 0) {
            const BezierCurve& curve = sideCurve(doc, c, "a fill's side");
            checkCurveSplittable(doc, c);
            std::array<Vec3, 4> pts;
            for (int i = 0; i < 4; ++i) pts[size_t(i)] = doc.points[curve.idx[size_t(i)]];
            geo[k] = {pts[0], evaluateCurve(pts, 0.5), pts[3], true, c};
            continue;
        }
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
        if (g.curve >= 0) {  // at its middle, in place (de Casteljau: the same curve, new inner points)
            insertCurvePoint(doc, uint32_t(g.curve), 0.5);
            continue;
        }
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
                if (const int32_t c = geo[k].curve; c >= 0) {  // its two segments, walked from the side's start
                    const bool fromStart = glm::length(doc.points[doc.curves[size_t(c)].idx[0]] - geo[k].start) <= tol;
                    const uint32_t segment = uint32_t(fromStart ? half : 1 - half);
                    h[k][size_t(half)] = Seg{0, Edge::U0, !fromStart, c, segment};
                    continue;
                }
                const auto s =
                    half == 0 ? openEdgeBetween(doc, geo[k].start, geo[k].mid, tol) : openEdgeBetween(doc, geo[k].mid, geo[k].end, tol);
                if (!s) throw EditError("side " + std::to_string(k + 1) + ": no open patch edge runs from its end to its middle");
                h[k][size_t(half)] = *s;
            }
    };
    findHalves();
    std::vector<size_t> given(n);  // the side as numbered when given, of each side in the loop's order
    for (size_t k = 0; k < n; ++k) given[k] = k;
    // Each fill patch's normal must agree with its neighbours': du runs along h[k][0] and dv back
    // along h[k-1][1] from the hole corner, so the loop must turn the right way.
    // (Judged at the first side that is a patch edge; a hole of curves keeps the order it was given in.)
    for (size_t k0 = 0; k0 < n; ++k0) {
        const Seg& s = h[k0][0];
        if (s.curve >= 0) continue;
        const Patch& S = doc.patches[s.patch];
        const int slot = edgeSlot(s.edge, s.reversed ? 3 : 0, 0);
        const Vec3 nS = evaluateNet(gatherNet(doc, S.idx), Basis::Bezier, 0.5, (slot % 4) / 3, (slot / 4) / 3).n;
        const Vec3 du = h[k0][0].at(doc, 1) - h[k0][0].at(doc, 0),
                   dv = h[(k0 + n - 1) % n][1].at(doc, 2) - h[(k0 + n - 1) % n][1].at(doc, 3);
        if (glm::dot(glm::cross(du, dv), nS) < 0.0) {
            std::reverse(geo.begin(), geo.end());
            std::reverse(given.begin(), given.end());
            for (SideGeo& g : geo) g.flip();
            findHalves();
        }
        break;
    }
    // Seam k runs from side k's middle to the centre: its first leg continues the surrounding's
    // cross tangent there (G1 with it), the centre estimated from the middles and those legs.
    // The fill's rows beside a patch side mirror the surrounding's, scaled by the side's tangent
    // ratio α. Where a curve meets the side at a hole corner, the fill's leg across the side there
    // is the curve's own (half its first leg, once split), so α is that leg over the surrounding's
    // there, and the rows along the side follow it: a G1 join holds one ratio along its edge
    // (between two patch sides the ratio is the surroundings', 1 relative to their mirror).
    std::vector<double> alpha(n, 1.0);
    size_t curveSides = 0, twoEdgeSides = 0;
    for (const SideGeo& g : geo) curveSides += g.curve >= 0 ? 1 : 0, twoEdgeSides += g.single ? 0 : 1;
    // A hole of patch edges whose sides' two ends ask different ratios: α runs along each side and
    // its joins are fitted (core/ops/fitted_sides).
    const auto ratios = sideRatios(doc, h);
    bool fitted = false;
    std::vector<std::array<double, 2>> sideEnds;
    // (Positive ratios, and hole corners the sides share: the fill's joins are made directly, not
    // through joinEdges, which would merge a corner's copies.)
    bool shared = true;
    for (size_t k = 0; k < n && curveSides == 0 && twoEdgeSides == 0; ++k)
        shared = shared && h[k][0].idx(doc, 0) == h[(k + n - 1) % n][1].idx(doc, 3);
    if (mayFit && curveSides == 0 && twoEdgeSides == 0 && shared &&
        std::all_of(ratios.begin(), ratios.end(), [](const auto& r) { return r && (*r)[0] > 0.0 && (*r)[1] > 0.0; }))
        for (const auto& r : ratios) sideEnds.push_back(*r), fitted = fitted || ratiosDisagree(*r);
    fittedOut = fitted;
    const std::vector<FittedSide> fit = fitted ? fitSides(sideEnds) : std::vector<FittedSide>{};
    // The fill's rows beside half side `half` of side k, walked from its hole corner.
    auto fittedRowOf = [&](size_t k, int half) {
        const Seg s = half == 0 ? h[k][0] : h[k][1].flipped();
        std::array<Vec3, 4> e, r;
        for (int i = 0; i < 4; ++i) e[size_t(i)] = s.at(doc, i), r[size_t(i)] = s.at(doc, i, 1);
        const std::array<Vec3, 4> f = half == 0 ? fittedRow(e, r, fit[k].start, fit[k].mid, fit[k].shearFirst)
                                                : fittedRow(e, r, fit[k].end, fit[k].mid, fit[k].shearSecond);
        std::array<Vec3, 4> out;
        for (int i = 0; i < 4; ++i) out[size_t(i)] = e[size_t(i)] + f[size_t(i)];
        return out;
    };
    for (size_t k = 0; k < n; ++k) {
        if (h[k][0].curve >= 0) continue;
        const size_t km = (k + n - 1) % n, kp = (k + 1) % n;
        double sum = 0.0;
        int count = 0;
        if (h[km][1].curve >= 0) {
            const double across = glm::length(h[k][0].at(doc, 0) - h[k][0].at(doc, 0, 1));
            if (across > 0.0) sum += glm::length(h[km][1].at(doc, 2) - h[km][1].at(doc, 3)) / across, ++count;
        }
        if (h[kp][0].curve >= 0) {
            const double across = glm::length(h[k][1].at(doc, 3) - h[k][1].at(doc, 3, 1));
            if (across > 0.0) sum += glm::length(h[kp][0].at(doc, 1) - h[kp][0].at(doc, 0)) / across, ++count;
        }
        if (count > 0) alpha[k] = sum / count;
    }
    // A curve side has no surrounding: its seam leaves the middle towards the centroid.
    std::vector<Vec3> c1(n);
    Vec3 centroid(0.0);
    for (size_t k = 0; k < n; ++k) centroid += geo[k].mid / double(n);
    for (size_t k = 0; k < n; ++k)
        c1[k] = fitted               ? 0.5 * (fittedRowOf(k, 0)[3] + fittedRowOf(k, 1)[3])
                : h[k][0].curve >= 0 ? geo[k].mid + (centroid - geo[k].mid) / 3.0
                                     : h[k][0].at(doc, 3) + alpha[k] * (h[k][0].at(doc, 3) - h[k][0].at(doc, 3, 1));
    double reach = 0.0;
    for (size_t k = 0; k < n; ++k) reach += glm::length(geo[k].mid - centroid) / double(n);
    Vec3 ahead(0.0);
    for (size_t k = 0; k < n; ++k) {
        const Vec3 leg = c1[k] - geo[k].mid;
        ahead += (geo[k].mid + (glm::length(leg) > 0.0 ? reach * glm::normalize(leg) : Vec3(0.0))) / double(n);
    }
    const Vec3 centre = 0.5 * (centroid + ahead);
    const uint32_t ic = addPoint(doc, centre);
    // The seams leave the centre by legs of one length: a seam's tangent ratio at the centre is then
    // 1, as it is at a side's middle (split there, its two legs are equal), so the ratio a G1 join
    // holds along it is the same at both ends (sides of unequal reach made the seams of a mixed
    // hole, edges and curves, over-constrained).
    double leg = 0.0;
    for (size_t k = 0; k < n; ++k) leg += glm::length(geo[k].mid - centre) / (3.0 * double(n));
    std::vector<uint32_t> mid(n), s1(n), s2(n);
    for (size_t k = 0; k < n; ++k) {
        mid[k] = h[k][0].idx(doc, 3);  // the surroundings' own point: the fill shares their edges
        s1[k] = addPoint(doc, c1[k]);
        const Vec3 towards = geo[k].mid - centre;
        s2[k] = addPoint(doc, centre + (glm::length(towards) > 0.0 ? leg * glm::normalize(towards) : towards / 3.0));
    }
    // Fill patch k at hole corner k (the start of side k): u along h[k][0], v back along h[k-1][1].
    const uint32_t first = uint32_t(doc.patches.size());
    for (size_t k = 0; k < n; ++k) {
        const size_t km = (k + n - 1) % n;
        const Seg a = h[k][0], b = h[km][1].flipped();
        // The row beside an edge: the surrounding's mirrored (G1 with it), or beside a curve the
        // blend of the legs at its two ends (from the hole corner along the other side, and the
        // seam's first leg at the side's middle), as a Coons patch would lean.
        auto mirror = [&](const Seg& s, int i) {
            if (s.curve < 0) return s.at(doc, i) + alpha[&s == &a ? k : km] * (s.at(doc, i) - s.at(doc, i, 1));
            const Seg& other = &s == &a ? b : a;
            const Vec3 atCorner = other.at(doc, 1) - other.at(doc, 0), atMiddle = c1[&s == &a ? k : km] - s.at(doc, 3);
            return s.at(doc, i) + (1.0 - i / 3.0) * atCorner + (i / 3.0) * atMiddle;
        };
        Patch P;
        auto set = [&](int i, int j, uint32_t q) { P.idx[size_t(4 * j + i)] = q; };
        // The hole's edges are the surroundings' own points (a corner the two sides do not share:
        // a curve's end, which the other side's join then shares, or a copy that the join merges).
        const uint32_t corner = a.idx(doc, 0) == b.idx(doc, 0) ? a.idx(doc, 0)
                                : a.curve >= 0                 ? a.idx(doc, 0)
                                : b.curve >= 0                 ? b.idx(doc, 0)
                                                               : addPoint(doc, a.at(doc, 0));
        if (b.curve >= 0 && b.idx(doc, 0) != corner)  // two curves meeting here share their end point from now on
            doc.curves[size_t(b.curve)].idx[3 * size_t(b.segment) + (b.reversed ? 3 : 0)] = corner;
        set(0, 0, corner);
        for (int i = 1; i < 3; ++i) set(i, 0, a.idx(doc, i));
        for (int j = 1; j < 3; ++j) set(0, j, b.idx(doc, j));
        set(3, 0, mid[k]);
        set(0, 3, mid[km]);
        set(3, 1, s1[k]), set(3, 2, s2[k]), set(3, 3, ic);
        set(1, 3, s1[km]), set(2, 3, s2[km]);
        // Beside the corner: between the two sides' rows, or the row of the side that is joined
        // (a join fits its ratio along the whole edge: a point off its mirror would bend it).
        const Vec3 twist = a.curve < 0 && b.curve >= 0   ? mirror(a, 1)
                           : a.curve >= 0 && b.curve < 0 ? mirror(b, 1)
                                                         : 0.5 * (mirror(a, 1) + mirror(b, 1));
        if (fitted) {  // the rows the fitted joins hold; the twist is one point (the lean β′ = α′/α)
            const auto ra = fittedRowOf(k, 0), rb = fittedRowOf(km, 1);
            set(1, 1, addPoint(doc, 0.5 * (ra[1] + rb[1])));
            set(2, 1, addPoint(doc, ra[2]));
            set(1, 2, addPoint(doc, rb[2]));
        } else {
            set(1, 1, addPoint(doc, twist));
            set(2, 1, addPoint(doc, mirror(a, 2)));
            set(1, 2, addPoint(doc, mirror(b, 2)));
        }
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
    // (Measured before the joins: they move points, and may split patches to close a corner.)
    const std::string which = ratioMismatch(ratios, given, sides);
    if (fitted) {
        for (size_t k = 0; k < n; ++k) {
            const size_t km = (k + n - 1) % n;
            const Seg b = h[km][1].flipped();
            doc.joins.push_back(fittedJoin(doc, h[k][0].patch, h[k][0].edge, h[k][0].reversed, first + uint32_t(k), Edge::V0, fit[k].start,
                                           fit[k].mid, fit[k].shearFirst));
            doc.joins.push_back(
                fittedJoin(doc, b.patch, b.edge, b.reversed, first + uint32_t(k), Edge::U0, fit[km].end, fit[km].mid, fit[km].shearSecond));
        }
        if (const Projection p = projectConstraints(doc, {}); !p.ok())
            throw EditError("the fill's sides cannot hold G1 with their ratios running along them: " + conflictMessage(p));
    }
    try {
        for (size_t k = 0; k < n && !fitted; ++k) {
            const size_t km = (k + n - 1) % n;
            if (h[k][0].curve < 0) joinNote(h[k][0].patch, h[k][0].edge, first + uint32_t(k), Edge::V0);
            if (h[km][1].curve < 0) joinNote(h[km][1].patch, h[km][1].edge, first + uint32_t(k), Edge::U0);
        }
    } catch (const EditError& e) {
        // Each side's fill seams continue the surroundings' seams at the hole corners and at the
        // side's middle, where their ratios must agree (DESIGN §14, corners).
        throw EditError(std::string(e.what()) +
                        "; a fill holds G1 when the seams meeting each side at its two ends have the same tangent ratio α (as on a "
                        "box rounded by blends)" +
                        (which.empty() ? "" : ", and here " + which) + ": make those seams match, or fill a smaller hole");
    }
    // The seams between the fill's patches: C0 first, so that the centre's fan is whole when the
    // corner construction makes them G1 together (one at a time, plain G1 rows would turn two
    // edges at the centre opposite and collapse the patch between them).
    for (size_t k = 0; k < n; ++k) joinEdges(doc, first + uint32_t(k), Edge::U1, first + uint32_t((k + 1) % n), Edge::V1, Continuity::C0);
    // (A side of two edges has no middle split: its seam's ratio there is the two edges' own.)
    if (n == 4 && curveSides > 0 && twoEdgeSides == 0) {
        // Four seams at the centre hold plain G1 only when the ratios of opposite seams multiply to
        // 1 (the legs there pair off opposite). Each seam's legs are equal at both its ends (the
        // centre's legs are one length; a side split at its middle has equal halves), so its ratio
        // is 1 — not the mean of its rows, which a fill with curve sides makes uneven.
        const Document beforeSeams = doc;
        for (size_t k = 0; k < n; ++k) {
            Join& jn = doc.joins[size_t(findJoin(doc, first + uint32_t(k), Edge::U1))];
            jn.continuity = Continuity::G1;
            jn.alpha = 1.0;
            jn.alphaEnd = 0.0;
            jn.beta2 = 0.0;
            jn.shear = {};
        }
        if (const Projection p = projectConstraints(doc, {}); !p.ok())
            throw EditError("the fill's seams cannot hold G1 together: " + conflictMessage(p));
        if (const std::string fold = foldMadeBy(beforeSeams, doc); !fold.empty())
            throw EditError("refused: the fill's seams would hold G1 only by folding " + fold);
        corners += "; its corner of 4 patches is regular: plain G1 joins hold it";
    } else {
        // A 3-, 5- or 6-sided centre is held by its leaning seams. The fill's patches are free
        // inside, so five or six of them are held as they are, not split 2×2 as a corner of fixed
        // patches is (core/ops/corner_ops): nothing round the hole is cut, and the fitted sides stay whole.
        corners += "; " + makeG1Corner(doc, first, 1, 1, true, false);
    }
    if (fitted) {
        const Document beforeHeld = doc;
        if (const Projection p = projectConstraints(doc, {}); !p.ok())
            throw EditError("the fill's sides cannot hold G1 with their ratios running along them: " + conflictMessage(p));
        if (const std::string fold = foldMadeBy(beforeHeld, doc); !fold.empty())
            throw EditError("refused: the fill's sides, whose ratios run along them, would hold G1 only by folding " + fold);
        if (const std::string out = fittedJoinsOutOfTolerance(doc); !out.empty())
            throw EditError("refused: the fill's sides, whose two ends ask different tangent ratios (" + which +
                            "), would hold G1 only within " + out +
                            ", beyond the 0.1° a fitted seam keeps; make those seams match, or fill a smaller hole");
    }
    note = "filled a " + std::to_string(n) + "-sided hole with " + std::to_string(n) + " patches (" + std::to_string(first) + ".." +
           std::to_string(first + n - 1) + ")";
    if (curveSides < n) note += ", G1 to its " + std::to_string(2 * (n - curveSides)) + " edges";
    if (curveSides > 0)
        note += std::string(curveSides < n ? " and" : ",") + " through the points of its " + std::to_string(curveSides) + " curve" +
                (curveSides == 1 ? "" : "s") + " (each split at its middle)";
    if (splitCount > 0) note += "; split " + std::to_string(splitCount) + " patches at the middle of its sides";
    return note + corners;
}

}  // namespace

std::string fillHole(Document& doc, const std::vector<HoleSide>& sides) {
    Document tried = doc;
    bool fitted = false;
    try {
        std::string note = fillHoleIn(tried, sides, true, fitted);
        doc = std::move(tried);
        return note;
    } catch (const EditError&) {
        if (!fitted) throw;
        // Fitted sides refused (past 0.1°, folding, or a centre that cannot hold): joins of one ratio
        // each, where the surroundings can bend to meet them (they are not joined on); else the
        // fitted reason, which names the sides.
        const std::exception_ptr fittedWhy = std::current_exception();
        tried = doc;
        bool unused = false;
        try {
            std::string note = fillHoleIn(tried, sides, false, unused);
            doc = std::move(tried);
            return note + "; its sides' two ends asked different ratios, so the patches round it were bent to one ratio per side";
        } catch (const EditError&) {
            std::rethrow_exception(fittedWhy);
        }
    }
}

std::string fillHoleWithTriangle(Document& doc, const std::vector<HoleSide>& sides) {
    if (sides.size() != 3) throw EditError("one triangle fills a hole of 3 sides, got " + std::to_string(sides.size()));
    const double tol = 1e-6 * std::max(modelSize(doc), 1e-300);
    auto near = [&](const Vec3& a, const Vec3& b) { return glm::length(a - b) <= tol; };
    std::array<Seg, 3> seg;
    for (size_t k = 0; k < 3; ++k) {
        if (const int32_t c = sides[k].curve; c >= 0) {
            sideCurve(doc, c, "a triangle's side");
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

#include "core/ops/patch_ops.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/eval/bezier_triangle.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/construction_refs.hpp"
#include "core/solve/constraint_solver.hpp"

namespace pw {

namespace {

template <class Item>
void checkItem(const std::vector<Item>& items, uint32_t i, const char* kind) {
    if (i >= items.size())
        throw EditError(std::string(kind) + " " + std::to_string(i) + " does not exist (the document has " + std::to_string(items.size()) +
                        ")");
}

void checkPatch(const Document& doc, uint32_t p) { checkItem(doc.patches, p, "patch"); }

// Removes item i and the pool points only it used.
template <class Item>
void eraseItem(Document& doc, std::vector<Item>& items, uint32_t i) {
    items.erase(items.begin() + i);
    compactPool(doc);
}

void checkBezier(const Document& doc, uint32_t p, const char* what) {
    checkPatch(doc, p);
    if (doc.patches[p].basis != Basis::Bezier)
        throw EditError(std::string(what) + " needs a Bézier patch; patch " + std::to_string(p) + " uses another basis");
}

uint32_t addPoint(Document& doc, const Vec3& v, double weight = 1.0) {
    doc.points.push_back(v);
    const uint32_t i = uint32_t(doc.points.size() - 1);
    if (weight != 1.0) setPointWeight(doc, i, weight);
    return i;
}

Edge opposite(Edge e) {
    switch (e) {
        case Edge::U0:
            return Edge::U1;
        case Edge::U1:
            return Edge::U0;
        case Edge::V0:
            return Edge::V1;
        default:
            return Edge::V0;
    }
}

// Joins touching patch p removed; indices above p shifted down.
void dropPatchFromJoins(Document& doc, uint32_t p) {
    std::erase_if(doc.joins, [&](const Join& j) { return j.patchA == p || j.patchB == p; });
    for (Join& j : doc.joins) {
        if (j.patchA > p) --j.patchA;
        if (j.patchB > p) --j.patchB;
    }
}

}  // namespace

Edge nearestEdge(double u, double v) {
    const double d[4] = {u, v, 1.0 - u, 1.0 - v};
    return Edge(std::min_element(d, d + 4) - d);
}

uint32_t addFlatPatch(Document& doc, const Vec3& center, double size, bool zUp) {
    Patch patch;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const double a = (j / 3.0 - 0.5) * size, b = (i / 3.0 - 0.5) * size;
            const Vec3 off = zUp ? Vec3(a, b, 0.0) : Vec3(a, 0.0, -b);
            patch.idx[size_t(i * 4 + j)] = addPoint(doc, center + off);
        }
    patch.name = "patch " + std::to_string(doc.patches.size());
    doc.patches.push_back(patch);
    return uint32_t(doc.patches.size() - 1);
}

namespace {
// A copy of items[k] (a patch or a triangle) with fresh points moved by `offset`, appended.
template <class Item>
uint32_t duplicateWithOwnPoints(Document& doc, std::vector<Item>& items, uint32_t k, const Vec3& offset, const char* kind) {
    Item copy = items[k];
    for (uint32_t& i : copy.idx) i = addPoint(doc, doc.points[i] + offset, pointWeight(doc, i));
    copy.name = (copy.name.empty() ? std::string(kind) + " " + std::to_string(k) : copy.name) + " copy";
    items.push_back(std::move(copy));
    return uint32_t(items.size() - 1);
}
}  // namespace

uint32_t duplicatePatch(Document& doc, uint32_t p, const Vec3& offset) {
    checkPatch(doc, p);
    return duplicateWithOwnPoints(doc, doc.patches, p, offset, "patch");
}

void deletePatch(Document& doc, uint32_t p) {
    checkPatch(doc, p);
    dropPatchFromJoins(doc, p);
    dropPatchFromConstructions(doc, p);
    eraseItem(doc, doc.patches, p);
}

namespace {
// Where flipPatch moves net slot s (0..15, row-major): the same row, the column mirrored.
int flippedSlot(int s) { return (s / 4) * 4 + 3 - s % 4; }
}  // namespace

void flipPatch(Document& doc, uint32_t p) {
    checkPatch(doc, p);
    Patch& pt = doc.patches[p];
    for (int s = 0; s < 16; ++s)
        if (s % 4 < 2) std::swap(pt.idx[size_t(s)], pt.idx[size_t(flippedSlot(s))]);
    if (pt.tessOverride) {
        auto& o = *pt.tessOverride;
        std::swap(o[0], o[2]);  // outer u=0 <-> u=1
    }
    // Edge U0 <-> U1 (k along v unchanged); on V0/V1 the parameter k runs the other way.
    for (Join& j : doc.joins) {
        for (int side = 0; side < 2; ++side) {
            const bool isA = side == 0;
            if ((isA ? j.patchA : j.patchB) != p) continue;
            Edge& e = isA ? j.edgeA : j.edgeB;
            if (e == Edge::U0 || e == Edge::U1)
                e = opposite(e);
            else
                j.reversed = !j.reversed;
        }
    }
}

uint32_t extrudeEdge(Document& doc, uint32_t p, Edge e) {
    checkBezier(doc, p, "extrude");
    if (findJoin(doc, p, e) >= 0)
        throw EditError("edge " + std::string(edgeName(e)) + " of patch " + std::to_string(p) +
                        " is already joined; extrude an open boundary edge");
    const Patch src = doc.patches[p];
    const Edge ne = opposite(e);  // the new patch's edge on the seam keeps both parameter directions
    Patch np;
    np.name = "patch " + std::to_string(doc.patches.size());
    for (int k = 0; k < 4; ++k) {
        const uint32_t b0 = src.idx[size_t(edgeSlot(e, k, 0))];
        const Vec3 a1 = doc.points[src.idx[size_t(edgeSlot(e, k, 1))]];
        const Vec3 d = doc.points[b0] - a1;  // C1: B1 - B0 = A0 - A1
        np.idx[size_t(edgeSlot(ne, k, 0))] = b0;
        for (int depth = 1; depth < 4; ++depth) np.idx[size_t(edgeSlot(ne, k, depth))] = addPoint(doc, doc.points[b0] + double(depth) * d);
    }
    doc.patches.push_back(np);
    const uint32_t q = uint32_t(doc.patches.size() - 1);
    doc.joins.push_back(Join{p, e, q, ne, false, Continuity::C1, 1.0});
    return q;
}

std::pair<uint32_t, uint32_t> splitPatch(Document& doc, uint32_t p, bool alongU, double t) {
    checkBezier(doc, p, "split");
    if (!(t > 1e-6 && t < 1.0 - 1e-6)) throw EditError("split parameter must lie strictly between 0 and 1");
    const Patch src = doc.patches[p];
    // Rational patches split in homogeneous form: each half keeps the exact surface and gets weights.
    const WeightedSplit halves = splitWindowBezier(gatherWindow(doc, src.idx), alongU, t);
    const Net16& first = halves.first.points;
    const Net16& second = halves.second.points;
    const auto weightOf = [](const WindowNet& h, size_t s) { return h.weights ? (*h.weights)[s] : 1.0; };
    // Edges of the first half: the low edge is kept, the far edge is the new seam.
    const Edge low = alongU ? Edge::U0 : Edge::V0, high = alongU ? Edge::U1 : Edge::V1;
    const Edge side0 = alongU ? Edge::V0 : Edge::U0, side1 = alongU ? Edge::V1 : Edge::U1;
    Patch a = src, b = src;
    b.name = (src.name.empty() ? "patch " + std::to_string(p) : src.name) + " b";
    // Slots on the low edge of a and the high edge of b keep the original pool entries; the shared
    // seam gets new points used by both; all other slots get fresh points.
    std::array<bool, 16> keepA{}, keepB{};
    for (int k = 0; k < 4; ++k) {
        keepA[size_t(edgeSlot(low, k, 0))] = true;
        keepB[size_t(edgeSlot(high, k, 0))] = true;
    }
    for (size_t s = 0; s < 16; ++s) {
        if (!keepA[s]) a.idx[s] = addPoint(doc, first[s], weightOf(halves.first, s));
        if (!keepB[s]) b.idx[s] = addPoint(doc, second[s], weightOf(halves.second, s));
    }
    for (int k = 0; k < 4; ++k) b.idx[size_t(edgeSlot(low, k, 0))] = a.idx[size_t(edgeSlot(high, k, 0))];
    // The split curve's end points coincide with the original corners: keep those shared.
    const uint32_t corner[4] = {src.idx[0], src.idx[3], src.idx[12], src.idx[15]};
    const int cornerSlot[4] = {0, 3, 12, 15};
    for (int c = 0; c < 4; ++c) {
        const size_t s = size_t(cornerSlot[c]);
        const auto same = [&](uint32_t i) {
            return doc.points[i] == doc.points[corner[c]] && pointWeight(doc, i) == pointWeight(doc, corner[c]);
        };
        if (same(a.idx[s])) a.idx[s] = corner[c];
        if (same(b.idx[s])) b.idx[s] = corner[c];
    }
    doc.patches[p] = a;
    doc.patches.push_back(b);
    const uint32_t q = uint32_t(doc.patches.size() - 1);
    // Joins: the cut sides are dropped, the far edge moves to the second half.
    std::vector<Join> kept;
    for (Join j : doc.joins) {
        bool drop = false;
        for (int side = 0; side < 2; ++side) {
            uint32_t& pt = side == 0 ? j.patchA : j.patchB;
            const Edge e = side == 0 ? j.edgeA : j.edgeB;
            if (pt != p) continue;
            if (e == side0 || e == side1) {
                drop = true;
                continue;
            }
            // The halves' tangent rows at the old edges shrink by t (low) or 1 - t (high): the
            // join's ratio changes with them (B1 - B0 = alpha (A0 - A1)).
            const double scale = e == low ? t : 1.0 - t;
            if (e == high) pt = q;
            // For C2/G2 the second differences shrink by scale²: β2 becomes β2·s² (B split) or β2/s (A split).
            if (holdsTangent(j.continuity)) {
                j.alpha = side == 1 ? j.alpha * scale : j.alpha / scale;
                j.beta2 = side == 1 ? j.beta2 * scale * scale : j.beta2 / scale;
                if (std::abs(j.alpha - 1.0) > 1e-12) j.continuity = holdsCurvature(j.continuity) ? Continuity::G2 : Continuity::G1;
            }
        }
        if (!drop) kept.push_back(j);
    }
    doc.joins = std::move(kept);
    const double alpha = (1.0 - t) / t;
    const bool c1 = std::abs(alpha - 1.0) < 1e-12;
    doc.joins.push_back(Join{p, high, q, low, false, c1 ? Continuity::C1 : Continuity::G1, c1 ? 1.0 : alpha});
    compactPool(doc);
    return {p, q};
}

namespace {

// +1 when walking edge e with k increasing runs counter-clockwise around the (u, v) square (the
// boundary loop of the normal du × dv), -1 when it runs clockwise.
int loopSign(Edge e) { return e == Edge::V0 || e == Edge::U1 ? 1 : -1; }

// The nearer way to pair the end points of a's edge ea with b's edge eb (true: k with 3 - k).
bool pairsReversed(const Document& doc, const Patch& A, Edge ea, const Patch& B, Edge eb) {
    auto pa = [&](int k) { return doc.points[A.idx[size_t(edgeSlot(ea, k, 0))]]; };
    auto pb = [&](int k) { return doc.points[B.idx[size_t(edgeSlot(eb, k, 0))]]; };
    const double straight = glm::length(pa(0) - pb(0)) + glm::length(pa(3) - pb(3));
    const double crossed = glm::length(pa(0) - pb(3)) + glm::length(pa(3) - pb(0));
    return crossed < straight;
}

// True when patch b uses no point that another patch, net, triangle or curve uses, apart from
// those of edge eb, and has no join: it can be turned over without disturbing anything else.
bool patchIsFree(const Document& doc, uint32_t b, Edge eb) {
    for (const Join& j : doc.joins)
        if (j.patchA == b || j.patchB == b) return false;
    // Uses of each point by every item, less b's own: what is left is another item's.
    std::vector<uint32_t> uses(doc.points.size(), 0);
    forEachPointIndex(doc, [&](uint32_t i) {
        if (i < uses.size()) ++uses[i];
    });
    const Patch& B = doc.patches[b];
    for (uint32_t i : B.idx) --uses[i];
    for (int k = 0; k < 4; ++k) uses[B.idx[size_t(edgeSlot(eb, k, 0))]] = 0;
    for (uint32_t i : B.idx)
        if (uses[i] > 0) return false;
    return true;
}

}  // namespace

JoinPlan planJoin(const Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb) {
    const Patch& A = doc.patches[a];
    const Patch& B = doc.patches[b];
    JoinPlan plan;
    plan.edgeB = eb;
    plan.reversed = pairsReversed(doc, A, ea, B, eb);
    const bool free = patchIsFree(doc, b, eb);
    // Normals agree across a seam when the two boundary loops walk it in opposite directions.
    if (loopSign(ea) * loopSign(eb) * (plan.reversed ? -1 : 1) > 0 && free) {
        plan.flipB = true;  // reversing u turns the normal over; the u edges swap names
        if (eb == Edge::U0 || eb == Edge::U1) plan.edgeB = eb == Edge::U0 ? Edge::U1 : Edge::U0;
        plan.reversed = eb == Edge::U0 || eb == Edge::U1 ? plan.reversed : !plan.reversed;
    }
    // Sides: A's outward direction at the seam against the way B extends from its edge.
    auto slotB = [&](int k, int d) {
        // After the flip (not applied yet) the slot of plan.edgeB's k-th point at depth d.
        const int s = edgeSlot(plan.edgeB, k, d);
        return plan.flipB ? flippedSlot(s) : s;
    };
    Vec3 out(0.0), chord = doc.points[A.idx[size_t(edgeSlot(ea, 3, 0))]] - doc.points[A.idx[size_t(edgeSlot(ea, 0, 0))]];
    double side = 0.0, gap = 0.0;
    for (int k = 0; k < 4; ++k) {
        const int kb = plan.reversed ? 3 - k : k;
        const Vec3 a0 = doc.points[A.idx[size_t(edgeSlot(ea, k, 0))]], a1 = doc.points[A.idx[size_t(edgeSlot(ea, k, 1))]];
        const Vec3 b0 = doc.points[B.idx[size_t(slotB(kb, 0))]];
        out += a0 - a1;
        for (int d = 1; d < 4; ++d) side += glm::dot(a0 - a1, doc.points[B.idx[size_t(slotB(kb, d))]] - b0);
        gap = std::max(gap, glm::length(a0 - b0));
    }
    plan.match = gap > 1e-6 * std::max(1.0, glm::length(chord));
    if (glm::dot(chord, chord) > 0.0) out -= glm::dot(out, chord) / glm::dot(chord, chord) * chord;
    if (side < 0.0 && glm::length(out) > 1e-12) {
        if (!free)
            throw EditError(
                "patch " + std::to_string(b) + " lies back over patch " + std::to_string(a) +
                " at that seam and is joined to other patches, so it cannot be turned over; pick the other edge or unjoin it first");
        plan.reflectB = true;
        plan.reflectNormal = glm::normalize(out);
    }
    return plan;
}

size_t joinEdges(Document& doc, uint32_t a, Edge ea, uint32_t b, Edge ebPicked, Continuity continuity) {
    checkBezier(doc, a, "join");
    checkBezier(doc, b, "join");
    if (a == b) throw EditError("join needs two different patches");
    if (findJoin(doc, a, ea) >= 0 || findJoin(doc, b, ebPicked) >= 0)
        throw EditError("one of the edges is already joined; unjoin it first");
    const JoinPlan plan = planJoin(doc, a, ea, b, ebPicked);
    const Edge eb = plan.edgeB;
    const bool reversed = plan.reversed;
    if (plan.flipB) flipPatch(doc, b);
    const Patch& A = doc.patches[a];
    const Patch& B = doc.patches[b];
    auto pa = [&](int k, int d) { return doc.points[A.idx[size_t(edgeSlot(ea, k, d))]]; };
    auto ib = [&](int k, int d) { return B.idx[size_t(edgeSlot(eb, reversed ? 3 - k : k, d))]; };
    if (plan.reflectB) {  // B turned over its own edge, to the far side of the seam
        const Vec3 n = plan.reflectNormal;
        for (int k = 0; k < 4; ++k)
            for (int d = 1; d < 4; ++d) {
                Vec3& q = doc.points[ib(k, d)];
                const Vec3 r = q - doc.points[ib(k, 0)];
                q -= 2.0 * glm::dot(r, n) * n;
            }
    }
    // Shape parameters, fixed from the current shape: α (β1) from the tangent rows' lengths (G1,
    // G2), β2 by least squares from the second differences (G2); C1 and C2 use α = 1, β2 = 0.
    const bool geometric = continuity == Continuity::G1 || continuity == Continuity::G2;
    double alpha = 1.0, beta2 = 0.0;
    if (geometric) {
        double sa = 0.0, sb = 0.0;
        for (int k = 0; k < 4; ++k) {
            sa += glm::length(pa(k, 0) - pa(k, 1));
            sb += glm::length(doc.points[ib(k, 1)] - doc.points[ib(k, 0)]);
        }
        alpha = sa > 1e-12 && sb > 1e-12 ? sb / sa : 1.0;
    }
    // B's second difference that the β-constraint asks for, given B's rows 0 and 1.
    auto curvatureRow = [&](int k, const Vec3& b0, const Vec3& b1) {
        const Vec3 t = pa(k, 0) - pa(k, 1);
        return 2.0 * b1 - b0 + alpha * alpha * (pa(k, 2) - 2.0 * pa(k, 1) + pa(k, 0)) + 0.5 * beta2 * t;
    };
    if (continuity == Continuity::G2 && !plan.match) {
        double num = 0.0, den = 0.0;
        for (int k = 0; k < 4; ++k) {
            const Vec3 t = pa(k, 0) - pa(k, 1);
            const Vec3 d = doc.points[ib(k, 2)] - curvatureRow(k, doc.points[ib(k, 0)], doc.points[ib(k, 1)]);
            num += glm::dot(d, t);
            den += glm::dot(t, t);
        }
        beta2 = den > 1e-24 ? 2.0 * num / den : 0.0;
    }
    std::vector<uint32_t> fixed;
    if (plan.match) {
        // Match (Rhino's MatchSrf): A stays; B's boundary row goes onto A's edge, its tangent row
        // moves with it (C0) or onto A's continuation (C1, G1), and for C2/G2 its third row onto
        // the curvature continuation (β2 = 0 when matching G2: B takes A's curvature).
        for (int k = 0; k < 4; ++k) {
            const Vec3 shift = pa(k, 0) - doc.points[ib(k, 0)];
            const Vec3 b1 = continuity == Continuity::C0 ? doc.points[ib(k, 1)] + shift : pa(k, 0) + alpha * (pa(k, 0) - pa(k, 1));
            if (holdsCurvature(continuity)) doc.points[ib(k, 2)] = curvatureRow(k, pa(k, 0), b1);
            doc.points[ib(k, 1)] = b1;
            doc.points[ib(k, 0)] = pa(k, 0);
            for (int d = 0; d < (holdsCurvature(continuity) ? 3 : 2); ++d) fixed.push_back(A.idx[size_t(edgeSlot(ea, k, d))]);
        }
    }
    // Merge: B's edge entries become A's (at the midpoints when they nearly met).
    std::vector<std::pair<uint32_t, uint32_t>> remap;
    for (int k = 0; k < 4; ++k) {
        const uint32_t ia = A.idx[size_t(edgeSlot(ea, k, 0))];
        const uint32_t ibk = ib(k, 0);
        if (ia == ibk) continue;
        doc.points[ia] = 0.5 * (doc.points[ia] + doc.points[ibk]);
        remap.emplace_back(ibk, ia);
    }
    // Everything that used B's edge points (triangles and curves too) now uses A's.
    for (auto [from, to] : remap)
        forEachPointIndex(doc, [from = from, to = to](uint32_t& i) {
            if (i == from) i = to;
        });
    doc.joins.push_back(Join{a, ea, b, eb, reversed, continuity, alpha, beta2});
    if (const Projection p = projectConstraints(doc, fixed); !p.ok()) throw EditError("the join conflicts: " + conflictMessage(p));
    compactPool(doc);
    return doc.joins.size() - 1;
}

void unjoin(Document& doc, size_t j) {
    if (j >= doc.joins.size()) throw EditError("no join " + std::to_string(j));
    const Join jn = doc.joins[j];
    doc.joins.erase(doc.joins.begin() + long(j));
    Patch& B = doc.patches[jn.patchB];
    for (int k = 0; k < 4; ++k) {
        const size_t s = size_t(edgeSlot(jn.edgeB, k, 0));
        B.idx[s] = addPoint(doc, doc.points[B.idx[s]], pointWeight(doc, B.idx[s]));
    }
}

uint32_t addCurve(Document& doc, const Vec3& center, double size, bool zUp) {
    BezierCurve c;
    c.idx.resize(4);
    const double xs[4] = {-0.5, -0.25, 0.25, 0.5}, ys[4] = {0.0, 0.5, 0.5, 0.0};
    for (int k = 0; k < 4; ++k) {
        const double a = xs[k] * size, b = ys[k] * size;
        c.idx[size_t(k)] = addPoint(doc, center + (zUp ? Vec3(a, b, 0.0) : Vec3(a, 0.0, -b)));
    }
    c.name = "curve " + std::to_string(doc.curves.size());
    doc.curves.push_back(c);
    return uint32_t(doc.curves.size() - 1);
}

uint32_t curveFromEdge(Document& doc, uint32_t p, Edge e) {
    checkBezier(doc, p, "take a curve from");
    BezierCurve c;
    c.idx.resize(4);
    for (int k = 0; k < 4; ++k) c.idx[size_t(k)] = doc.patches[p].idx[size_t(edgeSlot(e, k, 0))];
    c.name = (doc.patches[p].name.empty() ? "patch " + std::to_string(p) : doc.patches[p].name) + " edge " + std::string(edgeName(e));
    doc.curves.push_back(c);
    return uint32_t(doc.curves.size() - 1);
}

void deleteCurve(Document& doc, uint32_t c) {
    checkItem(doc.curves, c, "curve");
    dropCurveFromConstructions(doc, c);
    eraseItem(doc, doc.curves, c);
}

uint32_t addTriangle(Document& doc, const Vec3& center, double size, bool zUp) {
    // Corners u, v, w of an equilateral triangle, counter-clockwise seen from above (normal up).
    const double r = size / std::sqrt(3.0);
    auto corner = [&](double deg) {
        const double a = deg * 3.14159265358979323846 / 180.0;
        const double x = r * std::cos(a), y = r * std::sin(a);
        return zUp ? Vec3(x, y, 0.0) : Vec3(x, 0.0, -y);
    };
    const Vec3 U = corner(-30.0), V = corner(90.0), W = corner(210.0);
    TrianglePatch t;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3 - i; ++j) {
            const int k = 3 - i - j;
            t.idx[size_t(triSlot(i, j, k))] = addPoint(doc, center + (double(i) * U + double(j) * V + double(k) * W) / 3.0);
        }
    t.name = "triangle " + std::to_string(doc.triangles.size());
    doc.triangles.push_back(t);
    return uint32_t(doc.triangles.size() - 1);
}

uint32_t duplicateTriangle(Document& doc, uint32_t t, const Vec3& offset) {
    checkItem(doc.triangles, t, "triangle");
    return duplicateWithOwnPoints(doc, doc.triangles, t, offset, "triangle");
}

void deleteTriangle(Document& doc, uint32_t t) {
    checkItem(doc.triangles, t, "triangle");
    eraseItem(doc, doc.triangles, t);
}

void compactPool(Document& doc) {
    std::vector<uint32_t> remap(doc.points.size(), UINT32_MAX);
    forEachPointIndex(std::as_const(doc), [&](uint32_t i) { remap[i] = 0; });
    std::vector<Vec3> pts;
    pts.reserve(doc.points.size());
    for (size_t i = 0; i < doc.points.size(); ++i)
        if (remap[i] == 0) {
            remap[i] = uint32_t(pts.size());
            pts.push_back(doc.points[i]);
        }
    if (pts.size() == doc.points.size()) return;
    remapWeights(doc, remap, pts.size());
    doc.points = std::move(pts);
    forEachPointIndex(doc, [&](uint32_t& i) { i = remap[i]; });
}

}  // namespace pw

#include "core/ops/join_ops.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/base/errors.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/eval/fold_check.hpp"
#include "core/model/construction_refs.hpp"
#include "core/model/topology.hpp"
#include "core/ops/corner_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/ops/triangle_joins.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/sheared_joins.hpp"

namespace pw {
inline namespace ops {

namespace {

// "edge u0 of patch 2 is already joined to edge v1 of patch 5"
std::string describeEdgeJoin(const Document& doc, size_t j, uint32_t p, Edge e) {
    const Join& jn = doc.joins[j];
    const bool isA = jn.patchA == p && jn.edgeA == e;
    return "edge " + std::string(edgeName(e)) + " of patch " + std::to_string(p) + " is already joined to edge " +
           std::string(edgeName(isA ? jn.edgeB : jn.edgeA)) + " of patch " + std::to_string(isA ? jn.patchB : jn.patchA) + " (" +
           std::string(continuityName(jn.continuity)) + ")";
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

// α (β1) from the tangent rows' lengths for G1 and G2, 1 otherwise: the join's shape as it is.
// `a(k, d)` and `b(k, d)` are row d of each side at A's edge point k.
template <class RowA, class RowB>
double measuredAlpha(Continuity c, const RowA& a, const RowB& b) {
    if (c != Continuity::G1 && c != Continuity::G2) return 1.0;
    double sa = 0.0, sb = 0.0;
    for (int k = 0; k < 4; ++k) {
        sa += glm::length(a(k, 0) - a(k, 1));
        sb += glm::length(b(k, 1) - b(k, 0));
    }
    return sa > 1e-12 && sb > 1e-12 ? sb / sa : 1.0;
}

// B's third row that the β-constraint asks for, given B's rows 0 and 1.
template <class RowA>
Vec3 curvatureRow(const RowA& a, int k, double alpha, double beta2, const Vec3& b0, const Vec3& b1) {
    const Vec3 t = a(k, 0) - a(k, 1);
    return 2.0 * b1 - b0 + alpha * alpha * (a(k, 2) - 2.0 * a(k, 1) + a(k, 0)) + 0.5 * beta2 * t;
}

// β2 by least squares from B's second differences (G2; 0 otherwise).
template <class RowA, class RowB>
double measuredBeta2(Continuity c, double alpha, const RowA& a, const RowB& b) {
    if (c != Continuity::G2) return 0.0;
    double num = 0.0, den = 0.0;
    for (int k = 0; k < 4; ++k) {
        const Vec3 t = a(k, 0) - a(k, 1);
        const Vec3 d = b(k, 2) - curvatureRow(a, k, alpha, 0.0, b(k, 0), b(k, 1));
        num += glm::dot(d, t);
        den += glm::dot(t, t);
    }
    return den > 1e-24 ? 2.0 * num / den : 0.0;
}

// EditError when holding the joins folded a patch of `before` (three patches at a corner whose edges
// do not lie in one plane cannot all be G1 with one bicubic patch each: the solver would fold one).
void refuseFolds(const Document& before, const Document& after) {
    const std::string fold = foldMadeBy(before, after);
    if (fold.empty()) return;
    throw EditError("refused: the joins would hold only by folding " + fold +
                    "; where three or more patches meet at a corner whose edges do not lie in one plane, one bicubic patch per face "
                    "cannot be G1 there: join that seam C0, or split the corner patches first");
}

// A G1 join that continues C1/G1 seams through regular corners takes their ratios there exactly
// (α running linearly between two different ones).
void takeContinuedAlpha(Document& doc, size_t j) {
    const auto ends = alphaAtEnds(doc, j);
    Join& jn = doc.joins[j];
    if (ends[0] && ends[1] && std::abs(*ends[0] - *ends[1]) > 1e-12 * *ends[0]) {
        jn.alpha = *ends[0];
        jn.alphaEnd = *ends[1];
    } else if (ends[0] || ends[1]) {
        jn.alpha = ends[0] ? *ends[0] : *ends[1];
    }
}

}  // namespace

JoinPlan planJoin(const Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb) {
    const Patch& A = doc.patches[a];
    const Patch& B = doc.patches[b];
    JoinPlan plan;
    plan.edgeB = eb;
    plan.reversed = edgesPairReversed(doc, a, ea, b, eb);
    const bool free = patchIsFree(doc, b, eb);
    // Normals agree across a seam when the two boundary loops walk it in opposite directions.
    if (edgeLoopSign(ea) * edgeLoopSign(eb) * (plan.reversed ? -1 : 1) > 0 && free) {
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

size_t joinEdges(Document& doc, uint32_t a, Edge ea, uint32_t b, Edge ebPicked, Continuity continuity, std::string* note) {
    if (isTriangleEdge(ea) || isTriangleEdge(ebPicked)) return joinTriangleEdges(doc, a, ea, b, ebPicked, continuity);
    checkBezier(doc, a, "join");
    checkBezier(doc, b, "join");
    if (a == b) throw EditError("join needs two different patches");
    const int ja = findJoin(doc, a, ea), jb = findJoin(doc, b, ebPicked);
    if (ja >= 0 && ja == jb) {  // the pair is joined already: a new continuity for it
        setJoinContinuity(doc, size_t(ja), continuity, note);
        const int now = findJoin(doc, a, ea);
        return now >= 0 ? size_t(now) : size_t(ja);
    }
    if (ja >= 0 || jb >= 0)
        throw EditError(describeEdgeJoin(doc, ja >= 0 ? size_t(ja) : size_t(jb), ja >= 0 ? a : b, ja >= 0 ? ea : ebPicked) +
                        "; unjoin it first, or name its own partner edge to change the join's continuity");
    const JoinPlan plan = planJoin(doc, a, ea, b, ebPicked);
    const Document before = doc;
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
    auto pb = [&](int k, int d) { return doc.points[ib(k, d)]; };
    const double alpha = measuredAlpha(continuity, pa, pb);
    const double beta2 = plan.match ? 0.0 : measuredBeta2(continuity, alpha, pa, pb);
    std::vector<uint32_t> fixed;
    if (plan.match) {
        // Match (Rhino's MatchSrf): A stays; B's boundary row goes onto A's edge, its tangent row
        // moves with it (C0) or onto A's continuation (C1, G1), and for C2/G2 its third row onto
        // the curvature continuation (β2 = 0 when matching G2: B takes A's curvature).
        for (int k = 0; k < 4; ++k) {
            const Vec3 shift = pa(k, 0) - doc.points[ib(k, 0)];
            const Vec3 b1 = continuity == Continuity::C0 ? doc.points[ib(k, 1)] + shift : pa(k, 0) + alpha * (pa(k, 0) - pa(k, 1));
            if (holdsCurvature(continuity)) doc.points[ib(k, 2)] = curvatureRow(pa, k, alpha, beta2, pa(k, 0), b1);
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
    if (continuity == Continuity::G1 && !plan.match) takeContinuedAlpha(doc, doc.joins.size() - 1);
    // A join that closes a corner of 3, 5 or 6 patches with every seam C1/G1 makes it a G1 corner.
    const std::string corner = closeCornersOf(doc, doc.joins.size() - 1);
    if (corner.empty())
        if (const Projection p = projectConstraints(doc, fixed); !p.ok()) throw EditError("the join conflicts: " + conflictMessage(p));
    if (note) *note = corner;
    refuseFolds(before, doc);
    compactPool(doc);
    const int made = findJoin(doc, a, ea);
    return made >= 0 ? size_t(made) : doc.joins.size() - 1;
}

void setJoinContinuity(Document& doc, size_t j, Continuity continuity, std::string* note) {
    if (j >= doc.joins.size()) throw EditError("no join " + std::to_string(j));
    if (joinHasTriangle(doc.joins[j])) return setTriangleJoinContinuity(doc, j, continuity);
    for (const uint32_t p : {doc.joins[j].patchA, doc.joins[j].patchB})
        if (const int k = constructionOfPatch(doc, p); k >= 0)
            throw EditError("join " + std::to_string(j) + " is made by " + constructionLabel(doc, size_t(k)) +
                            ", which sets its continuity; bake it first to change the join by hand");
    const Document before = doc;
    Join& jn = doc.joins[j];
    const Patch& A = doc.patches[jn.patchA];
    const Patch& B = doc.patches[jn.patchB];
    auto pa = [&](int k, int d) { return doc.points[A.idx[size_t(edgeSlot(jn.edgeA, k, d))]]; };
    auto pb = [&](int k, int d) { return doc.points[B.idx[size_t(edgeSlot(jn.edgeB, jn.reversed ? 3 - k : k, d))]]; };
    jn.continuity = continuity;
    jn.alpha = measuredAlpha(continuity, pa, pb);
    jn.beta2 = measuredBeta2(continuity, jn.alpha, pa, pb);
    jn.shear = {};
    jn.alphaEnd = 0.0;
    jn.fitted = false;  // measured again as an exact join (a fill's fitted side made by hand)
    jn.fittedSpan = {0.0, 1.0};
    if (continuity == Continuity::G1) takeContinuedAlpha(doc, j);
    // A change that closes a corner of 3, 5 or 6 C1/G1 seams makes it a G1 corner.
    if (const std::string corner = closeCornersOf(doc, j); !corner.empty()) {
        if (note) *note = corner;
        refuseFolds(before, doc);
        return;
    }
    // A's rows at the seam stay; B's move onto the new conditions (like Match).
    std::vector<uint32_t> fixed;
    for (int k = 0; k < 4; ++k)
        for (int d = 0; d < (holdsCurvature(continuity) ? 3 : holdsTangent(continuity) ? 2 : 1); ++d)
            fixed.push_back(A.idx[size_t(edgeSlot(jn.edgeA, k, d))]);
    std::sort(fixed.begin(), fixed.end());
    fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
    if (const Projection p = projectConstraints(doc, fixed); !p.ok())
        throw EditError("join " + std::to_string(j) + " cannot be " + std::string(continuityName(continuity)) + ": " + conflictMessage(p) +
                        "; it stays as it was");
    refuseFolds(before, doc);
}

void remeasureJoin(Document& doc, size_t j) {
    if (joinHasTriangle(doc.joins[j])) return remeasureTriangleJoin(doc, j);
    Join& jn = doc.joins[j];
    if (!holdsTangent(jn.continuity)) return;
    const Patch& A = doc.patches[jn.patchA];
    const Patch& B = doc.patches[jn.patchB];
    auto pa = [&](int k, int d) { return doc.points[A.idx[size_t(edgeSlot(jn.edgeA, k, d))]]; };
    auto pb = [&](int k, int d) { return doc.points[B.idx[size_t(edgeSlot(jn.edgeB, jn.reversed ? 3 - k : k, d))]]; };
    if (hasShear(jn)) {  // a corner's leaning seam: α and β(t) fitted again (exact after a split)
        if (const auto fit = fitShear(doc, jn)) jn.alpha = fit->alpha, jn.alphaEnd = fit->alphaEnd, jn.shear = fit->shear;
        return;
    }
    const Continuity geometric = holdsCurvature(jn.continuity) ? Continuity::G2 : Continuity::G1;
    jn.alpha = measuredAlpha(geometric, pa, pb);
    jn.beta2 = holdsCurvature(jn.continuity) ? measuredBeta2(geometric, jn.alpha, pa, pb) : 0.0;
    if (std::abs(jn.alpha - 1.0) > 1e-12 || std::abs(jn.beta2) > 1e-12) jn.continuity = geometric;
}

void unjoin(Document& doc, size_t j) {
    if (j >= doc.joins.size()) throw EditError("no join " + std::to_string(j));
    const Join jn = doc.joins[j];
    doc.joins.erase(doc.joins.begin() + long(j));
    if (isTriangleEdge(jn.edgeB)) {  // the triangle on side B gets its own copies
        TrianglePatch& T = doc.triangles[jn.patchB];
        for (int k = 0; k < 4; ++k) {
            const size_t s = size_t(triEdgeSlot(triangleEdgeNumber(jn.edgeB), k));
            T.idx[s] = addPoint(doc, doc.points[T.idx[s]]);
        }
        return;
    }
    Patch& B = doc.patches[jn.patchB];
    for (int k = 0; k < 4; ++k) {
        const size_t s = size_t(edgeSlot(jn.edgeB, k, 0));
        B.idx[s] = addPoint(doc, doc.points[B.idx[s]], pointWeight(doc, B.idx[s]));
    }
}

}  // namespace ops
}  // namespace pw

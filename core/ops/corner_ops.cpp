#include "core/ops/corner_ops.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <utility>

#include "core/base/errors.hpp"
#include "core/eval/fold_check.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/model/construction_refs.hpp"
#include "core/model/topology.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/ops/split_ops.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/sheared_joins.hpp"

namespace pw {
inline namespace ops {

namespace {

int cornerSlot(int cu, int cv) { return 12 * cv + 3 * cu; }
Edge uEdge(int cu) { return cu == 0 ? Edge::U0 : Edge::U1; }
Edge vEdge(int cv) { return cv == 0 ? Edge::V0 : Edge::V1; }
bool isUEdge(Edge e) { return e == Edge::U0 || e == Edge::U1; }

// The end (0 or 3) of edge e of patch q at pool point `vertex`, or -1.
int endAt(const Document& doc, uint32_t q, Edge e, uint32_t vertex) {
    const Patch& P = doc.patches[q];
    if (P.idx[size_t(edgeSlot(e, 0, 0))] == vertex) return 0;
    if (P.idx[size_t(edgeSlot(e, 3, 0))] == vertex) return 3;
    return -1;
}

std::string fmt(const Vec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.3g, %.3g, %.3g)", v.x, v.y, v.z);
    return buf;
}

// The corner (c = cu + 2·cv) of patch q at position `at`, or -1.
int cornerAt(const Document& doc, uint32_t q, const Vec3& at, double tol) {
    for (int c = 0; c < 4; ++c)
        if (glm::length(doc.points[doc.patches[q].idx[size_t(cornerSlot(c % 2, c / 2))]] - at) <= tol) return c;
    return -1;
}

// A patch corner at position `at` whose fan closes, if any.
std::optional<std::pair<CornerCycle, std::pair<uint32_t, int>>> fanAt(const Document& doc, const Vec3& at, double tol) {
    for (uint32_t q = 0; q < doc.patches.size(); ++q)
        for (int cv = 0; cv < 2; ++cv)
            for (int cu = 0; cu < 2; ++cu)
                if (glm::length(doc.points[doc.patches[q].idx[size_t(cornerSlot(cu, cv))]] - at) <= tol)
                    if (auto c = cornerCycle(doc, q, cu, cv)) return std::make_pair(*c, std::make_pair(q, cu + 2 * cv));
    return std::nullopt;
}

void checkCornerPatches(const Document& doc, const CornerCycle& c) {
    for (uint32_t q : c.patches) {
        checkBezier(doc, q, "corner");
        checkPolynomial(doc, q, "a G1 corner needs polynomial patches around it");
        if (const int k = constructionOfPatch(doc, q); k >= 0)
            throw EditError("patch " + std::to_string(q) + " is made by " + constructionLabel(doc, size_t(k)) +
                            ", which sets its joins; bake it first to make the corner G1");
    }
    for (size_t j : c.joins)
        if (holdsCurvature(doc.joins[j].continuity))
            throw EditError("join " + std::to_string(j) + " is " + std::string(continuityName(doc.joins[j].continuity)) + "; a corner of " +
                            std::to_string(c.patches.size()) + " patches can be held G1, not G2: change that join to G1 first");
}

// The end of join jn's edge (A's point 0 or 3) at `at`, or -1 when neither end is there.
int joinEndAt(const Document& doc, const Join& jn, const Vec3& at, double tol) {
    const Patch& A = doc.patches[jn.patchA];
    if (glm::length(doc.points[A.idx[size_t(edgeSlot(jn.edgeA, 0, 0))]] - at) <= tol) return 0;
    if (glm::length(doc.points[A.idx[size_t(edgeSlot(jn.edgeA, 3, 0))]] - at) <= tol) return 3;
    return -1;
}

// The shear coefficient of join jn at its end at `at` (0 when neither end is there).
double shearAt(const Document& doc, const Join& jn, const Vec3& at, double tol) {
    const int k = joinEndAt(doc, jn, at, tol);
    return k == 0 ? jn.shear[0] : k == 3 ? jn.shear[2] : 0.0;
}

bool tangentOnly(Continuity c) { return holdsTangent(c) && !holdsCurvature(c); }

}  // namespace

std::optional<CornerCycle> cornerCycle(const Document& doc, uint32_t p, int cu, int cv) {
    if (p >= doc.patches.size()) return std::nullopt;
    CornerCycle c;
    const uint32_t vertex = doc.patches[p].idx[size_t(cornerSlot(cu, cv))];
    c.at = doc.points[vertex];
    uint32_t q = p;
    Edge out = uEdge(cu);
    for (int step = 0; step < 8; ++step) {
        c.patches.push_back(q);
        const int j = findJoin(doc, q, out);
        if (j < 0) return std::nullopt;
        const Join& jn = doc.joins[size_t(j)];
        const bool qIsA = jn.patchA == q && jn.edgeA == out;
        const uint32_t q2 = qIsA ? jn.patchB : jn.patchA;
        const Edge e2 = qIsA ? jn.edgeB : jn.edgeA;
        const int k = endAt(doc, q2, e2, vertex);
        if (k < 0 || (q2 == q && e2 == out)) return std::nullopt;
        c.joins.push_back(size_t(j));
        const int s = edgeSlot(e2, k, 0);
        const int cu2 = (s % 4) / 3, cv2 = (s / 4) / 3;
        if (q2 == p && cu2 == cu && cv2 == cv) return e2 == vEdge(cv) ? std::optional(c) : std::nullopt;
        q = q2;
        out = isUEdge(e2) ? vEdge(cv2) : uEdge(cu2);
    }
    return std::nullopt;
}

std::string makeG1Corner(Document& doc, uint32_t p, int cu, int cv, bool allSeams, bool split) {
    checkBezier(doc, p, "corner");
    std::optional<CornerCycle> cyc = cornerCycle(doc, p, cu, cv);
    if (!cyc)
        throw EditError("the corner of patch " + std::to_string(p) + " at u = " + std::to_string(cu) + ", v = " + std::to_string(cv) +
                        " is open: every edge through it needs a join first");
    checkCornerPatches(doc, *cyc);
    const size_t n = cyc->patches.size();
    const Vec3 at = cyc->at;
    if (n == 4) {
        for (size_t j : cyc->joins)
            if (allSeams)
                if (doc.joins[j].continuity != Continuity::G1 && doc.joins[j].continuity != Continuity::C1)
                    setJoinContinuity(doc, j, Continuity::G1);
        return "corner of 4 patches at " + fmt(at) + " is regular: plain G1 joins hold it";
    }
    if (n != 3 && n != 5 && n != 6)
        throw EditError("a corner of " + std::to_string(n) + " patches; corners of 3, 5 or 6 patches can be held G1");
    const double tol = 1e-9 * std::max(modelSize(doc), 1e-300);
    std::string splitNote;
    bool leaning = false;  // split already: a seam leans here
    for (size_t j : cyc->joins) leaning = leaning || shearAt(doc, doc.joins[j], at, tol) != 0.0;
    if (n >= 5 && !leaning && split) {
        // Five or six patches: the leaning seams need the freedom of a 2×2 split of each corner
        // patch (issue 40's prototype: one bicubic per face leaves 2 (n = 5) or 4 (n = 6)
        // boundary conditions unmet). Each cut runs through its ring, so no join is dropped.
        const size_t before = doc.patches.size();
        std::set<std::pair<uint32_t, bool>> cut;
        for (uint32_t q : cyc->patches)
            for (bool alongU : {true, false}) {
                if (cut.count({q, alongU})) continue;
                for (const auto& [rc, second] : splitRing(doc, q, alongU, 0.5)) {
                    cut.insert({rc.patch, rc.alongU});
                    cut.insert({second, rc.alongU});
                }
            }
        auto fan = fanAt(doc, at, tol);
        if (!fan) throw EditError("the corner at " + fmt(at) + " could not be found again after splitting its patches");
        cyc = fan->first;
        splitNote = "; split its " + std::to_string(n) + " patches 2×2 first (" + std::to_string(doc.patches.size() - before) +
                    " patches added through their rings)";
    }
    const Document base = doc;
    // The tangent plane: the patches' corner normals together.
    Vec3 normal(0.0);
    for (uint32_t q : cyc->patches)
        if (const int c = cornerAt(doc, q, at, tol); c >= 0)
            normal += evaluateNet(gatherNet(doc, doc.patches[q].idx), Basis::Bezier, 0.5, c % 2, c / 2).n;
    if (glm::length(normal) < 1e-6) throw EditError("the patches around the corner at " + fmt(at) + " do not face one way");
    normal = glm::normalize(normal);
    auto flat = [&](const Vec3& x) { return x - glm::dot(x, normal) * normal; };
    // Each seam's end at the corner (A's point 0 or 3), and its edge leg from the corner.
    auto endOf = [&](const Join& jn) { return joinEndAt(doc, jn, at, tol) == 0 ? 0 : 3; };
    auto legSlots = [&](const Join& jn) {
        const int k = endOf(jn), kb = jn.reversed ? 3 - k : k;
        return std::pair(size_t(edgeSlot(jn.edgeA, k == 0 ? 1 : 2, 0)), size_t(edgeSlot(jn.edgeB, kb == 0 ? 1 : 2, 0)));
    };
    // Where every seam continues one of ratio 1 through its far end (or none), a fill's centre can
    // also be held with every ratio 1: the seams' legs an affine image of a regular n-gon's spokes
    // (l(i−1) + l(i+1) = 2 cos(2π/n)·l(i) round it), the one layout whose leans then close. (Not a
    // corner of the user's own patches: their legs are not the tool's to lay.)
    // A seam that continues one through a regular corner at its far end keeps that seam's α (the
    // rows there are singular unless it matches exactly): found once, from the corner as it is (the
    // seams made here and the legs laid here are not what the far ends continue).
    std::vector<std::optional<double>> farAlpha(n);
    bool unitRatios = true;
    for (size_t i = 0; i < n; ++i) {
        const auto ends = alphaAtEnds(doc, cyc->joins[i]);
        farAlpha[i] = endOf(doc.joins[cyc->joins[i]]) == 0 ? ends[1] : ends[0];
        unitRatios = unitRatios && (!farAlpha[i] || std::abs(*farAlpha[i] - 1.0) < 1e-9);
    }
    bool turnsBadly = false;  // the corner's edges lie on one line or over each other: no layout helps
    auto badTurn = [&](const std::string& why) {
        turnsBadly = true;
        return EditError(why);
    };
    auto hold = [&](bool regular) {
        if (regular) {
            std::vector<Vec3> legs;
            for (size_t j : cyc->joins) {
                const Join& jn = doc.joins[j];
                legs.push_back(flat(doc.points[doc.patches[jn.patchA].idx[legSlots(jn).first]] - at));
            }
            // P cos θi + Q sin θi, θi = ±2πi/n, fitted to the legs (least squares), the turn that fits better.
            double best = -1.0;
            std::vector<Vec3> laid;
            for (double turn : {1.0, -1.0}) {
                Vec3 P(0.0), Q(0.0);
                for (size_t i = 0; i < n; ++i) {
                    const double th = turn * 2.0 * std::numbers::pi * double(i) / double(n);
                    P += legs[i] * (2.0 * std::cos(th) / double(n)), Q += legs[i] * (2.0 * std::sin(th) / double(n));
                }
                std::vector<Vec3> fit(n);
                double err = 0.0;
                for (size_t i = 0; i < n; ++i) {
                    const double th = turn * 2.0 * std::numbers::pi * double(i) / double(n);
                    fit[i] = P * std::cos(th) + Q * std::sin(th);
                    err += glm::dot(fit[i] - legs[i], fit[i] - legs[i]);
                }
                if (best < 0.0 || err < best) best = err, laid = fit;
            }
            for (size_t i = 0; i < n; ++i) {
                const Join& jn = doc.joins[cyc->joins[i]];
                const auto [sa, sb] = legSlots(jn);
                doc.points[doc.patches[jn.patchA].idx[sa]] = at + laid[i];
                doc.points[doc.patches[jn.patchB].idx[sb]] = at + laid[i];
            }
        }
        size_t held = 0;
        for (size_t i = 0; i < n; ++i) {
            const size_t j = cyc->joins[i];
            Join& jn = doc.joins[j];
            if (!allSeams && !tangentOnly(jn.continuity)) continue;  // a C0 seam says nothing about tangents
            ++held;
            const Patch& A = doc.patches[jn.patchA];
            const Patch& B = doc.patches[jn.patchB];
            const int k = endOf(jn);
            const int kb = jn.reversed ? 3 - k : k;
            const Vec3 a0 = doc.points[A.idx[size_t(edgeSlot(jn.edgeA, k, 0))]];
            const Vec3 aLeg = flat(doc.points[A.idx[size_t(edgeSlot(jn.edgeA, k, 1))]] - a0);
            const Vec3 bLeg = flat(doc.points[B.idx[size_t(edgeSlot(jn.edgeB, kb, 1))]] - a0);
            const Vec3 along = flat(k == 0 ? doc.points[A.idx[size_t(edgeSlot(jn.edgeA, 1, 0))]] - a0
                                           : a0 - doc.points[A.idx[size_t(edgeSlot(jn.edgeA, 2, 0))]]);
            // bLeg = −α·aLeg + s·along, in the tangent plane.
            const double aa = glm::dot(aLeg, aLeg), ad = glm::dot(aLeg, along), dd = glm::dot(along, along);
            const double det = aa * dd - ad * ad;
            if (!(det > 1e-12 * aa * dd))
                throw badTurn("refused: at the corner at " + fmt(at) + " the edges beside join " + std::to_string(j) +
                              " lie on one line (a patch there has lost its tangent plane), so the seams cannot turn round it G1");
            // With its far α kept, only its lean β(0) is measured; else α and β(0) both, from the
            // corner's edges in the plane.
            const std::optional<double>& far = farAlpha[i];
            const double rb = -glm::dot(aLeg, bLeg), rd = glm::dot(along, bLeg);
            const double alpha = far ? *far : regular ? 1.0 : (dd * rb + ad * rd) / det;
            const double s = regular || far ? glm::dot(bLeg + alpha * aLeg, along) / dd : (ad * rb + aa * rd) / det;
            if (!(alpha > 0.02))
                throw badTurn("join " + std::to_string(j) + " (patch " + std::to_string(jn.patchA) + " " + std::string(edgeName(jn.edgeA)) +
                              " – patch " + std::to_string(jn.patchB) + " " + std::string(edgeName(jn.edgeB)) +
                              ") does not turn one way around the corner at " + fmt(at) + ": its two sides lie over each other there");
            jn.continuity = Continuity::G1;
            jn.fitted = false;
            jn.fittedSpan = {0.0, 1.0};
            jn.alpha = alpha;
            jn.alphaEnd = 0.0;
            jn.beta2 = 0.0;
            jn.shear[1] = 0.0;
            jn.shear[k == 0 ? 0 : 2] = s;
        }
        if (const Projection pr = projectConstraints(doc, {}); !pr.ok())
            throw EditError("the corner of " + std::to_string(n) + " patches at " + fmt(at) + " cannot be held G1: " + conflictMessage(pr));
        if (const std::string fold = foldMadeBy(base, doc); !fold.empty())
            throw EditError("refused: the corner of " + std::to_string(n) + " patches at " + fmt(at) + " would hold G1 only by folding " +
                            fold + "; round the corner first (fill-hole makes a rounded one)");
        return held;
    };
    size_t held = 0;
    std::string laidNote;
    try {
        held = hold(false);
    } catch (const EditError&) {
        if (split || !unitRatios || turnsBadly) throw;  // (a fill's centre only: its legs are the fill's own points)
        doc = base;                                     // the measured leans do not close round it: every ratio 1, the legs laid regular
        try {
            held = hold(true);
            laidNote = ", every ratio 1 and its edges there laid evenly round it";
        } catch (const EditError&) {
            doc = base;
            held = hold(false);  // (throws its own reason)
        }
    }
    return "corner of " + std::to_string(n) + " patches at " + fmt(at) + ": " +
           (held == n ? "held G1, its " + std::to_string(n) + " seams"
                      : std::to_string(held) + " of its " + std::to_string(n) + " seams G1,") +
           " leaning along their edges near it" + laidNote + splitNote;
}

std::array<std::optional<double>, 2> alphaAtEnds(const Document& doc, size_t j) {
    std::array<std::optional<double>, 2> out;
    if (j >= doc.joins.size()) return out;
    const Join& jn = doc.joins[j];
    const Patch& A = doc.patches[jn.patchA];
    const double size = std::max(modelSize(doc), 1e-300);  // computed once: it reads every point
    const double tol = 1e-9 * size, near = 1e-6 * size;
    // The edge of patch q other than e through its corner at `at`, and the join on it.
    auto next = [&](uint32_t q, Edge e, const Vec3& at) -> int {
        const int c = cornerAt(doc, q, at, tol);
        return c < 0 ? -1 : findJoin(doc, q, isUEdge(e) ? vEdge(c / 2) : uEdge(c % 2));
    };
    auto across = [&](size_t k, uint32_t q) {
        return doc.joins[k].patchA == q ? std::pair(doc.joins[k].patchB, doc.joins[k].edgeB)
                                        : std::pair(doc.joins[k].patchA, doc.joins[k].edgeA);
    };
    for (int k : {0, 3}) {
        const Vec3 at = doc.points[A.idx[size_t(edgeSlot(jn.edgeA, k, 0))]];
        if (const auto fan = fanAt(doc, at, tol); fan && fan->first.patches.size() != 4) continue;  // not a regular corner
        std::optional<double>& result = out[k == 0 ? 0 : 1];
        // Two seams on round the corner, either way: the seam that continues j through it.
        for (const auto& [q, e] : {std::pair(jn.patchA, jn.edgeA), std::pair(jn.patchB, jn.edgeB)}) {
            const int j2 = next(q, e, at);
            if (j2 < 0) continue;
            const auto [q3, e3] = across(size_t(j2), q);
            const int j3 = next(q3, e3, at);
            if (j3 < 0 || size_t(j3) == j || !tangentOnly(doc.joins[size_t(j3)].continuity)) continue;
            // The two seams cross the same two tangent legs there: B's leg = −α·A's leg for both, so
            // α is the other's (or its inverse when the sides are the other way round). Taken
            // exactly: the cross tangents' rows round a regular corner are singular unless the
            // ratios multiply to exactly 1.
            const Join& o = doc.joins[size_t(j3)];
            if (shearAt(doc, o, at, tol) != 0.0) continue;
            const Vec3 la = doc.points[A.idx[size_t(edgeSlot(jn.edgeA, k, 1))]];
            const int ko = joinEndAt(doc, o, at, tol) == 0 ? 0 : 3;
            const Vec3 oa = doc.points[doc.patches[o.patchA].idx[size_t(edgeSlot(o.edgeA, ko, 1))]];
            const Vec3 ob = doc.points[doc.patches[o.patchB].idx[size_t(edgeSlot(o.edgeB, o.reversed ? 3 - ko : ko, 1))]];
            const double alphaThere = ko == 0 ? o.alpha : endAlpha(o);
            if (glm::length(la - oa) <= near)
                result = alphaThere;
            else if (glm::length(la - ob) <= near)
                result = 1.0 / alphaThere;
            if (result) break;
        }
    }
    return out;
}

std::string closeCornersOf(Document& doc, size_t j) {
    if (j >= doc.joins.size()) return "";
    const Join jn = doc.joins[j];
    if (!tangentOnly(jn.continuity)) return "";
    const Patch& A = doc.patches[jn.patchA];
    const Vec3 ends[2] = {doc.points[A.idx[size_t(edgeSlot(jn.edgeA, 0, 0))]], doc.points[A.idx[size_t(edgeSlot(jn.edgeA, 3, 0))]]};
    const double tol = 1e-9 * std::max(modelSize(doc), 1e-300);
    std::string notes;
    for (const Vec3& at : ends) {
        const auto fan = fanAt(doc, at, tol);
        if (!fan) continue;
        const CornerCycle& c = fan->first;
        const size_t n = c.patches.size();
        if (n == 4 || n < 3 || n > 6) continue;
        // A tangent seam that does not lean there yet: plain rows would make two of the corner's
        // edges point opposite ways, collapsing the patch between them.
        bool needed = false;
        for (size_t k : c.joins) needed = needed || (tangentOnly(doc.joins[k].continuity) && shearAt(doc, doc.joins[k], at, tol) == 0.0);
        if (!needed) continue;
        const auto [q, corner] = fan->second;
        notes += (notes.empty() ? "" : "; ") + makeG1Corner(doc, q, corner % 2, corner / 2, false);
    }
    return notes;
}

}  // namespace ops
}  // namespace pw

#include "core/ops/triangle_joins.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/base/errors.hpp"
#include "core/eval/fold_check.hpp"
#include "core/model/construction_refs.hpp"
#include "core/model/topology.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/triangle_seams.hpp"

namespace pw {
inline namespace ops {

namespace {

void checkSide(const Document& doc, uint32_t item, Edge e) {
    if (isTriangleEdge(e)) {
        if (item >= doc.triangles.size()) throw EditError("no triangle " + std::to_string(item));
        return;
    }
    checkBezier(doc, item, "a join with a triangle");
    checkPolynomial(doc, item, "a join with a triangle needs a polynomial patch");
    if (const int k = constructionOfPatch(doc, item); k >= 0)
        throw EditError("patch " + std::to_string(item) + " is made by " + constructionLabel(doc, size_t(k)) +
                        ", which sets its joins; bake it first to join it to a triangle");
}

void checkContinuity(Continuity c) {
    if (c != Continuity::C0 && c != Continuity::G1)
        throw EditError("a join with a Bézier triangle is C0 or G1 (got " + std::string(continuityName(c)) +
                        "): a triangle's cross derivative along its edge is quadratic where a patch's is cubic, so their "
                        "parametric C1 has no meaning; G1 holds the tangent plane");
}

// |D| summed at the Bernstein coefficients: a side's cross derivative size.
double crossLength(const Document& doc, const SeamSide& s) {
    double sum = 0.0;
    for (const PointCombination& c : s.cross) sum += glm::length(valueOf(doc, c));
    return sum / double(s.cross.size());
}

// α and β for join j as it stands, by least squares (exact where the seam is G1 already; else what
// the projection then straightens the seam to, each side's cross derivative kept as near as it can
// be). EditError when the seam has no tangent plane or B lies back over A (α ≤ 0: G1 would fold).
void measure(Document& doc, Join& jn) {
    jn.shear = {};
    jn.alphaEnd = 0.0;
    jn.alpha = 1.0;
    if (jn.continuity != Continuity::G1) return;
    const auto a = seamSide(doc, jn, false), b = seamSide(doc, jn, true);
    if (!a || !b) throw EditError("the join names a patch or triangle that does not exist");
    if (!(crossLength(doc, *a) > 0.0) || !(crossLength(doc, *b) > 0.0))
        throw EditError("the seam has no tangent plane on one side (a collapsed edge); join it C0");
    const auto fit = fitTriangleSeam(doc, jn);
    if (!fit) throw EditError("the seam has no tangent plane along it (a cross derivative along the edge); join it C0");
    if (!(fit->alpha > 0.0) || fit->alphaEnd < 0.0)
        throw EditError(joinSideName(jn, true) + " lies back over " + joinSideName(jn, false) +
                        " at that seam, so G1 would fold it; move it to the other side of the edge first, or join C0");
    jn.alpha = fit->alpha;
    jn.alphaEnd = fit->alphaEnd;
    jn.shear = fit->shear;
}

// EditError when holding the joins turned part of a patch or triangle over.
void refuseFolding(const Document& before, const Document& after) {
    if (const std::string fold = foldMadeBy(before, after); !fold.empty())
        throw EditError("refused: the join would hold only by folding " + fold +
                        "; move the sides nearer to one tangent plane first, or join C0");
}

// The points of side A the join's rows involve (its edge, and for G1 its cross derivative's),
// sorted: what stays put when B is matched to A.
std::vector<uint32_t> sideAPoints(const Document& doc, const Join& jn) {
    std::vector<uint32_t> out;
    if (const auto side = seamSide(doc, jn, false)) {
        out.assign(side->edge.begin(), side->edge.end());
        if (jn.continuity == Continuity::G1)
            for (const auto& c : side->cross)
                for (const auto& term : c) out.push_back(term.first);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace

size_t joinTriangleEdges(Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb, Continuity continuity) {
    checkContinuity(continuity);
    checkSide(doc, a, ea);
    checkSide(doc, b, eb);
    if (a == b && isTriangleEdge(ea) == isTriangleEdge(eb))
        throw EditError("join needs two different " + std::string(isTriangleEdge(ea) ? "triangles" : "patches"));
    const int ja = findJoin(doc, a, ea), jb = findJoin(doc, b, eb);
    if (ja >= 0 && ja == jb) {
        setTriangleJoinContinuity(doc, size_t(ja), continuity);
        return size_t(ja);
    }
    if (ja >= 0 || jb >= 0) {
        const Join& other = doc.joins[size_t(ja >= 0 ? ja : jb)];
        throw EditError(joinSideName(ja >= 0 ? a : b, ja >= 0 ? ea : eb) + " is already joined (join " + std::to_string(ja >= 0 ? ja : jb) +
                        ", " + joinSideName(other, false) + " – " + joinSideName(other, true) + ", " +
                        std::string(continuityName(other.continuity)) + "); unjoin it first");
    }
    const std::vector<uint32_t> pa = edgePoolOf(doc, a, ea), pb = edgePoolOf(doc, b, eb);
    auto P = [&](uint32_t i) { return doc.points[i]; };
    const double same = glm::length(P(pa[0]) - P(pb[0])) + glm::length(P(pa[3]) - P(pb[3]));
    const double crossed = glm::length(P(pa[0]) - P(pb[3])) + glm::length(P(pa[3]) - P(pb[0]));
    const bool reversed = crossed < same;
    double gap = 0.0;
    for (int k = 0; k < 4; ++k) gap = std::max(gap, glm::length(P(pa[size_t(k)]) - P(pb[size_t(reversed ? 3 - k : k)])));
    const bool match = gap > 1e-6 * std::max(1.0, glm::length(P(pa[3]) - P(pa[0])));
    // B's edge entries become A's: at the midpoints when they met, on A's edge when matching.
    std::vector<std::pair<uint32_t, uint32_t>> remap;
    for (int k = 0; k < 4; ++k) {
        const uint32_t ia = pa[size_t(k)], ib = pb[size_t(reversed ? 3 - k : k)];
        if (ia == ib) continue;
        if (!match) doc.points[ia] = 0.5 * (doc.points[ia] + doc.points[ib]);
        remap.emplace_back(ib, ia);
    }
    for (auto [from, to] : remap)
        forEachPointIndex(doc, [from = from, to = to](uint32_t& i) {
            if (i == from) i = to;
        });
    const Document before = doc;
    doc.joins.push_back(Join{a, ea, b, eb, reversed, continuity, 1.0});
    Join& jn = doc.joins.back();
    measure(doc, jn);
    const std::vector<uint32_t> fixed = match ? sideAPoints(doc, jn) : std::vector<uint32_t>{};
    if (const Projection p = projectConstraints(doc, fixed); !p.ok()) throw EditError("the join conflicts: " + conflictMessage(p));
    refuseFolding(before, doc);
    compactPool(doc);
    const int made = findJoin(doc, a, ea);
    return made >= 0 ? size_t(made) : doc.joins.size() - 1;
}

void setTriangleJoinContinuity(Document& doc, size_t j, Continuity continuity) {
    if (j >= doc.joins.size()) throw EditError("no join " + std::to_string(j));
    checkContinuity(continuity);
    const Document before = doc;
    Join& jn = doc.joins[j];
    jn.continuity = continuity;
    measure(doc, jn);
    // A's side of the seam stays; B's moves onto the new rows.
    if (const Projection p = projectConstraints(doc, sideAPoints(doc, jn)); !p.ok())
        throw EditError("join " + std::to_string(j) + " cannot be " + std::string(continuityName(continuity)) + ": " + conflictMessage(p) +
                        "; it stays as it was");
    refuseFolding(before, doc);
}

void remeasureTriangleJoin(Document& doc, size_t j) {
    Join& jn = doc.joins[j];
    if (jn.continuity != Continuity::G1) return;
    if (const auto fit = fitTriangleSeam(doc, jn); fit && fit->alpha > 0.0 && fit->alphaEnd >= 0.0)
        jn.alpha = fit->alpha, jn.alphaEnd = fit->alphaEnd, jn.shear = fit->shear;
}

}  // namespace ops
}  // namespace pw

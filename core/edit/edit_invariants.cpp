#include "core/edit/edit_invariants.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <vector>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/eval/fold_check.hpp"
#include "core/model/join_detect.hpp"
#include "core/model/topology.hpp"
#include "core/ops/fitted_sides.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"

namespace pw {
inline namespace edit {

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

// A fitted join (a fill's side whose ratio runs along it) holds its rows and, beyond them, its
// measured angle within kFittedJoinDegrees; an edit may not take one past that (a document read
// with one past it already may be edited as long as the worst gets no worse).
void checkFittedAngles(const Document& before, const Document& after) {
    const std::string out = fittedJoinsWorsened(before, after);
    if (out.empty()) return;
    throw EditError("refused: it would leave " + out + ", beyond the " + number(kFittedJoinDegrees) +
                    "° a fill's fitted seam keeps; move less, or unjoin that seam first");
}

void checkJoins(const Document& before, const Document& after, bool detected) {
    const double tol =
        detected ? std::max(joinTolerance(after), JoinDetectOptions{}.relativeTolerance * modelSize(after)) : joinTolerance(after);
    const JoinResiduals r = joinResiduals(after);
    double worst = r.netSeams;
    for (double v : r.perJoin) worst = std::max(worst, v);
    if (worst <= tol) return;
    // A document that was already off (read from a file that way) may be edited as long as the
    // edit makes it no worse.
    const double worstBefore = maxConstraintResidual(before);
    if (worstBefore > joinTolerance(before) && worst <= worstBefore * (1.0 + 1e-9) + tol) return;
    std::string names;
    int named = 0;
    for (size_t j = 0; j < r.perJoin.size(); ++j)
        if (r.perJoin[j] > tol && named++ < 4)
            names += (names.empty() ? "" : "; ") + describeJoin(after, j) + " off by " + number(r.perJoin[j]);
    if (r.netSeams > tol && named++ < 4) names += (names.empty() ? "" : "; ") + std::string("a net's C1 seam off by ") + number(r.netSeams);
    throw EditError("refused: it would leave " + names + " (joins hold within " + number(tol) +
                    "); change or unjoin the conflicting join first");
}

// Patches of `after` whose control points (their indices or positions) differ from `before`'s; new
// patches count as changed.
std::vector<bool> changedPatches(const Document& before, const Document& after) {
    std::vector<bool> changed(after.patches.size(), true);
    const size_t common = std::min(before.patches.size(), after.patches.size());
    for (size_t p = 0; p < common; ++p) {
        const Patch &a = before.patches[p], &b = after.patches[p];
        bool same = a.idx == b.idx;
        for (size_t k = 0; same && k < b.idx.size(); ++k)
            same = b.idx[k] < before.points.size() && b.idx[k] < after.points.size() && before.points[b.idx[k]] == after.points[b.idx[k]] &&
                   pointWeight(before, b.idx[k]) == pointWeight(after, b.idx[k]);
        changed[p] = !same;
    }
    return changed;
}

// The joins on patch p, named (at most two), for a refusal: " at join 3 (…)" or "".
std::string joinsOnPatch(const Document& doc, int p) {
    std::string out;
    int named = 0;
    for (size_t j = 0; j < doc.joins.size() && named < 2; ++j)
        if (quadJoin(doc.joins[j]) && (int(doc.joins[j].patchA) == p || int(doc.joins[j].patchB) == p))
            out += std::string(named++ ? " and " : " at ") + describeJoin(doc, j);
    return out;
}

// Whether `after` holds a join `before` did not (a new one, or one whose continuity changed). Most
// edits leave the joins as they were (one comparison); otherwise n log n.
bool joinsAddedOrChanged(const Document& before, const Document& after) {
    if (before.joins == after.joins) return false;
    using Key = std::tuple<uint32_t, Edge, uint32_t, Edge, Continuity>;
    auto key = [](const Join& j) { return Key{j.patchA, j.edgeA, j.patchB, j.edgeB, j.continuity}; };
    std::vector<Key> had;
    had.reserve(before.joins.size());
    for (const Join& j : before.joins) had.push_back(key(j));
    std::sort(had.begin(), had.end());
    return std::any_of(after.joins.begin(), after.joins.end(),
                       [&](const Join& j) { return !std::binary_search(had.begin(), had.end(), key(j)); });
}

// A surface never satisfies a constraint by folding or collapsing. Patch p of `before` and of
// `after` are compared where the edit kept every patch in its place; a patch that only moved
// rigidly, was mirrored or scaled uniformly keeps its shape and is not measured.
// - An edit that brings in or changes joins may not turn part of a reshaped patch over or collapse
//   a tangent plane that was not so.
// - Any other edit (a move, a rotation, a scale whose joins drag the neighbours) may not turn over
//   part of a reshaped patch that has a join. A patch with no join has no constraint to satisfy: its
//   shape, collapsed corners included (a pole), is the user's own.
// New patches have no "before": they may not be turned over at all where the model had no fold
// (newFoldIn), unless an import brought them (Brought::File: the shapes are the file's own). The
// operations that join name the cause more precisely first (join_ops, corner_ops, triangle_joins).
std::string foldRefusal(const Document& before, const Document& after, const std::vector<bool>& changed, Brought brought) {
    if (const std::string fold = brought == Brought::File ? "" : newFoldIn(before, after); !fold.empty())
        return "refused: it would make a folded surface, " + fold + "; change the edges or curves it is made from";
    if (after.patches.size() != before.patches.size() || after.triangles.size() != before.triangles.size()) return "";
    if (joinsAddedOrChanged(before, after)) {
        const std::string fold = foldMadeBy(before, after);
        return fold.empty() ? "" : "refused: its joins would hold only by folding " + fold + "; join C0 or reshape the patches first";
    }
    std::vector<bool> joined(after.patches.size(), false);
    for (const Join& j : after.joins)
        if (quadJoin(j) && j.patchA < joined.size() && j.patchB < joined.size()) joined[j.patchA] = joined[j.patchB] = true;
    for (size_t p = 0; p < joined.size() && p < changed.size(); ++p) joined[p] = joined[p] && changed[p];
    int patch = -1;
    const std::string fold = foldMadeIn(before, after, joined, true, &patch);
    if (fold.empty()) return "";
    return "refused: holding its joins would fold " + fold + joinsOnPatch(after, patch) +
           "; move less, unjoin that join, or join with less continuity";
}

// No accepted edit leaves a coordinate the file reader would refuse (issue 73: the document could
// then no longer be saved or autosaved).
void checkCoordinates(const Document& after) {
    for (size_t i = 0; i < after.points.size(); ++i)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(after.points[i][k]) || std::abs(after.points[i][k]) > limits::kMaxCoordinate)
                throw EditError("refused: it would move point " + std::to_string(i) + " to " + number(after.points[i][k]) + " in " +
                                "xyz"[k] + ", beyond the ±" + number(limits::kMaxCoordinate) + " a document may hold");
}

std::string measuredFailure(const JoinContinuity& m, uint8_t f, const ContinuityTolerances& tol) {
    std::string out;
    auto add = [&](const std::string& s) { out += (out.empty() ? "" : ", ") + s; };
    if (f & kPositionOut) add("a gap of " + number(m.c0Gap) + " (tolerance " + number(tol.position) + ")");
    if (f & kAngleOut) add(number(m.normalAngleDeg) + "° between the normals (tolerance " + number(tol.angleDeg) + "°)");
    if (f & kCurvatureOut) add(number(m.curvatureDeviationPct) + " % curvature deviation (tolerance " + number(tol.curvaturePct) + " %)");
    return out;
}

// What a user sees (issue 73): the control-point rows can hold while the surface does not (a G1
// join of two collapsed pole edges measures 180°; a G2 join's curvature after a split). Every join
// between patches the edit changed is measured as `info` and the Continuity panel measure it,
// against the document's tolerances. One that was out the same way before and got no worse may
// stay (a file read so); fitted joins are held by their own angle (checkFittedAngles).
void checkMeasured(const Document& before, const Document& after, const std::vector<bool>& changed) {
    std::vector<size_t> only;
    const bool joinsSame = before.joins == after.joins;
    for (size_t j = 0; j < after.joins.size(); ++j) {
        const Join& jn = after.joins[j];
        if (!quadJoin(jn) || jn.fitted || jn.patchA >= changed.size() || jn.patchB >= changed.size()) continue;
        // A join the edit made or changed (a pole's join raised to G2 moves no point) or one beside a changed patch.
        const bool madeOrChanged = !joinsSame && std::find(before.joins.begin(), before.joins.end(), jn) == before.joins.end();
        if (changed[jn.patchA] || changed[jn.patchB] || madeOrChanged) only.push_back(j);
    }
    if (only.empty()) return;
    const std::vector<JoinContinuity> measured = continuityReport(after, 32, only);
    std::vector<size_t> failing;
    for (const JoinContinuity& m : measured)
        if (toleranceFailures(m, after.joins[m.join].continuity, after.tolerances)) failing.push_back(m.join);
    if (failing.empty()) return;
    // The same joins before the edit, where they were there (same sides, same continuity).
    std::vector<size_t> earlier;
    std::vector<int> earlierOf(after.joins.size(), -1);
    for (size_t j : failing)
        for (size_t i = 0; i < before.joins.size(); ++i) {
            const Join &a = before.joins[i], &b = after.joins[j];
            if (a.patchA == b.patchA && a.edgeA == b.edgeA && a.patchB == b.patchB && a.edgeB == b.edgeB && a.continuity == b.continuity) {
                earlierOf[j] = int(earlier.size());
                earlier.push_back(i);
                break;
            }
        }
    const std::vector<JoinContinuity> was = earlier.empty() ? std::vector<JoinContinuity>{} : continuityReport(before, 32, earlier);
    std::string names;
    int named = 0;
    for (const JoinContinuity& m : measured) {
        const uint8_t f = toleranceFailures(m, after.joins[m.join].continuity, after.tolerances);
        if (!f) continue;
        if (earlierOf[m.join] >= 0) {
            const JoinContinuity& w = was[size_t(earlierOf[m.join])];
            const double slack = 1e-9;
            const bool noWorse =
                (toleranceFailures(w, before.joins[earlier[size_t(earlierOf[m.join])]].continuity, before.tolerances) & f) == f &&
                m.c0Gap <= std::max(w.c0Gap, after.tolerances.position) * (1 + slack) + 1e-12 &&
                m.normalAngleDeg <= std::max(w.normalAngleDeg, after.tolerances.angleDeg) * (1 + slack) + 1e-9 &&
                m.curvatureDeviationPct <= std::max(w.curvatureDeviationPct, after.tolerances.curvaturePct) * (1 + slack) + 1e-9;
            if (noWorse) continue;
        }
        if (named++ < 3)
            names += (names.empty() ? "" : "; ") + describeJoin(after, m.join) + " with " + measuredFailure(m, f, after.tolerances);
    }
    if (named == 0) return;
    throw EditError("refused: it would leave " + names + (named > 3 ? " and " + std::to_string(named - 3) + " more" : std::string()) +
                    ", measured along the seam; change or unjoin the conflicting join, or join with less continuity");
}

}  // namespace

double joinTolerance(const Document& doc) { return 1e-6 * modelSize(doc) + 1e-12; }

std::string describeJoin(const Document& doc, size_t j) {
    const Join& jn = doc.joins[j];
    return "join " + std::to_string(j) + " (" + joinSideName(jn, false) + " – " + joinSideName(jn, true) + ", " +
           std::string(continuityName(jn.continuity)) + ")";
}

void checkEditInvariants(const Document& before, const Document& after, Brought brought) {
    const bool detected = brought != Brought::Nothing;
    checkCoordinates(after);
    checkJoins(before, after, detected);
    checkFittedAngles(before, after);
    const std::vector<bool> changed = changedPatches(before, after);
    checkMeasured(before, after, changed);
    if (std::string fold = foldRefusal(before, after, changed, brought); !fold.empty()) throw EditError(fold);
}

}  // namespace edit
}  // namespace pw

#include "core/edit/edit_invariants.hpp"

#include <algorithm>
#include <cstdio>
#include <tuple>
#include <vector>

#include "core/base/errors.hpp"
#include "core/eval/fold_check.hpp"
#include "core/model/join_detect.hpp"
#include "core/model/topology.hpp"
#include "core/ops/fitted_sides.hpp"
#include "core/solve/constraint_solver.hpp"

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

// A join is never "held" by folding: an edit that brings in or changes joins may not turn part of a
// patch over or collapse a tangent plane that was not so before. Checked where every patch keeps
// its place (joining, changing continuity, corners, any edit that reshapes without adding or
// removing patches): a split or a fill makes new patches whose shapes have no "before" (a half of a
// cap's patch at its pole samples differently from the whole), and they check their own. The
// operations that join name the cause more precisely first (join_ops, corner_ops, triangle_joins).
void checkFolds(const Document& before, const Document& after) {
    if (after.patches.size() != before.patches.size() || after.triangles.size() != before.triangles.size()) return;
    if (!joinsAddedOrChanged(before, after)) return;
    if (const std::string fold = foldMadeBy(before, after); !fold.empty())
        throw EditError("refused: its joins would hold only by folding " + fold + "; join C0 or reshape the patches first");
}

}  // namespace

double joinTolerance(const Document& doc) { return 1e-6 * modelSize(doc) + 1e-12; }

std::string describeJoin(const Document& doc, size_t j) {
    const Join& jn = doc.joins[j];
    return "join " + std::to_string(j) + " (" + joinSideName(jn, false) + " – " + joinSideName(jn, true) + ", " +
           std::string(continuityName(jn.continuity)) + ")";
}

void checkEditInvariants(const Document& before, const Document& after, bool detected) {
    checkJoins(before, after, detected);
    checkFittedAngles(before, after);
    checkFolds(before, after);
}

}  // namespace edit
}  // namespace pw

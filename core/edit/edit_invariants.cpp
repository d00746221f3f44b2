#include "core/edit/edit_invariants.hpp"

#include <algorithm>
#include <cstdio>

#include "core/base/errors.hpp"
#include "core/model/join_detect.hpp"
#include "core/model/topology.hpp"
#include "core/solve/constraint_solver.hpp"

namespace pw {

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
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

}  // namespace

double joinTolerance(const Document& doc) { return 1e-6 * modelSize(doc) + 1e-12; }

std::string describeJoin(const Document& doc, size_t j) {
    const Join& jn = doc.joins[j];
    return "join " + std::to_string(j) + " (" + joinSideName(jn, false) + " – " + joinSideName(jn, true) + ", " +
           std::string(continuityName(jn.continuity)) + ")";
}

void checkEditInvariants(const Document& before, const Document& after, bool detected) { checkJoins(before, after, detected); }

}  // namespace pw

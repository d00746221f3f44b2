// The sides of a fill whose two ends ask different tangent ratios (issue 40, item 2; DESIGN §14).
// At each hole corner the surroundings fix the ratio α of the fill's seam along each side; when a
// side's two ends disagree, α runs linearly from each end to their mean at the side's middle, the
// fill's other seam at each corner leans by β′ = α′/α (so the corner's twist stays one point) and
// the two halves lean by ±b at the middle (so they agree there). The identity
//   D_fill(t) = α(t)·D_surrounding(t) + β(t)·c′(t)
// is then degree 4 where the fill's rows are cubic: its middle coefficient is let go (the join is
// `fitted`) and the seam's measured angle, not exactness, is what holds it (kFittedJoinDegrees).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/model/document.hpp"
#include "core/ops/fill_hole.hpp"

namespace pw {
inline namespace ops {

// One side's α and lean: its first half walked from its start (hole corner k) to its middle, its
// second half walked from its end (hole corner k+1) back to its middle.
struct FittedSide {
    double start = 1.0, mid = 1.0, end = 1.0;
    std::array<double, 3> shearFirst{}, shearSecond{};  // β in Bernstein form along each half as walked
};

// Whether a side's two ends ({at its start, at its end}) ask different ratios.
bool ratiosDisagree(const std::array<double, 2>& r);

// The sides, as numbered when given (`given[k]`: the given number of the loop's side k), whose two
// ends ask for different ratios, with their edges and ratios; "" when none does.
std::string ratioMismatch(const std::vector<std::optional<std::array<double, 2>>>& ratios, const std::vector<size_t>& given,
                          const std::vector<HoleSide>& sides);

// From the ratios each side's ends ask for ({at its start, at its end}), in the loop's order.
std::vector<FittedSide> fitSides(const std::vector<std::array<double, 2>>& ratios);

// The fill's row beside a half side walked from its hole corner: `edge` its points, `row` the
// surrounding's row beside them, α from a0 (at the corner) to a1 (at the middle), β as `shear`.
// The identity's coefficients 0, 1, 3 and 4 are met exactly.
std::array<Vec3, 4> fittedRow(const std::array<Vec3, 4>& edge, const std::array<Vec3, 4>& row, double a0, double a1,
                              const std::array<double, 3>& shear);

// The fitted G1 join of the surrounding's edge (patch, edge; `walkedReversed` when the half side
// was walked from A's point 3) to the fill's edge, α and β as walked from the hole corner.
Join fittedJoin(const Document& doc, uint32_t patch, Edge edge, bool walkedReversed, uint32_t fill, Edge fillEdge, double a0, double a1,
                const std::array<double, 3>& shear);

// The largest measured normal angle of the fitted joins (of `only`, when given), 0 when none.
double worstFittedAngle(const Document& doc, const std::vector<size_t>& only = {});

// The fitted joins (of `only`, when given) whose measured normal angle exceeds kFittedJoinDegrees,
// described with their angles ("join 12 (…) at 0.14°"); "" when none does.
std::string fittedJoinsOutOfTolerance(const Document& doc, const std::vector<size_t>& only = {});

// What an edit from `before` to `after` may not do to the fitted joins (of `only`, when given):
// take one past kFittedJoinDegrees, unless `wasWorst` (their worst angle before; measured from
// `before` when negative) was past it already and the worst gets no worse. The joins it leaves
// past, described as fittedJoinsOutOfTolerance does; "" when the edit may stand.
std::string fittedJoinsWorsened(const Document& before, const Document& after, const std::vector<size_t>& only = {},
                                double wasWorst = -1.0);

}  // namespace ops
}  // namespace pw

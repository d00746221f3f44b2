// The curve sides of a fill (core/ops/fill_hole): a curve of one cubic segment that the fill's
// patches share their edge with, split at its middle; refused where the split would cut it loose
// from something else; after a 2×2 split of the fill, the curve takes the fill's split edges.
#pragma once

#include <cstdint>
#include <string>

#include "core/model/document.hpp"

namespace pw {
inline namespace ops {

// The curve c when it is one polynomial cubic segment, not closed (`side` names what it would be
// in the error: "a fill's side"); else EditError.
const BezierCurve& sideCurve(const Document& d, int32_t c, const std::string& side);

// EditError when splitting curve c would cut it loose from a live construction made from it, or
// from an item or another curve sharing its inner points.
void checkCurveSplittable(const Document& d, int32_t c);

// After the fill's patches (from `first` on) were split, curve c takes their edges along it as
// its segments, so the fill shares its points again.
void curveOntoSplitFill(Document& d, uint32_t c, uint32_t first);

}  // namespace ops
}  // namespace pw

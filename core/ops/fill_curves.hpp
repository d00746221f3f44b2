// The curve sides of a fill (core/ops/fill_hole): a curve of one cubic segment that the fill's
// patches share their edge with, split at its middle; refused where the split would cut it loose
// from something else.
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

}  // namespace ops
}  // namespace pw

// Inserting and deleting points of a curve (issue 39), keeping its shape where that is possible:
// insertCurvePoint() splits a segment at a parameter by de Casteljau (homogeneous, so rational
// curves too), which does not change the curve at all; removeCurvePoint() merges the two segments
// that meet at an on-curve point into one cubic whose ends and end tangent directions are theirs,
// which gives back exactly the segment a split made (and a close cubic otherwise).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/model/document.hpp"

namespace pw {
inline namespace construct {

// Splits curve c at parameter t (segment floor(t), at its fraction; 0 < t < segments, not at a
// segment end): one more segment, its inner points new pool points (the old ones, which a patch
// or a surface may share, stay where they are; compactPool() drops them if no one's). EditError outside.
void insertCurvePoint(Document& doc, uint32_t c, double t);
// Removes on-curve point k (the end of segment k - 1, 0 < k < segments; any k of a closed curve of
// 2 segments or more), merging its two segments into new inner points. The five pool points it
// drops are no longer the curve's (compactPool() removes them when nothing else uses them). EditError when there is
// no such point or the curve would have no segment left.
void removeCurvePoint(Document& doc, uint32_t c, size_t k);

}  // namespace construct
}  // namespace pw

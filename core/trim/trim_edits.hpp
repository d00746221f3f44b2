// What removing, copying or flipping items does to trims and live curves (issue 64): references
// renumbered, links to a removed item detached (baked) rather than pointed at another item.
#pragma once

#include "core/model/document.hpp"

namespace pw {
inline namespace trim {

// Before curve c is erased: loops and curve links that use it are detached; later curves' numbers
// go down by one.
void dropCurveFromTrims(Document& doc, uint32_t c);
// Before patch p (or net s) is erased: curve links on it are detached; later numbers go down by one.
void dropSurfaceFromTrims(Document& doc, const SurfaceRef& s);
// A patch's u reversed (flip): its loops mirrored u -> 1 - u and turned round (orientation kept).
void flipTrimsU(std::vector<TrimLoop>& loops);
// A copy's loops keep their shape but not their link (the curve lies on the original).
void detachTrims(std::vector<TrimLoop>& loops);
// True when any loop or curve of the document is live.
bool hasLiveTrims(const Document& doc);

}  // namespace trim
}  // namespace pw

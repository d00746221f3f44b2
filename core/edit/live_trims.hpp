// Live trims (issue 64): curves made by `intersect` and `project` are made again from their
// surfaces, and trim loops made from curves are laid again on their surfaces, after every edit and
// on every mouse move of a drag, until `bake` detaches them. A curve or loop whose inputs no longer
// give it keeps its last good shape and says why (its `error`, and a note).
#pragma once

#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace edit {

// Remakes every live curve (in order, so a projection of an intersection follows it) and every
// live loop. Returns notes for the status line.
std::vector<std::string> refreshTrims(Document& doc);

// A new curve of the document through the Bézier chain `bezier` (3n + 1 points; closed when the
// last equals the first), with new pool points; returns its number.
uint32_t appendCurve(Document& doc, const std::vector<Vec3>& bezier, bool closed, const std::string& name, std::optional<CurveLink> link);

// The largest distance between two surfaces along the trim edge that one curve cuts into both:
// for each pair of loops made from the same curve, measured at the curve's samples (`info`).
struct TrimEdgeGap {
    uint32_t curve = 0;
    SurfaceRef a, b;
    double gap = 0.0;
};
std::vector<TrimEdgeGap> trimEdgeGaps(const Document& doc);

}  // namespace edit
}  // namespace pw

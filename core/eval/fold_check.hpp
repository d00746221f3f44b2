// Whether a patch is folded or collapsed (issue 40's invariant: a surface never satisfies a
// constraint by folding or collapsing). A patch is tessellated on a regular grid, as a level-N
// export would be, and each triangle whose geometric normal faces against the surface normals at
// its corners counts as turned over; a corner where the surface's tangent plane vanishes (du × dv
// = 0: a tangent row collapsed onto its edge) counts as collapsed. Edits compare these counts
// before and after: an edit may keep a degenerate corner the model already had (a sphere's pole),
// never make a new one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace eval {

struct PatchShape {
    int invertedTriangles = 0;  // of the 2·level² grid triangles
    int collapsedCorners = 0;   // of the four corners
    bool operator==(const PatchShape&) const = default;
};

// Patch p of `doc` on a level × level grid (default: a level-16 export's triangles).
PatchShape patchShape(const Document& doc, uint32_t p, int level = 16);

// Bézier triangle t of `doc` on its level-n grid (n² triangles): those turned over against the
// normals at their corners (collapsedCorners stays 0).
PatchShape triangleShape(const Document& doc, uint32_t t, int level = 16);

// True when `after` is worse than `before`: more triangles turned over or more corners collapsed.
inline bool foldedFurther(const PatchShape& before, const PatchShape& after) {
    return after.invertedTriangles > before.invertedTriangles || after.collapsedCorners > before.collapsedCorners;
}

// The first patch (then Bézier triangle) an edit folded: patch p of `before` and of `after` are the
// same patch (the operations that join keep the patches' order); of those whose shape changed, the
// first that foldedFurther. "" when none, else "patch 3 (5 of its triangles turned over)".
std::string foldMadeBy(const Document& before, const Document& after);

// foldMadeBy over the patches `changed` marks (patch p of `before` and of `after` are the same
// patch; Bézier triangles are not looked at), for an edit that already knows them; `turnedOnly`: only turned-over triangles count, not
// collapsed corners; `foldedPatch`, when given, receives the patch named. Both leave out a patch
// that only moved as a rigid body, was mirrored or scaled uniformly: its shape is the same.
std::string foldMadeIn(const Document& before, const Document& after, const std::vector<bool>& changed, bool turnedOnly = false,
                       int* foldedPatch = nullptr);

// The first new patch (then Bézier triangle) of `after` (those past `before`'s count: a loft's, a
// blend's, a fill's, a revolve's, a split's or a copy's) with a triangle turned over, where `before`
// had none turned over anywhere: a model without folds may gain none. A model that already had
// some may carry them into copies and pieces (mirror, duplicate, split of a folded import), so it
// is not checked. "" when none, else as foldMadeBy.
std::string newFoldIn(const Document& before, const Document& after);

}  // namespace eval
}  // namespace pw

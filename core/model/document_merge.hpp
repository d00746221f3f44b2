// Merging one document into another (File > Import, `import` in scripts): every kind of content
// comes along — patches, nets, Bézier triangles, curves and the joins between patches — with its
// own pool points, renumbered to sit after what is already there.
#pragma once

#include <cstdint>

#include "core/model/document.hpp"

namespace pw {
inline namespace model {

// Where the merged content landed in the target: [first, first + count) of each list.
struct MergedRange {
    uint32_t firstPoint = 0, pointCount = 0;
    uint32_t firstPatch = 0, patchCount = 0;
    uint32_t firstSurface = 0, surfaceCount = 0;
    uint32_t firstTriangle = 0, triangleCount = 0;
    uint32_t firstCurve = 0, curveCount = 0;
    uint32_t firstJoin = 0, joinCount = 0;
};

// Appends `from`'s points, patches, surfaces, triangles, curves and joins to `into` (indices
// renumbered; `into`'s settings, camera and name are kept). Returns where they went.
MergedRange mergeDocument(Document& into, const Document& from);

}  // namespace model
}  // namespace pw

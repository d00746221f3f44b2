// A tessellator's output as data: the tessellation coordinates (gl_TessCoord) of every primitive one
// device made for one (domain, partitioning, levels) set, in the order it emitted them, and the
// comparison of two such patterns. The Vulkan spec fixes the counts (tess_domain.hpp) but leaves
// where the short fractional segments go and how the rings are triangulated to the implementation:
// comparing patterns is how two GPUs' choices are shown side by side (`render --compare-device`).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/model/document.hpp"
#include "core/tess/tess_domain.hpp"

namespace pw {
inline namespace tess {

struct TessPattern {
    DomainKind kind = DomainKind::Quad;
    Spacing spacing = Spacing::Equal;
    DomainLevels levels;
    // gl_TessCoord.xy of each primitive's vertices, 3 a triangle (w = 1 - u - v on the triangle
    // domain) or 2 an isoline segment.
    std::vector<std::array<float, 2>> uv;

    int vertsPerPrimitive() const { return kind == DomainKind::Isoline ? 2 : 3; }
    size_t primitives() const { return uv.size() / size_t(vertsPerPrimitive()); }
    std::vector<std::array<float, 2>> distinctPoints() const;  // each tessellation coordinate once (sorted)
    // The same (domain, partitioning, levels) set, whatever the points.
    bool sameSet(DomainKind k, Spacing s, const DomainLevels& l) const { return kind == k && spacing == s && levels == l; }
};

// Where a tessellation coordinate is drawn (x right, y up): the unit square for quads and isolines
// (u right, v up), the equilateral triangle for triangles with the corner u = 1 bottom left, v = 1
// bottom right and w = 1 on top.
std::array<float, 2> domainPicturePoint(DomainKind kind, std::array<float, 2> uv);

// How two patterns of the same set differ. Points closer than the tolerance are the same point;
// a primitive matches one of the other pattern with the same points (in any order; as many times
// as it occurs there).
struct PatternDiff {
    std::vector<uint8_t> onlyInA, onlyInB;  // per primitive: 1 where the other pattern has no such primitive
    size_t primitivesOnlyA = 0, primitivesOnlyB = 0;
    size_t pointsOnlyA = 0, pointsOnlyB = 0;  // distinct points the other pattern lacks
    size_t windingFlips = 0;                  // matched triangles (of some area) the two emitted with opposite winding
    bool sameOrder = false;                   // the same primitives emitted in the same order
    bool identical() const { return primitivesOnlyA == 0 && primitivesOnlyB == 0 && pointsOnlyA == 0 && pointsOnlyB == 0; }
};
PatternDiff comparePatterns(const TessPattern& a, const TessPattern& b, float tolerance = 1e-5f);

}  // namespace tess
}  // namespace pw

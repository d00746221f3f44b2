// Live symmetry (Blender's mesh symmetry, Rhino's Symmetry): with it on, every transform of
// control points moves each point's mirror partner to the mirror image across a plane normal to X,
// Y or Z, and the moved points that lie on the plane stay on it. The plane goes through the 3D
// cursor when symmetry is turned on (the `symmetry` command), like `mirror`'s.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace select {

struct Symmetry {
    int axis = -1;  // -1 off, 0..2 the plane x, y or z = offset
    double offset = 0.0;
    bool on() const { return axis >= 0; }
    bool operator==(const Symmetry&) const = default;
};
std::string symmetryName(const Symmetry& s);  // "off", "X", "Y", "Z"

// What a transform of `moved` drives under s: each moved point's partner (a point some item uses,
// at its mirror image to 1e-6 of the model size, not moved itself) and the moved points on the
// plane.
struct SymmetryPairs {
    std::vector<std::pair<uint32_t, uint32_t>> partners;  // (moved point, its mirror)
    std::vector<uint32_t> onPlane;
    // The moved points and their own partners, sorted: what the solver must hold fixed.
    std::vector<uint32_t> driven(const std::vector<uint32_t>& moved) const;
};
SymmetryPairs symmetryPairs(const Document& doc, const std::vector<uint32_t>& moved, const Symmetry& s);

// The patch edge whose points are the mirror images of edge e of patch p under s (a point on the
// plane is its own image), for joins made under live symmetry; none when no patch has such an edge
// or the edge is its own image.
std::optional<std::pair<uint32_t, Edge>> mirrorEdge(const Document& doc, uint32_t p, Edge e, const Symmetry& s);

// After the moved points took their new positions: the ones on the plane back onto it, each
// partner at its point's mirror image.
void applySymmetry(std::vector<Vec3>& points, const SymmetryPairs& pairs, const Symmetry& s);

}  // namespace select
}  // namespace pw

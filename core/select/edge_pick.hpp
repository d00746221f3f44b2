// Picking a patch's boundary edge under the mouse, pure (no Vulkan): what the join tool hovers and
// clicks (ui/editor/viewport.cpp). An edge is a boundary curve of a Bézier patch that is not joined yet;
// the nearest one on screen wins, and among edges that lie on top of each other (two patches
// placed edge to edge) the one of the patch under the mouse.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/model/camera_math.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace select {

struct PatchEdge {
    uint32_t patch = 0;
    Edge edge = Edge::U0;
    bool operator==(const PatchEdge&) const = default;
};

// Points along boundary curve e of patch p (any basis, rational where weighted), n segments, from
// k = 0 to k = 3; for a triangle's edge (Edge::T0..T2) the cubic of triangle p's edge points.
// Empty when the patch or triangle does not exist.
std::vector<Vec3> boundaryCurve(const Document& doc, uint32_t p, Edge e, int n = 24);

// The open (not joined) boundary edge of a shown Bézier patch whose curve passes nearest pixel
// (x, y) of a width x height view, within radiusPx; patch `skipPatch` is left out (the first pick
// of a join). nullopt when none is that near.
std::optional<PatchEdge> pickBoundaryEdge(const Document& doc, const Camera& cam, double x, double y, int width, int height,
                                          double radiusPx, int skipPatch = -1);

// "3:u1", the form the `join` command reads.
std::string patchEdgeName(const PatchEdge& e);

}  // namespace select
}  // namespace pw

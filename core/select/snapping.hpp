// What a move snaps to while Ctrl is held (DESIGN §6): the grid, or the nearest control point,
// boundary edge or surface of the items the move does not touch, under the mouse. Pure (no window):
// the drag controller (core/edit/drag_controller.hpp) asks it once per mouse event.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace select {

enum class SnapTarget { Grid, Points, Edges, Surfaces };
std::string_view snapTargetName(SnapTarget t);  // "grid", "points", "edges", "surfaces"
std::optional<SnapTarget> parseSnapTarget(std::string_view name);

// The world point under the mouse at (x, y) (pixels of a width x height view of `cam`) that a move
// snaps to, for the targets other than the grid:
//   Points:   the nearest used pool point within `radiusPx` of the mouse;
//   Edges:    the nearest point of a window's or triangle's boundary curve within `radiusPx`;
//   Surfaces: where the mouse ray first meets a surface.
// Items with a point in `moved` (a pool mask) are left out, and so are moved points and hidden items. nullopt:
// nothing there, the move is not snapped.
std::optional<Vec3> snapPoint(const Document& doc, const std::vector<bool>& moved, SnapTarget target, const Camera& cam, int width,
                              int height, double x, double y, double radiusPx = 12.0);

}  // namespace select
}  // namespace pw

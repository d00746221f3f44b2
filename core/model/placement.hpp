// Where new geometry goes: at the 3D cursor, but never inside what is already there (issue 19:
// Add and Import put new items at the origin, inside the model).
#pragma once

#include <cstddef>

#include "core/model/document.hpp"

namespace pw {
inline namespace model {

// The points from `firstNewPoint` on belong to items just added. When their bounding box overlaps
// the box of any older patch, net, triangle or curve, they move along +X (the model's "right")
// until they are clear, with a gap of a tenth of their own width. Returns the move (0 when none).
Vec3 moveClearOfExisting(Document& doc, size_t firstNewPoint);

}  // namespace model
}  // namespace pw

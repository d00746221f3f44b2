// Mirror (issue 19): a copy of the selected patches, Bézier triangles and curves reflected across
// the plane normal to X, Y or Z through a point (the 3D cursor). Points on the plane are shared, so
// the copy meets the original there; the copies' u direction is reversed so their normals stay
// outward; joins between mirrored patches are copied, and the seams on the plane are joined — C1
// where the original's cross-boundary rows are perpendicular to the plane (the mirror is then
// C1), else C0.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace ops {

struct MirrorResult {
    std::vector<uint32_t> patches, triangles, curves;  // the new items
    std::vector<uint32_t> points;                      // every point of the new items (sorted)
    size_t seamJoins = 0;                              // joins made on the plane
};

// The visible items of `items` (patches, triangles or curves) whose points are all in `selected`
// (a sorted pool list): what mirror, and flip, take from a selection of points.
template <class Item>
std::vector<uint32_t> wholeItems(const std::vector<Item>& items, const std::vector<uint32_t>& selected) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < items.size(); ++i)
        if (!items[i].hidden && std::all_of(items[i].idx.begin(), items[i].idx.end(),
                                            [&](uint32_t p) { return std::binary_search(selected.begin(), selected.end(), p); }))
            out.push_back(i);
    return out;
}

// Mirrors the items whose points are all in `selected` (a sorted pool list). `axis` 0, 1, 2;
// `planeAt` the plane's coordinate on that axis. Throws EditError when no whole item is selected.
MirrorResult mirrorItems(Document& doc, const std::vector<uint32_t>& selected, int axis, double planeAt);

}  // namespace ops
}  // namespace pw

// A trimmed window's segments per cell, for the fragment shader (issue 64's 1.3× benchmark): the
// window's (u, v) square cut into kTrimCells x kTrimCells cells (core/gpu/trim_math.h), each with
// only the segments a ray towards +u from one of its points may cross. A segment wholly to the
// right of a cell and spanning its whole v range is crossed from every point of it: it is counted
// into the cell's parity instead of listed. A cell with no segment left is settled by its parity
// alone (most cells away from a curve), so a fragment tests a few segments, not the window's all.
#pragma once

#include <cstdint>
#include <vector>

#include "core/trim/trim_loops.hpp"

namespace pw {
inline namespace trim {

struct TrimCell {
    uint32_t parity = 0;             // the window's base parity plus the crossings counted in
    std::vector<uint32_t> segments;  // indices into WindowTrim::segments, in its order (lowest v first)
};
// Row-major, v rows of u cells; empty when the window has no kTrimTest.
std::vector<TrimCell> trimCells(const WindowTrim& w);
// Whether point uv of the window is kept, from its cell (the same answer as trimKeeps on all the
// window's segments).
bool cellKeeps(const WindowTrim& w, const std::vector<TrimCell>& cells, glm::dvec2 uv);

}  // namespace trim
}  // namespace pw

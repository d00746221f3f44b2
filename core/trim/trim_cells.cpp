#include "core/trim/trim_cells.hpp"

#include <algorithm>

#include "core/gpu/trim_math.h"

namespace pw {
inline namespace trim {

namespace {

constexpr uint32_t kCells = gpu::kTrimCells;

uint32_t cellOf(double x) { return std::min(uint32_t(std::clamp(x, 0.0, 1.0) * kCells), kCells - 1); }

}  // namespace

std::vector<TrimCell> trimCells(const WindowTrim& w) {
    if (!(w.flags & gpu::kTrimTest)) return {};
    std::vector<TrimCell> cells(size_t(kCells) * kCells);
    const uint32_t base = (w.flags & gpu::kTrimBaseKept) ? 1u : 0u;
    for (TrimCell& cell : cells) cell.parity = base;
    // Segment by segment (so that each cell's list keeps the window's order, lowest v first), over
    // the rows its v range reaches and the cells left of its right end only, one row and column of
    // margin beyond; the exact tests decide.
    for (uint32_t s = 0; s < w.segments.size(); ++s) {
        const auto& b = w.segments[s].b;
        const double vmin = std::min(b[0].y, b[3].y), vmax = std::max(b[0].y, b[3].y);
        const double umin = std::min({b[0].x, b[1].x, b[2].x, b[3].x}), umax = std::max({b[0].x, b[1].x, b[2].x, b[3].x});
        const uint32_t iLo = cellOf(vmin) > 0 ? cellOf(vmin) - 1 : 0, iHi = std::min(cellOf(vmax) + 1, kCells - 1);
        const uint32_t jHi = std::min(cellOf(umax) + 1, kCells - 1);
        for (uint32_t i = iLo; i <= iHi; ++i)
            for (uint32_t j = 0; j <= jHi; ++j) {
                const double u0 = double(j) / kCells, u1 = double(j + 1) / kCells, v0 = double(i) / kCells, v1 = double(i + 1) / kCells;
                // The cell as closed (its last row and column hold v = 1 and u = 1): a segment's v range is [vmin, vmax).
                if (vmin > v1 || vmax <= v0 || umax < u0) continue;  // no ray from the cell meets it
                TrimCell& cell = cells[size_t(i) * kCells + j];
                if (umin > u1 && vmin <= v0 && vmax > v1)
                    ++cell.parity;  // every ray from the cell crosses it
                else
                    cell.segments.push_back(s);
            }
    }
    return cells;
}

bool cellKeeps(const WindowTrim& w, const std::vector<TrimCell>& cells, glm::dvec2 uv) {
    const TrimCell& cell = cells[size_t(cellOf(uv.y)) * kCells + cellOf(uv.x)];
    uint32_t crossings = cell.parity;
    for (uint32_t s : cell.segments) {
        const auto& b = w.segments[s].b;
        crossings += gpu::trimCrossing<double>(uv, b[0], b[1], b[2], b[3]);
    }
    return (crossings & 1u) != 0u;
}

}  // namespace trim
}  // namespace pw

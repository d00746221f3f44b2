// The notes' rounding table as a slide (`patchwork rounding`): for each partitioning, the segments
// one edge gets at each requested level and, for the fractional ones, how far the two short
// segments have slid (the notes' (f - 3) / (5 - 3) * 100), from core/tess/tess_domain.hpp's rules
// (the ones the render tests hold equal to the GPU's counts). SVG, PDF or PNG.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/tess/tess_domain.hpp"
#include "render/figures/cairo_canvas.hpp"

namespace pw::render {
inline namespace figures {

// "integer [1..64]", "fractional_odd [1, 3, ..., 63]": the row's name (the notes' D3D names) and
// the segment counts it allows.
std::string roundingRowTitle(Spacing spacing);
// "5" or "5 (13 %)".
std::string roundingCellText(const RoundingCell& cell);
// The table as aligned text lines: a header of levels, then a line per partitioning.
std::vector<std::string> roundingTableLines(const std::vector<RoundingRow>& rows);

std::string roundingTableFigure(std::optional<VectorFormat> format, const std::filesystem::path& output, uint32_t width, uint32_t height,
                                const std::vector<RoundingRow>& rows);

}  // namespace figures
}  // namespace pw::render

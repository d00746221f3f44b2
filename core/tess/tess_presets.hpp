// Teaching presets: the tessellation factor sets the lecture notes show (shared/seeds: quad and
// triangle domains, the fractional example under integer and fractional_odd spacing), the notes'
// bicubic Bézier patch with its 16 control points, and their distance-based level formula.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/model/document.hpp"
#include "core/tess/tess_domain.hpp"

namespace pw {
inline namespace tess {

struct TessPreset {
    std::string name;   // id for the command line: "quad-1_2_3_4-4_4", "tri-4.9_4.5_4.1-4.4-fractional_odd"
    std::string label;  // as the notes write it: "quad {1,2,3,4 | 4,4}"
    DomainKind kind = DomainKind::Quad;
    DomainLevels levels;
    Spacing spacing = Spacing::Equal;
    std::string note;  // one line for the tooltip / figure caption
};

// Every factor-set preset, quad first, then triangle (the AMD tutorial's levels 1.0, 1.5 and 3.0
// under fractional_odd among them), then the fractional example (twice: integer and fractional_odd).
const std::vector<TessPreset>& tessPresets();
const TessPreset* findTessPreset(std::string_view name);

// The bicubic Bézier patch of the notes (16 control points, rows z = +15 .. -15) as a document,
// viewed from above at an angle, y up. Version 1: the first notes' points, tessellated at 25;
// version 2: the second notes' (the raised point at y = 30, corners at -20 and +20), at 15 under
// integer partitioning like their hull shader. Other versions throw std::invalid_argument.
inline constexpr int kNotesPatchVersions = 2;
Document notesBezierPatch(int version = 1);

// The notes' distance formula, level = 64 * saturate((d1 - d) / (d1 - d0)) with d0 = 20 and d1 =
// 100, applied to `doc`'s settings (adaptive distance mode). The formula itself, for a distance:
float notesDistanceLevel(float distance, float d0 = 20.0f, float d1 = 100.0f);
// The first notes' distance formula: 64 saturate((100 - d) / (100 - 20)), level 0 culling the patch.
// `fromCentre` (the notes' own): one level per patch from the centre of its control points, so
// neighbours at different distances disagree on their shared edge and cracks open; otherwise each
// edge from its midpoint (crack-free, the same formula).
void applyNotesDistanceFormula(TessSettings& t, bool fromCentre = true);
// The terrain notes' (Direct3D 12 demo): edges from their midpoints, inner levels from the patch
// centre, level 2^lerp(20, 4, saturate((d - 10) / (200 - 10))) (clamped to 64 by the tessellator:
// 64 up to d = 176.25, then down to 16 at 200), fractional_even; the height map moves the vertices only.
void applyNotesTerrainFormula(TessSettings& t);

}  // namespace tess
}  // namespace pw

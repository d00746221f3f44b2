// The settings of an export, whatever its format: the tessellation level (glTF, OBJ), the grouping
// into primitives and the control cage (glTF), and export as displayed (glTF, OBJ). STEP is exact
// and takes none of them. Kept in a glTF's extras so a re-export writes the same file.
#pragma once

#include <array>
#include <cstdint>

#include "core/mesh/mesh_split.hpp"

namespace pw {
inline namespace io {

struct ExportOptions {
    int level = 0;                                     // tessellation level; 0 = the document's (max of its uniform levels, rounded up)
    MeshGrouping primitives = MeshGrouping::Surfaces;  // one primitive per connected surface, patch, or one
    bool cage = false;                                 // add the control cage (LINES, its own node)
    // The surface as the GPU tessellated it for the document's view (per-edge, adaptive levels;
    // render/surface_capture), passed in as `displayed`; `level` then only samples the curves.
    bool asDisplayed = false;
    std::array<int, 2> viewport{0, 0};  // as displayed: the view's size in pixels (screen-space levels)
    // As displayed: the patches (windows and triangles) the view culled and the file therefore
    // lacks (off screen, facing away), as the GPU counted them; -1 where the device cannot count.
    int64_t culledPatches = -1;
    bool operator==(const ExportOptions&) const = default;
};

}  // namespace io
}  // namespace pw

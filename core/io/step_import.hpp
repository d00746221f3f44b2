// Import of CAD surfaces from STEP (.step, .stp) and IGES (.iges, .igs) through OpenCASCADE: every
// face whose surface is a polynomial B-spline or Bézier surface of degree <= 3 in both directions,
// untrimmed (or trimmed only to an iso-parametric rectangle), becomes Bézier patches by knot
// insertion (exact; degree raised to 3 where lower). Boundaries that meet (within 1e-9 of the
// model's size) share pool points and get joins detected as for .bpt. Every other face is skipped
// with a note naming it and why; a file with no usable face is refused (InputError).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {

struct CadImportReport {
    size_t faces = 0;                // faces in the file
    size_t importedFaces = 0;        // of them, turned into patches
    std::vector<std::string> notes;  // one per skipped face: "face 3: trimmed by a curve (...)"
};

Document importCadSurfaces(const std::filesystem::path& path, CadImportReport* report = nullptr);

}  // namespace pw

// Import of CAD surfaces from STEP (.step, .stp) and IGES (.iges, .igs) through OpenCASCADE: every
// face whose surface is a B-spline or Bézier surface (rational or not) of degree <= 3 in both
// directions, or one OpenCASCADE converts to such a B-spline (planes, cylinders, cones, spheres,
// tori, surfaces of revolution and extrusion, offsets), untrimmed or trimmed only to an
// iso-parametric rectangle, becomes Bézier patches by knot insertion (exact; degree raised to 3
// where lower). Boundaries that meet (within 1e-9 of the
// model's size) share pool points and get joins detected as for .bpt. Every other face is skipped
// with a note naming it and why; a file with no usable face is refused (InputError).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace io {

struct CadImportReport {
    size_t faces = 0;                  // faces in the file
    size_t importedFaces = 0;          // of them, turned into patches
    std::vector<std::string> notes;    // one per skipped face ("face 3: trimmed by a curve (...)"), and the unit's when not the file's own
    double area = 0, skippedArea = 0;  // of all faces and of the skipped ones, in the file's units (0 when none was skipped)

    // "skipped 2 of 26 faces, 3.1 % of the area" (empty when every face came in).
    std::string skippedSummary() const;
};

Document importCadSurfaces(const std::filesystem::path& path, CadImportReport* report = nullptr);

// The processor time OpenCASCADE may take in a child process: PATCHWORK_CAD_SECONDS when set and not empty
// (at least 1 ms), else `fallback` (imports: limits::kMaxCadImportSeconds; exports take longer).
double cadSecondsLimit(double fallback);

// A STEP file that names no valid length unit (none, several different ones, or one Patchwork does
// not know) is refused, since millimetres cannot be told from metres (issue 73: such files were
// read as metres, an mm part 1 000× too large). With a unit assumed here (the commands' `--unit`)
// it is read in that unit and a note says so. Process-wide; nullopt (the default) refuses.
void assumeCadUnit(std::optional<LengthUnit> unit);
// How far a face of degree above 3 may move when it is approximated by bicubic patches, in the
// file's units (the commands' `--tolerance`); nullopt (the default): 1e-4 of the model's size.
// Each approximated face gets a note with its measured deviation. Process-wide.
void setCadTolerance(std::optional<double> tolerance);

}  // namespace io
}  // namespace pw

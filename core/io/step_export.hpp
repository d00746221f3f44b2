// STEP export (AP214 or AP242), and IGES, through OpenCASCADE: exact surfaces, sewn into shells.
//   - every Bézier patch: a bicubic B-spline face (knots {0, 1});
//   - every spline net: one B-spline face for the whole net (its Bézier windows joined, then every
//     interior knot removed that the surface allows: a uniform B-spline net comes back as itself);
//   - every Bézier triangle: a bicubic face with a collapsed edge (exact, see
//     triangleAsCollapsedQuad) — STEP has no triangular B-spline surface, and CAD systems expect
//     degenerate edges at poles anyway;
//   - faces sewn (shared boundaries become shared edges) into shells; a closed shell becomes a solid
//     (MANIFOLD_SOLID_BREP, faces outwards), an open one stays a shell; several pieces go in one
//     compound. Curves are not written.
//   - +Z up (a Y-up document turned a quarter about X, exactly), lengths in metres (the document's
//     unit), the product named after the document, each face after its patch, net or triangle.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "core/model/document.hpp"

namespace pw {
inline namespace io {

enum class StepSchema { AP214, AP242 };

struct StepExportOptions {
    StepSchema schema = StepSchema::AP214;
    // The product's (and IGES sender's) name; empty: the document's, or "Patchwork". exportStep
    // names an untitled document after the file ("ball.step": "ball").
    std::string product;
};

struct StepExportStats {
    size_t faces = 0, shells = 0;
    size_t solids = 0;           // closed shells written as solids
    size_t sharedEdges = 0;      // edges sewn between two faces
    size_t freeEdges = 0;        // boundary edges (open surfaces)
    size_t degenerateEdges = 0;  // collapsed edges (poles, triangles' collapsed side)
    size_t bytes = 0;
    size_t parts = 0;  // products: 1, or one per sewn piece when the user named a part (STEP only)
};

// The file's text. Throws OutputError-free std::runtime_error when OCCT fails.
std::string exportStepText(const Document& doc, const StepExportOptions& options, StepExportStats* stats = nullptr);
// The same shapes as IGES 5.3 (B-rep mode: B-spline surface faces, shells and solids), in the
// document's unit, its name as the sender's; IGES has no place for the faces' names.
std::string exportIgesText(const Document& doc, StepExportStats* stats = nullptr, const std::string& product = {});

// Atomic write (.step or .stp; .iges or .igs as IGES). Throws OutputError naming the path.
StepExportStats exportStep(const Document& doc, const std::filesystem::path& path, const StepExportOptions& options = {});

}  // namespace io
}  // namespace pw

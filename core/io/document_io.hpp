// Load and save by file extension, through the format table (core/io/formats.hpp): .patchwork
// (native), .bpt (tea set), .gltf/.glb (export, and import of Patchwork glTF files whose extras
// carry the patches), .obj (export), .step/.stp (export and import of exact surfaces), .iges/.igs
// (import). Saves are atomic.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/io/gltf_export.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace io {

// What a load learnt beside the document.
struct LoadReport {
    std::optional<ExportOptions> exportOptions;  // a Patchwork glTF's own export options
    std::vector<std::string> notes;              // what was skipped (STEP/IGES faces) and why
    bool incomplete = false;                     // something of the file was left out (faces skipped)
};

// A file that comes in incomplete (STEP/IGES faces skipped) is refused with InputError naming what
// was left out, unless `partial` (the command line's --partial, the editor's open with its notice).
Document loadDocument(const std::filesystem::path& path, LoadReport* report = nullptr, bool partial = false);
// A glTF or OBJ with gltf.asDisplayed writes `displayed` (the GPU's tessellation, captured by the
// caller with render/; consumed); without it such a save is refused (OutputError naming the path).
void saveDocument(const Document& doc, const std::filesystem::path& path, const ExportOptions& gltf = {},
                  TriangleMesh* displayed = nullptr);

// The extensions saveDocument writes (".patchwork, .bpt, ... or .stp"), and whether it writes `path`'s.
std::string savableExtensions();
bool canSave(const std::filesystem::path& path);
// Whether saveDocument writes `path` as a tessellated mesh (.gltf, .glb, .obj): the formats an
// export as displayed applies to.
bool isMeshFormat(const std::filesystem::path& path);

// One status line for what a load skipped ("2 faces not imported; face 3 skipped: ..."), or "" when
// nothing was.
std::string skippedSummary(const std::vector<std::string>& notes);

// Formats that keep everything a document holds (patches, nets, triangles, curves, joins):
// .patchwork, .gltf and .glb. Writing another (.bpt) is an export: Save asks for a name instead.
bool saveKeepsEverything(const std::filesystem::path& path);

// The built-in teapot (data/teapot.bpt compiled into the binary), joins detected.
Document builtinTeapot();

}  // namespace io
}  // namespace pw

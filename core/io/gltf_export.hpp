// glTF 2.0 export (.gltf with an embedded buffer, or .glb) through tinygltf (DESIGN §5).
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>
#include <optional>

#include "core/io/export_options.hpp"
#include "core/mesh/mesh_split.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace io {

// The options an export used, kept in asset.extras.patchworkExport ({"level", "primitives",
// "cage"}, and "asDisplayed": true with "viewport": [w, h] when it was) so a re-export without flags writes the same file. nullopt when the
// extras have none; InputError naming `field` when they are malformed.
std::optional<ExportOptions> exportOptionsFromJson(const nlohmann::json& j, const std::string& source);

// The file's bytes: binary (.glb) or JSON (.gltf, buffer as a data URI). The editable document
// (documentToJson) is stored in the asset's extras under "patchwork".
std::string exportGltfBytes(const Document& doc, bool binary, const ExportOptions& options);

// Atomic write; the format from the extension (.glb or .gltf). Throws OutputError / InputError.
void exportGltf(const Document& doc, const std::filesystem::path& path, const ExportOptions& options);

// What an export wrote (for the command line and the benchmark).
struct GltfExportStats {
    int level = 0;  // the tessellation level used
    size_t triangles = 0;
    size_t vertices = 0;       // of the surface mesh (welded within each primitive)
    size_t primitives = 0;     // surface primitives
    size_t openSurfaces = 0;   // of them, open (double-sided)
    size_t cageSegments = 0;   // 0 without the cage
    size_t curveSegments = 0;  // line-strip segments of the document's Bézier curves
    size_t bytes = 0;          // size of the file
};

// The level an export uses: `requested` if > 0, else the document's max(outer, inner) rounded
// up; clamped to [1, limits::kMaxExportLevel].
int resolveExportLevel(const Document& doc, int requested);

// Same as above, also reporting what was written. With options.asDisplayed, `displayed` is the
// surface mesh (consumed) instead of tessellateDocument at the level (std::invalid_argument if absent).
std::string exportGltfBytes(const Document& doc, bool binary, const ExportOptions& options, GltfExportStats* stats,
                            TriangleMesh* displayed = nullptr);
GltfExportStats exportGltfWithStats(const Document& doc, const std::filesystem::path& path, const ExportOptions& options,
                                    TriangleMesh* displayed = nullptr);

}  // namespace io
}  // namespace pw

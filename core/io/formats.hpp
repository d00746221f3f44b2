// The file formats, one row each: extensions, what Patchwork does with them (load, save, a
// tessellated mesh or exact surfaces), and the functions that do it. Loading and saving
// (core/io/document_io), the command line's help and checks (app/), the editor's dialogs and the
// `open`/`save-as`/`export` commands all read this table, so a new format is one row here plus its
// reader or writer in core/io/.
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/export_options.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace mesh {
struct TriangleMesh;
}  // namespace mesh
}  // namespace pw

namespace pw {
inline namespace io {

struct LoadReport;

struct FileFormat {
    std::string_view name;                     // "glTF 2.0 binary"
    std::vector<std::string_view> extensions;  // lower case, with the dot; the first is the usual one
    // Reopens as the patches it was written from (.patchwork, .bpt, Patchwork glTF): what
    // `patchwork edit` and Save As write. The others are imports (STEP, IGES) or exports (OBJ).
    bool document = false;
    bool mesh = false;             // a tessellated mesh: export level and "as displayed" apply
    bool keepsEverything = false;  // holds all a document can (nets, triangles, curves, joins): Save writes it without asking
    std::function<Document(const std::filesystem::path&, LoadReport*)> load;  // null: not read
    std::function<void(const Document&, const std::filesystem::path&, const ExportOptions&, TriangleMesh* displayed)>
        save;  // null: not written
};

// Every format, documents first.
std::span<const FileFormat> fileFormats();
// The format of `path` by its extension (any case), or nullptr.
const FileFormat* formatOf(const std::filesystem::path& path);

// Lists for help texts and messages: ".patchwork, .bpt, .gltf, .glb, .step, .stp, .iges or .igs".
// Export: what File > Export writes (meshes and exact surfaces, not the plain document formats).
// Exact: the exact-surface exports (STEP, IGES).
enum class FormatUse { Load, Save, Document, Mesh, Export, Exact };
std::string formatList(FormatUse use, std::string_view lastJoin = " or ");
bool formatDoes(const FileFormat& f, FormatUse use);

}  // namespace io
}  // namespace pw

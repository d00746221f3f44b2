// Loading and saving documents by file extension.
#include "core/document_io.hpp"

#include "core/bpt_format.hpp"
#include "core/embedded_data.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/gltf_import.hpp"
#include "core/obj_export.hpp"
#include "core/patchwork_format.hpp"
#include "core/step_export.hpp"
#include "core/step_import.hpp"

namespace pw {

namespace {
constexpr const char* kLoadable = ".patchwork, .bpt, .gltf, .glb, .step, .stp, .iges or .igs";
constexpr const char* kSavable = ".patchwork, .bpt, .gltf, .glb, .obj, .step or .stp";
}

Document loadDocument(const std::filesystem::path& path, LoadReport* report) {
    const std::string ext = lowerExtension(path);
    if (report) *report = LoadReport{};
    if (ext == ".patchwork") return parseDocument(readFileLimited(path), path.string());
    if (ext == ".bpt") return loadBpt(path);
    if (ext == ".gltf" || ext == ".glb") return importPatchworkGltf(path, report ? &report->exportOptions : nullptr);
    if (ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs") {
        CadImportReport cad;
        Document doc = importCadSurfaces(path, &cad);
        if (report) report->notes = std::move(cad.notes);
        return doc;
    }
    throw InputError(path.string(), "unknown file type '" + ext + "'; Patchwork reads " + kLoadable);
}

void saveDocument(const Document& doc, const std::filesystem::path& path, const GltfExportOptions& gltf, TriangleMesh* displayed) {
    const std::string ext = lowerExtension(path);
    if (isMeshFormat(path) && gltf.asDisplayed && !displayed)
        throw OutputError(path.string(), "the surface as displayed comes from the GPU; export it with `patchwork export "
                                         "--as-displayed` or the editor's File > Export As Displayed");
    if (ext == ".patchwork") {
        writeFileAtomic(path, serializeDocument(doc));
    } else if (ext == ".bpt") {
        std::string text;
        try {
            text = formatBpt(doc);
        } catch (const InputError& e) {
            // Not representable in the format: a problem with the output the user asked for.
            throw OutputError(path.string(), (e.field().empty() ? "" : e.field() + ": ") + e.reason());
        }
        writeFileAtomic(path, text);
    } else if (ext == ".gltf" || ext == ".glb") {
        exportGltfWithStats(doc, path, gltf, gltf.asDisplayed ? displayed : nullptr);
    } else if (ext == ".step" || ext == ".stp") {
        exportStep(doc, path);
    } else if (ext == ".obj") {
        exportObj(doc, path, gltf.level, gltf.asDisplayed ? displayed : nullptr);
    } else {
        throw OutputError(path.string(), "unknown file type '" + ext + "'; Patchwork writes " + kSavable);
    }
}

const char* savableExtensions() { return kSavable; }

bool isMeshFormat(const std::filesystem::path& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".gltf" || ext == ".glb" || ext == ".obj";
}

bool canSave(const std::filesystem::path& path) {
    const std::string ext = lowerExtension(path);
    for (const char* e : {".patchwork", ".bpt", ".gltf", ".glb", ".obj", ".step", ".stp"})
        if (ext == e) return true;
    return false;
}

std::string skippedSummary(const std::vector<std::string>& notes) {
    if (notes.empty()) return {};
    return std::to_string(notes.size()) + (notes.size() == 1 ? " face" : " faces") + " not imported; " + notes.front();
}

bool saveKeepsEverything(const std::filesystem::path& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".patchwork" || ext == ".gltf" || ext == ".glb";
}

Document builtinTeapot() {
    Document doc = parseBpt(embedded::teapotBpt, "teapot.bpt (built in)");
    doc.name = "teapot";
    return doc;
}

}  // namespace pw

#include "core/io/formats.hpp"

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/document_io.hpp"
#include "core/io/gltf_export.hpp"
#include "core/io/gltf_import.hpp"
#include "core/io/obj_export.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/io/step_export.hpp"
#include "core/io/step_import.hpp"

namespace pw {
inline namespace io {

namespace {

Document loadCad(const std::filesystem::path& path, LoadReport* report) {
    CadImportReport cad;
    Document doc = importCadSurfaces(path, &cad);
    if (report) {
        report->notes = std::move(cad.notes);
        report->incomplete = cad.importedFaces < cad.faces;
        if (const std::string summary = cad.skippedSummary(); !summary.empty()) report->notes.push_back(summary);
    }
    return doc;
}

Document loadGltf(const std::filesystem::path& path, LoadReport* report) {
    return importPatchworkGltf(path, report ? &report->exportOptions : nullptr);
}

void saveGltf(const Document& doc, const std::filesystem::path& path, const ExportOptions& options, TriangleMesh* displayed) {
    exportGltfWithStats(doc, path, options, options.asDisplayed ? displayed : nullptr);
}

std::vector<FileFormat> makeFormats() {
    std::vector<FileFormat> f;
    f.push_back({.name = "Patchwork document",
                 .extensions = {".patchwork"},
                 .document = true,
                 .keepsEverything = true,
                 .load = [](const std::filesystem::path& p, LoadReport*) { return parseDocument(readFileLimited(p), p.string()); },
                 .save =
                     [](const Document& d, const std::filesystem::path& p, const ExportOptions&, TriangleMesh*) {
                         const std::string text = serializeDocument(d);
                         // Read back, it must be the same document: written again, the same bytes.
                         writeFileAtomic(p, text, [&](const std::filesystem::path& staged) {
                             if (serializeDocument(parseDocument(readFileLimited(staged), p.string())) != text)
                                 throw InputError(p.string(), "it reads back as a different document");
                         });
                     }});
    f.push_back({.name = "Newell tea-set patches",
                 .extensions = {".bpt"},
                 .document = true,
                 .load = [](const std::filesystem::path& p, LoadReport* r) { return loadBpt(p, r ? &r->notes : nullptr); },
                 .save =
                     [](const Document& d, const std::filesystem::path& p, const ExportOptions&, TriangleMesh*) {
                         std::string text;
                         try {
                             text = formatBpt(d);
                         } catch (const InputError& e) {
                             // Not representable in the format: a problem with the output the user asked for.
                             throw OutputError(p.string(), (e.field().empty() ? "" : e.field() + ": ") + e.reason());
                         }
                         // Read back: the same patches (the reader orients them and detects the joins).
                         writeFileAtomic(p, text, [&](const std::filesystem::path& staged) {
                             if (parseBpt(readFileLimited(staged), p.string()).patches.size() != std::stoull(text))
                                 throw InputError(p.string(), "it reads back with a different number of patches");
                         });
                     }});
    f.push_back({.name = "glTF 2.0",
                 .extensions = {".gltf"},
                 .document = true,
                 .mesh = true,
                 .keepsEverything = true,
                 .load = loadGltf,
                 .save = saveGltf});
    f.push_back({.name = "glTF 2.0 binary",
                 .extensions = {".glb"},
                 .document = true,
                 .mesh = true,
                 .keepsEverything = true,
                 .load = loadGltf,
                 .save = saveGltf});
    f.push_back({.name = "Wavefront OBJ",
                 .extensions = {".obj"},
                 .mesh = true,
                 .save = [](const Document& d, const std::filesystem::path& p, const ExportOptions& o, TriangleMesh* displayed) {
                     exportObj(d, p, o.level, o.asDisplayed ? displayed : nullptr);
                 }});
    f.push_back({.name = "STEP",
                 .extensions = {".step", ".stp"},
                 .load = loadCad,
                 .save = [](const Document& d, const std::filesystem::path& p, const ExportOptions&, TriangleMesh*) { exportStep(d, p); }});
    f.push_back({.name = "IGES",
                 .extensions = {".iges", ".igs"},
                 .load = loadCad,
                 .save = [](const Document& d, const std::filesystem::path& p, const ExportOptions&, TriangleMesh*) { exportStep(d, p); }});
    return f;
}

}  // namespace

std::span<const FileFormat> fileFormats() {
    static const std::vector<FileFormat> formats = makeFormats();
    return formats;
}

const FileFormat* formatOf(const std::filesystem::path& path) {
    const std::string ext = lowerExtension(path);
    for (const FileFormat& f : fileFormats())
        for (std::string_view e : f.extensions)
            if (ext == e) return &f;
    return nullptr;
}

bool formatDoes(const FileFormat& f, FormatUse use) {
    switch (use) {
        case FormatUse::Load:
            return bool(f.load);
        case FormatUse::Save:
            return bool(f.save);
        case FormatUse::Document:
            return f.document;
        case FormatUse::Mesh:
            return f.mesh;
        case FormatUse::Export:
            return f.save && (f.mesh || !f.document);
        case FormatUse::Exact:
            return f.save && !f.mesh && !f.document;
    }
    return false;
}

std::string formatList(FormatUse use, std::string_view lastJoin) {
    std::vector<std::string_view> exts;
    for (const FileFormat& f : fileFormats())
        if (formatDoes(f, use))
            for (std::string_view e : f.extensions) exts.push_back(e);
    std::string out;
    for (size_t i = 0; i < exts.size(); ++i) {
        if (i > 0) out += i + 1 == exts.size() ? std::string(lastJoin) : std::string(", ");
        out += exts[i];
    }
    return out;
}

}  // namespace io
}  // namespace pw

// Loading and saving documents by file extension.
#include "core/io/document_io.hpp"

#include "core/base/embedded_data.hpp"
#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/formats.hpp"

namespace pw {
inline namespace io {

Document loadDocument(const std::filesystem::path& path, LoadReport* report, bool partial) {
    LoadReport own;
    if (!report) report = &own;
    *report = LoadReport{};
    const FileFormat* f = formatOf(path);
    if (!f || !f->load)
        throw InputError(path.string(), "unknown file type '" + lowerExtension(path) + "'; Patchwork reads " + formatList(FormatUse::Load));
    Document doc = f->load(path, report);
    if (report->incomplete && !partial) {
        std::string what;
        for (const std::string& n : report->notes) what += (what.empty() ? "" : "; ") + n;
        throw InputError(path.string(), what + " (--partial takes what came in)");
    }
    return doc;
}

void saveDocument(const Document& doc, const std::filesystem::path& path, const ExportOptions& options, TriangleMesh* displayed) {
    const FileFormat* f = formatOf(path);
    if (!f || !f->save)
        throw OutputError(path.string(),
                          "unknown file type '" + lowerExtension(path) + "'; Patchwork writes " + formatList(FormatUse::Save));
    if (f->mesh && options.asDisplayed && !displayed)
        throw OutputError(path.string(),
                          "the surface as displayed comes from the GPU; export it with `patchwork export "
                          "--as-displayed` or the editor's File > Export As Displayed");
    f->save(doc, path, options, displayed);
}

std::string savableExtensions() { return formatList(FormatUse::Save); }

bool isMeshFormat(const std::filesystem::path& path) {
    const FileFormat* f = formatOf(path);
    return f && f->mesh;
}

bool canSave(const std::filesystem::path& path) {
    const FileFormat* f = formatOf(path);
    return f && f->save;
}

std::string skippedSummary(const std::vector<std::string>& notes) {
    if (notes.empty()) return {};
    return std::to_string(notes.size()) + (notes.size() == 1 ? " face" : " faces") + " not imported; " + notes.front();
}

bool saveKeepsEverything(const std::filesystem::path& path) {
    const FileFormat* f = formatOf(path);
    return f && f->keepsEverything;
}

Document builtinTeapot() {
    Document doc = parseBpt(embedded::teapotBpt, "teapot.bpt (built in)");
    doc.name = "teapot";
    return doc;
}

}  // namespace io
}  // namespace pw

// `patchwork convert IN OUT`: any loadable document to any savable one, by extension (.patchwork,
// .bpt, .gltf, .glb). glTF output uses the input's export options when it is a Patchwork glTF, else
// the defaults (one exported as displayed is tessellated on the GPU again). The output is written
// atomically: on any error nothing is left at OUT (an existing file there stays as it was).
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.hpp"
#include "app/displacement_args.hpp"
#include "app/displayed_mesh.hpp"
#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/io/document_io.hpp"
#include "core/io/formats.hpp"

namespace pw::app {

namespace {

struct ConvertOptions {
    std::string input, output;
    bool quiet = false;
    bool partial = false;
};

int runConvert(const ConvertOptions& opt) {
    // Refuse an unknown output type before doing any work.
    if (!canSave(opt.output))
        throw OutputError(opt.output, "unknown file type '" + lowerExtension(opt.output) + "'; Patchwork writes " + savableExtensions());
    LoadReport report;
    const Document doc = loadDocument(opt.input, &report, opt.partial);
    for (const std::string& note : report.notes) std::cerr << "patchwork convert: " << opt.input << ": " << note << "\n";
    (void)loadDocumentHeightMap(doc, opt.input);  // a height map that cannot be read is refused, whatever the output
    ExportOptions options = report.exportOptions.value_or(ExportOptions{});
    std::optional<TriangleMesh> displayed;  // a glTF exported as displayed is written so again
    if ((options.asDisplayed || doc.displacement.active()) && isMeshFormat(opt.output)) {  // displaced: only the GPU displaces
        DisplayedMeshRequest request = displayedMeshRequest(options);
        request.map = loadDocumentHeightMap(doc, opt.input);
        render::CapturedSurface captured = captureDisplayedMesh(doc, request);
        options.culledPatches = captured.culledPatches();
        displayed = std::move(captured.mesh);
    }
    saveDocument(doc, opt.output, options, displayed ? &*displayed : nullptr);
    if (!opt.quiet)
        std::cout << "wrote " << opt.output << " (" << doc.patches.size() << " patches, " << doc.surfaces.size() << " surfaces, "
                  << doc.points.size() << " points, " << doc.joins.size() << " joins)\n";
    return 0;
}

}  // namespace

void registerConvertCommand(CLI::App& app, Action& run) {
    const auto [cmd, opt] =
        addSubcommand<ConvertOptions>(app, run, "convert", "Convert a document between formats, chosen by the file extensions", runConvert);
    cmd->add_option("input", opt->input, "Input (" + formatList(FormatUse::Load, ", ") + ")")->required();
    cmd->add_option("output", opt->output, "Output (" + formatList(FormatUse::Save, ", ") + "); replaced atomically")->required();
    cmd->add_flag("-q,--quiet", opt->quiet, "Print nothing on success");
    addCadReadOptions(cmd);
    cmd->add_flag(
        "--partial", opt->partial,
        "Take a STEP/IGES file that comes in incomplete (faces skipped) as far as it comes; otherwise such a file is refused (exit 2)");
}

}  // namespace pw::app

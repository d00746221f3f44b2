// `patchwork export FILE -o OUT [--tess N] [--merge] [--cage]`: tessellates the document and writes a
// glTF 2.0 file (.gltf with an embedded buffer, or .glb) that also carries the editable patches.
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "core/document_io.hpp"
#include "core/file_io.hpp"
#include "core/gltf_export.hpp"
#include "core/limits.hpp"

namespace pw::app {

namespace {

struct ExportArgs {
    std::string input;
    std::string output;
    int tess = 0;  // 0 = the document's level
    bool tessGiven = false;
    bool merge = false;
    bool cage = false;
};

int runExport(const ExportArgs& args) {
    if (args.tessGiven && (args.tess < 1 || args.tess > limits::kMaxExportLevel)) {
        std::cerr << "patchwork export: --tess must be an integer from 1 to " << limits::kMaxExportLevel << " (got "
                  << args.tess << ")\n";
        return 2;
    }
    (void)checkOutputPath(args.output);  // refuse an unwritable output before tessellating
    const Document doc = loadDocument(args.input);
    GltfExportOptions options;
    options.level = args.tessGiven ? args.tess : 0;
    options.merge = args.merge;
    options.cage = args.cage;
    const GltfExportStats stats = exportGltfWithStats(doc, args.output, options);
    std::cout << "wrote " << args.output << ": " << stats.triangles << " triangles, " << stats.vertices << " vertices";
    if (args.cage) std::cout << ", " << stats.cageSegments << " cage segments";
    if (stats.curveSegments) std::cout << ", " << stats.curveSegments << " curve segments";
    std::cout << ", " << stats.bytes << " bytes (level " << stats.level << ", "
              << (args.merge ? "one merged primitive" : "one primitive per patch") << ")\n";
    return 0;
}

}  // namespace

void registerExportCommand(CLI::App& app, Action& run) {
    const auto [cmd, args] = addSubcommand<ExportArgs>(app, run, "export", "Tessellate a document and write it as glTF 2.0 (.gltf or .glb)", runExport);
    cmd->add_option("file", args->input, "Document to export (.patchwork, .bpt, .gltf, .glb)")->required();
    cmd->add_option("-o,--output", args->output, "Output file: .glb (binary) or .gltf (JSON, embedded buffer)")->required();
    cmd->add_option("--tess", args->tess,
                    "Tessellation level per patch side, 1.." + std::to_string(limits::kMaxExportLevel) +
                        " (default: the document's level)");
    cmd->add_flag("--merge", args->merge, "One mesh primitive for everything instead of one per patch");
    cmd->add_flag("--cage", args->cage, "Add the control cage as a LINES primitive");
    cmd->parse_complete_callback([cmd = cmd, args = args] { args->tessGiven = cmd->count("--tess") > 0; });
}

}  // namespace pw::app

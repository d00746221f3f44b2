// `patchwork export FILE -o OUT [--tess N | --as-displayed [--size WxH] [--device NAME]]
// [--primitives surfaces|patches|single] [--cage]`: tessellates the document and writes a glTF 2.0
// file (.gltf with an embedded buffer, or .glb) that also carries the editable patches, or OBJ; or
// exact STEP. --as-displayed writes the triangles the GPU draws for the document's view (app/displayed_mesh). Options not given come from
// FILE's own export options when it is a Patchwork glTF (so re-exporting it without flags writes the same file), else the defaults.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.hpp"
#include "app/displacement_args.hpp"
#include "app/displayed_mesh.hpp"
#include "app/level_args.hpp"
#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/limits.hpp"
#include "core/io/document_io.hpp"
#include "core/io/formats.hpp"
#include "core/io/gltf_export.hpp"
#include "core/io/obj_export.hpp"
#include "core/io/step_export.hpp"
#include "render/vk/device.hpp"

namespace pw::app {

namespace {

struct ExportArgs {
    std::string input;
    bool partial = false;
    std::string output;
    int tess = 0;  // 0 = the document's level
    bool tessGiven = false;
    std::string primitives;  // empty: not given
    bool cage = false;
    bool cageGiven = false;
    std::string schema = "ap214";
    bool asDisplayed = false;
    bool asDisplayedGiven = false;
    std::string size;  // WxH, empty: the file's own (as displayed before) or 1280x720
    std::string device;
    bool validation = false;
    DisplacementArgs displacement;
};

// The surface as displayed, when asked for (or when FILE was exported so and no --tess overrides
// it): captured on the GPU, described on stdout. nullopt: tessellate at the level.
std::optional<TriangleMesh> displayedMesh(const ExportArgs& args, const Document& docIn, ExportOptions& options) {
    Document doc = docIn;
    const bool displaced = doc.displacement.active();
    if (displaced && args.asDisplayedGiven && !args.asDisplayed)
        throw InputError("export", "--no-as-displayed: a displaced surface is exported as displayed (only the GPU displaces it)");
    if (displaced && args.tessGiven) {  // --tess: uniform levels for the displaced surface, and all of it
        doc.tess.outer = {float(args.tess), float(args.tess), float(args.tess), float(args.tess)};
        doc.tess.inner = {float(args.tess), float(args.tess)};
        doc.tess.adaptive = AdaptiveMode::None;
        doc.tess.cullOffscreen = doc.tess.cullBackfaces = false;  // a fixed level is the whole model; only the view culls
    }
    const bool wanted = displaced || (args.asDisplayedGiven ? args.asDisplayed : options.asDisplayed && !args.tessGiven);
    options.asDisplayed = wanted;
    if (!wanted) {
        options.viewport = {0, 0};
        return std::nullopt;
    }
    DisplayedMeshRequest request = displayedMeshRequest(options);
    if (!args.size.empty()) {
        const auto [w, h] = parseImageSize("export", args.size);
        request.viewport = {int(w), int(h)};
    }
    options.viewport = request.viewport;
    request.device = args.device;
    request.validation = args.validation;
    request.map = loadDocumentHeightMap(doc, args.input);
    std::string deviceName;
    render::CapturedSurface captured = captureDisplayedMesh(doc, request, &deviceName);
    options.culledPatches = captured.culledPatches();  // said in the glTF's extras
    std::cout << describeCapture(captured, request, deviceName) << "\n";
    return std::move(captured.mesh);
}

// The document to export, after refusing an unwritable output (before any work); what the load
// skipped goes to stderr.
Document loadForExport(const ExportArgs& args, LoadReport& report) {
    (void)checkOutputPath(args.output);
    Document doc = loadDocument(args.input, &report, args.partial);
    for (const std::string& note : report.notes) std::cerr << "patchwork export: " << args.input << ": " << note << "\n";
    applyDisplacementArgs("export", args.displacement, doc);
    (void)loadDocumentHeightMap(doc, args.input);  // an unreadable map is refused before any work
    return doc;
}

int runCadExport(const ExportArgs& args) {
    if (args.schema != "ap214" && args.schema != "ap242") {
        std::cerr << "patchwork export: --schema must be ap214 or ap242 (got " << args.schema << ")\n";
        return 2;
    }
    LoadReport report;
    const Document doc = loadForExport(args, report);
    if (doc.displacement.active())
        std::cerr
            << "patchwork export: STEP holds the exact patches without their displacement (a height map is not a surface STEP can carry)\n";
    StepExportOptions options;
    options.schema = args.schema == "ap242" ? StepSchema::AP242 : StepSchema::AP214;
    const StepExportStats stats = exportStep(doc, args.output, options);
    std::cout << "wrote " << args.output << ": " << stats.faces << " exact faces in " << stats.shells
              << (stats.shells == 1 ? " shell" : " shells")
              << (stats.solids ? " (" + std::to_string(stats.solids) + (stats.solids == 1 ? " closed: a solid)" : " closed: solids)") : "")
              << ", " << stats.sharedEdges << " shared edges, " << stats.freeEdges << " free, " << stats.degenerateEdges << " collapsed, "
              << stats.bytes << " bytes ("
              << (formatOf(args.output)->name == std::string_view("IGES") ? "IGES"
                  : args.schema == "ap242"                                ? "AP242"
                                                                          : "AP214")
              << ", " << lengthUnitName(doc.unit) << ", +Z up)\n";
    return 0;
}

int runObjExport(const ExportArgs& args) {
    LoadReport report;
    const Document doc = loadForExport(args, report);
    ExportOptions options = report.exportOptions.value_or(ExportOptions{});
    std::optional<TriangleMesh> displayed = displayedMesh(args, doc, options);
    const ObjExportStats stats = exportObj(doc, args.output, args.tessGiven ? args.tess : 0, displayed ? &*displayed : nullptr);
    std::filesystem::path mtl = args.output;
    mtl.replace_extension(".mtl");
    std::cout << "wrote " << args.output << " and " << mtl.filename().string() << ": " << stats.triangles << " triangles, "
              << stats.positions << " positions, " << stats.normals << " normals, " << stats.uvs << " texture coordinates, " << stats.groups
              << " groups";
    if (stats.lineSegments) std::cout << ", " << stats.lineSegments << " curve segments";
    std::cout << ", " << stats.bytes << " bytes ("
              << (stats.asDisplayed ? std::string("as displayed") : "level " + std::to_string(stats.level)) << ")\n";
    return 0;
}

int runGltfExport(const ExportArgs& args) {
    const auto grouping = args.primitives.empty() ? std::nullopt : parseMeshGrouping(args.primitives);
    if (!args.primitives.empty() && !grouping) {
        std::cerr << "patchwork export: --primitives must be surfaces, patches or single (got " << args.primitives << ")\n";
        return 2;
    }
    LoadReport report;
    const Document doc = loadForExport(args, report);
    ExportOptions options = report.exportOptions.value_or(ExportOptions{});
    if (args.tessGiven) options.level = args.tess;
    if (grouping) options.primitives = *grouping;
    if (args.cageGiven) options.cage = args.cage;
    std::optional<TriangleMesh> displayed = displayedMesh(args, doc, options);
    const GltfExportStats stats = exportGltfWithStats(doc, args.output, options, displayed ? &*displayed : nullptr);
    std::cout << "wrote " << args.output << ": " << stats.triangles << " triangles, " << stats.vertices << " vertices";
    if (options.cage) std::cout << ", " << stats.cageSegments << " cage segments";
    if (stats.curveSegments) std::cout << ", " << stats.curveSegments << " curve segments";
    std::cout << ", " << stats.bytes << " bytes ("
              << (options.asDisplayed ? std::string("as displayed") : "level " + std::to_string(stats.level)) << ", " << stats.primitives
              << (stats.primitives == 1 ? " primitive" : " primitives") << " ("
              << (options.primitives == MeshGrouping::Surfaces  ? "one per connected surface"
                  : options.primitives == MeshGrouping::Patches ? "one per patch"
                                                                : "all in one")
              << "), " << stats.openSurfaces << " open and double-sided)\n";
    return 0;
}

int runExport(const ExportArgs& args) {
    const std::string ext = lowerExtension(args.output);
    const FileFormat* format = formatOf(args.output);
    if (format && format->save && !format->mesh && !format->document) {
        if (args.asDisplayedGiven && args.asDisplayed) {
            std::cerr << "patchwork export: --as-displayed applies to tessellated exports (" << formatList(FormatUse::Mesh, ", ") << "); "
                      << format->name << " is exact\n";
            return 2;
        }
        return runCadExport(args);  // exact: no level
    }
    if (args.tessGiven && args.asDisplayedGiven && args.asDisplayed) {
        std::cerr << "patchwork export: --tess and --as-displayed exclude each other (the displayed levels are the document's)\n";
        return 2;
    }
    if (args.tessGiven && (args.tess < 1 || args.tess > limits::kMaxExportLevel)) {
        std::cerr << "patchwork export: --tess must be an integer from 1 to " << limits::kMaxExportLevel << " (got " << args.tess << ")\n";
        return 2;
    }
    const int rc = ext == ".obj" ? runObjExport(args) : runGltfExport(args);
    if (rc == 0 && (args.validation || render::validationRequestedByEnv()) && render::Device::validationMessageCount() > 0) {
        std::cerr << "patchwork export: " << render::Device::validationMessageCount() << " Vulkan validation message(s)\n";
        return 1;
    }
    return rc;
}

}  // namespace

void registerExportCommand(CLI::App& app, Action& run) {
    const auto [cmd, args] = addSubcommand<ExportArgs>(app, run, "export",
                                                       "Write a document tessellated (" + formatList(FormatUse::Mesh, ", ") +
                                                           ") or as exact surfaces (" + formatList(FormatUse::Exact, ", ") + ")",
                                                       runExport);
    cmd->add_option("file", args->input, "Document to export (" + formatList(FormatUse::Load, ", ") + ")")->required();
    cmd->add_option("-o,--output", args->output,
                    "Output file, by its extension: tessellated " + formatList(FormatUse::Mesh, ", ") +
                        " (.gltf with its buffer embedded, .obj with its .mtl beside it); exact " + formatList(FormatUse::Exact, ", "))
        ->required();
    cmd->add_option(
        "--tess", args->tess,
        "Tessellation level per patch side, 1.." + std::to_string(limits::kMaxExportLevel) + " (default: the document's level)");
    cmd->add_option("--primitives", args->primitives,
                    "surfaces: one welded primitive per connected surface (default); patches: one per patch, each with "
                    "its own vertices; single: one for everything");
    cmd->add_flag("--cage,!--no-cage", args->cage, "Add the control cage as lines in its own node (unlit)");
    cmd->add_option("--schema", args->schema, "STEP application protocol: ap214 (default) or ap242");
    cmd->add_flag("--as-displayed,!--no-as-displayed", args->asDisplayed,
                  "The triangles the GPU draws for the document's view (its per-edge levels, partitioning, adaptive "
                  "levels and culling from its camera), read back from the tessellator and welded");
    cmd->add_option("--size", args->size, "With --as-displayed: the view's size WIDTHxHEIGHT (default 1280x720)");
    cmd->add_option("--device", args->device, "With --as-displayed: Vulkan device, substring of its name");
    addDisplacementOptions(cmd, args->displacement);
    addCadReadOptions(cmd);
    cmd->add_flag(
        "--partial", args->partial,
        "Take a STEP/IGES file that comes in incomplete (faces skipped) as far as it comes; otherwise such a file is refused (exit 2)");
    cmd->add_flag("--validation", args->validation, "With --as-displayed: Khronos validation layer; exit 1 on any message");
    cmd->parse_complete_callback([cmd = cmd, args = args] {
        args->tessGiven = cmd->count("--tess") > 0;
        args->cageGiven = cmd->count("--cage") + cmd->count("--no-cage") > 0;
        args->asDisplayedGiven = cmd->count("--as-displayed") + cmd->count("--no-as-displayed") > 0;
    });
}

}  // namespace pw::app

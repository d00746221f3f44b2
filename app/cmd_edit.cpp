// `patchwork edit [IN] -o OUT [--run SCRIPT] [-c 'cmd; cmd; …']`: the editor's commands without a
// window (core/commands/command_table.hpp). IN defaults to an empty document; the script runs first, then
// the -c commands. A bad line fails with SCRIPT:LINE: message and exit 2, and then nothing is
// written: OUT and every file a `save` in the script named stay as they were.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/commands/command_table.hpp"
#include "core/io/document_io.hpp"
#include "core/io/formats.hpp"

namespace pw::app {

namespace {

struct EditOptions {
    std::string input, output, script, commands;
    bool quiet = false;
    bool partial = false;
};

// Keeps the script's writes until it has run to its end.
class ScriptHost final : public CommandHost {
public:
    void write(const Document& doc, const std::string& path) override { writes.emplace_back(path, doc); }
    // Notes of the edits (a construction whose inputs no longer fit) go to standard error.
    void note(const std::string& message) override { std::cerr << "note: " << message << "\n"; }
    std::vector<std::pair<std::string, Document>> writes;
};

int runEdit(const EditOptions& opt) {
    const FileFormat* format = formatOf(opt.output);
    if (!format || !format->document || !format->save)
        throw OutputError(opt.output,
                          "unknown file type '" + lowerExtension(opt.output) + "'; Patchwork writes " + formatList(FormatUse::Document));
    EditSession session;
    if (!opt.input.empty())
        for (const std::string& note : session.open(opt.input, opt.partial))
            std::cerr << "patchwork edit: " << opt.input << ": " << note << "\n";
    const CommandTable table = makeCommandTable();
    ScriptHost host;
    if (!opt.script.empty()) table.runScript(session, host, readFileLimited(opt.script), opt.script);
    if (!opt.commands.empty()) table.runScript(session, host, opt.commands, "-c");
    for (const auto& [path, doc] : host.writes) saveDocument(doc, path, session.exportOptions);
    const Document out = session.documentToSave();
    // Written in place of its own input while another program wrote that file (a second editor's
    // save): refused, so that work is not discarded silently (issue 73).
    std::error_code ec;
    if (!opt.input.empty() && std::filesystem::equivalent(opt.input, opt.output, ec) && session.fileChangedOnDisk())
        throw OutputError(opt.output, "was changed by another program while this edit ran; nothing was written (write to another file)");
    saveDocument(out, opt.output, session.exportOptions);
    if (!opt.quiet)
        std::cout << "wrote " << opt.output << " (" << out.patches.size() << " patches, " << out.surfaces.size() << " nets, "
                  << out.triangles.size() << " triangles, " << out.curves.size() << " curves, " << out.points.size() << " points, "
                  << out.joins.size() << " joins)\n";
    return 0;
}

}  // namespace

void registerEditCommand(CLI::App& app, Action& run) {
    const auto [cmd, opt] = addSubcommand<EditOptions>(
        app, run, "edit", "Run editor commands without a window (the names of the F1 help and the palette)", runEdit);
    cmd->add_option("input", opt->input, "Document to start from (" + formatList(FormatUse::Load, ", ") + "); default: an empty document");
    cmd->add_option("-o,--output", opt->output, "Where to write the result (" + formatList(FormatUse::Document, ", ") + "; by extension)")
        ->required();
    cmd->add_option("--run", opt->script, "Script file: one command per line or ';'-separated, '#' starts a comment");
    cmd->add_option("-c,--commands", opt->commands, "Commands, ';'-separated (run after --run)");
    cmd->add_flag("-q,--quiet", opt->quiet, "Print nothing on success");
    addCadReadOptions(cmd);
    cmd->add_flag(
        "--partial", opt->partial,
        "Take a STEP/IGES file that comes in incomplete (faces skipped) as far as it comes; otherwise such a file is refused (exit 2)");
}

}  // namespace pw::app

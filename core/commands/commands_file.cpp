// File and history commands: new, open, import, save, save-as, export-gltf, screenshot, unit, quit,
// undo, redo.
#include <filesystem>
#include <initializer_list>
#include <optional>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/commands/command_table.hpp"
#include "core/io/document_io.hpp"
#include "core/io/formats.hpp"

#include "core/tess/tess_presets.hpp"

namespace pw {
inline namespace commands {

namespace {

bool canUndo(const EditSession& s) { return s.history().canUndo(); }
bool canRedo(const EditSession& s) { return s.history().canRedo(); }

// New and Open replace the document: a window asks about unsaved changes first.
bool mayReplace(CommandContext& ctx) {
    if (!ctx.guarded || !ctx.session.isModified()) return true;
    std::vector<std::string> words{ctx.command.name};
    words.insert(words.end(), ctx.args.begin(), ctx.args.end());
    return ctx.host.confirmDiscard(words);
}

// Open, import, save and export take FILE or, in a window, nothing for its file dialog: a script
// (no window) must name the file.
void expectFileWithoutWindow(const CommandContext& ctx) {
    if (!ctx.has(0) && !ctx.host.hasWindow())
        throw EditError("expected 1 argument, got 0 (usage: " + ctx.command.name + " " + commandUsage(ctx.command) + ")");
}

// A window's "save as" of a figure: without an argument its file dialog opens (nothing to write
// yet); with one, the path, which must end in one of `extensions` (any case).
std::optional<std::string> outputArgument(CommandContext& ctx, FileDialogKind dialog, std::initializer_list<const char*> extensions) {
    if (!ctx.has(0)) {
        ctx.host.fileDialog(dialog);
        return std::nullopt;
    }
    const std::string ext = lowerExtension(ctx.word(0));
    std::string names;  // ".svg, .pdf or .png"
    for (size_t i = 0; i < extensions.size(); ++i) {
        const char* e = extensions.begin()[i];
        if (ext == e) return ctx.word(0);
        names += (i == 0 ? "" : i + 1 == extensions.size() ? " or " : ", ") + std::string(e);
    }
    throw EditError("'" + ctx.word(0) + "' is not a " + names + " file");
}

// `overwrite`: the user chose to replace the file though another program wrote it since it was
// opened or saved here (a second editor on the same file): without it that save is refused, naming
// what to do, so that no one's work is discarded silently (issue 73).
void save(CommandContext& ctx, const std::string& path, bool overwrite = false) {
    std::error_code ec;
    const bool same = path == ctx.session.path() || std::filesystem::equivalent(path, ctx.session.path(), ec);
    if (same && !overwrite && ctx.session.fileChangedOnDisk() && !ctx.host.confirmOverwriteChanged(path)) {
        if (ctx.host.hasWindow()) return;  // the window asks; its answer saves again (or not)
        throw EditError(path +
                        " was changed by another program since it was opened or saved here; saving now would discard "
                        "that work. Save under another name, open it again to see it, or replace it: `save " +
                        path + " overwrite`");
    }
    ctx.host.write(ctx.session.documentToSave(), path);
    ctx.session.savedTo(path);
    ctx.host.saved(path);
    ctx.host.status("Saved " + path);
}

// Every exec below sees words the table has checked against the command's forms.

void execNew(CommandContext& ctx) {
    if (mayReplace(ctx)) ctx.session.newDocument();
}

void execOpen(CommandContext& ctx) {
    expectFileWithoutWindow(ctx);
    if (!mayReplace(ctx)) return;
    if (!ctx.has(0))
        ctx.host.fileDialog(FileDialogKind::Open);
    else if (const auto notes = ctx.session.open(ctx.word(0)); !notes.empty())
        ctx.host.status(skippedSummary(notes));
}

void execOpenNotesPatch(CommandContext& ctx) {
    const int version = ctx.has(0) ? int(ctx.index(0)) + 1 : 1;  // "1" or "2"
    if (mayReplace(ctx)) ctx.session.reset(notesBezierPatch(version), "");
}

void execImport(CommandContext& ctx) {
    expectFileWithoutWindow(ctx);
    if (!ctx.has(0))
        ctx.host.fileDialog(FileDialogKind::Import);
    else
        ctx.session.import(ctx.word(0));
}

void execSave(CommandContext& ctx) {
    expectFileWithoutWindow(ctx);
    if (ctx.has(0))
        save(ctx, ctx.word(0), ctx.has(1));
    else if (!ctx.session.path().empty() && saveKeepsEverything(ctx.session.path()))
        save(ctx, ctx.session.path());
    else
        ctx.host.fileDialog(FileDialogKind::SaveAs);
}

void execSaveAs(CommandContext& ctx) { ctx.host.fileDialog(FileDialogKind::SaveAs); }

void execExportGltf(CommandContext& ctx) {
    expectFileWithoutWindow(ctx);
    if (!ctx.has(0)) return ctx.host.fileDialog(FileDialogKind::ExportGltf);
    const std::filesystem::path p = ctx.word(0);
    const FileFormat* f = formatOf(p);
    if (!f || !formatDoes(*f, FormatUse::Export))
        throw EditError("'" + ctx.word(0) + "' is not a " + formatList(FormatUse::Export) + " file");
    ctx.host.exportFile(ctx.session.documentToSave(), ctx.word(0));
}

void execScreenshot(CommandContext& ctx) { ctx.host.screenshot(ctx.has(0) ? ctx.word(0) : std::string()); }

void execDomainFigure(CommandContext& ctx) {
    if (const auto path = outputArgument(ctx, FileDialogKind::DomainFigure, {".svg", ".pdf", ".png"})) ctx.host.domainFigure(*path);
}

void execSweepAnimation(CommandContext& ctx) {
    if (const auto path = outputArgument(ctx, FileDialogKind::SweepAnimation, {".gif", ".mp4", ".webm"})) ctx.host.sweepAnimation(*path);
}

void execUnit(CommandContext& ctx) {
    const LengthUnit unit = *parseLengthUnit(ctx.word(0));
    ctx.session.apply(
        "Unit " + ctx.word(0), [&](Document& d) { d.unit = unit; }, false);
}

void execQuit(CommandContext& ctx) {
    if (mayReplace(ctx)) ctx.host.quit();
}

void execUndo(CommandContext& ctx) {
    ctx.session.undo();
    ctx.host.status("Undone");
}

void execRedo(CommandContext& ctx) {
    ctx.session.redo();
    ctx.host.status("Redone");
}

}  // namespace

void addFileCommands(CommandTable& t) {
    using namespace arg;
    t.add({.name = "new",
           .label = "New",
           .menu = "File",
           .help = "Start a new document with one flat patch",
           .bindings = {{"", "", {"Ctrl+N"}}},
           .exec = execNew});
    t.add({.name = "open",
           .label = "Open...",
           .menu = "File",
           .forms = {{}, {path()}},
           .help = "Open a document (" + formatList(FormatUse::Load, ", ") + "; glTF files that Patchwork wrote)",
           .bindings = {{"", "", {"Ctrl+O"}}},
           .exec = execOpen});
    t.add({.name = "open-notes-patch",
           .label = "Open the Notes' Bézier Patch",
           .forms = {{}, {choice("VERSION", {"1", "2"})}},
           .help = "Replace the document with the 16-point Bézier patch of the lecture notes: 1 the first notes' (level 25), 2 the "
                   "second notes' (level 15)",
           .exec = execOpenNotesPatch});
    t.add({.name = "import",
           .label = "Import...",
           .menu = "File",
           .forms = {{}, {path()}},
           .help = "Add everything in a .patchwork, .bpt or Patchwork glTF file to this document, selected",
           .exec = execImport});
    t.add({.name = "save",
           .label = "Save",
           .menu = "File",
           .forms = {{}, {path()}, {path(), choice("MODE", {"overwrite"})}},
           .help = "Save to the document's file (atomic write); untitled or .bpt documents ask for a name. A file another "
                   "program wrote since it was opened here is not replaced unless `overwrite` follows its name",
           .bindings = {{"", "", {"Ctrl+S"}}},
           .exec = execSave});
    t.add({.name = "save-as",
           .label = "Save As...",
           .menu = "File",
           .help = "Save under a new name (" + formatList(FormatUse::Document, ", ") + ")",
           .bindings = {{"", "", {"Ctrl+Shift+S"}}},
           .windowOnly = true,
           .exec = execSaveAs});
    t.add({.name = "export-gltf",
           .label = "Export...",
           .menu = "File",
           .forms = {{}, {path()}},
           .help = "Write a glTF 2.0 (.gltf, .glb; the patches kept in extras) or OBJ (.obj + .mtl) mesh, or exact "
                   "STEP surfaces (.step, .stp)",
           .exec = execExportGltf});
    t.add({.name = "screenshot",
           .label = "Save Screenshot...",
           .menu = "File",
           .forms = {{}, {path()}},
           .help = "Save the 3D viewport (without panels) as a PNG",
           .bindings = {{"", "", {"F12"}}},
           .windowOnly = true,
           .exec = execScreenshot});
    t.add({.name = "domain-figure",
           .label = "Save Domain Figure...",
           .menu = "File",
           .forms = {{}, {path()}},
           .help = "Save the domain view (its panes, levels and counts) as a vector figure for slides: .svg or .pdf (every "
                   "triangle one path), or .png",
           .windowOnly = true,
           .exec = execDomainFigure});
    t.add({.name = "sweep-animation",
           .label = "Save Sweep Animation...",
           .menu = "File",
           .forms = {{}, {path()}},
           .help = "Save the Teaching panel's level sweep (from, to, seconds) as an animation at 10 frames a second: the domain "
                   "view's panes when it is open, else the 3D view; .gif, .mp4 or .webm",
           .windowOnly = true,
           .exec = execSweepAnimation});
    // The document's length unit from the File menu (also `set unit`, the settings table's row).
    t.add({.name = "unit",
           .label = "Document Unit",
           .menu = "File",
           .forms = {{choice("UNIT", {"mm", "cm", "m", "in"})}},
           .help = "The length unit of the document's coordinates, which STEP, glTF (in metres) and OBJ files state; the numbers "
                   "are relabelled, not scaled",
           .bindings =
               {{"Unit: Millimetres", "mm", {}}, {"Unit: Centimetres", "cm", {}}, {"Unit: Metres", "m", {}}, {"Unit: Inches", "in", {}}},
           .exec = execUnit});
    t.add({.name = "quit",
           .label = "Quit",
           .menu = "File",
           .help = "Close the editor (asks about unsaved changes)",
           .bindings = {{"", "", {"Ctrl+Q"}}},
           .windowOnly = true,
           .exec = execQuit});
    t.add({.name = "undo",
           .label = "Undo",
           .menu = "Edit",
           .help = "Undo the last edit (one drag is one step)",
           .bindings = {{"", "", {"Ctrl+Z"}}},
           .enabled = canUndo,
           .exec = execUndo});
    t.add({.name = "redo",
           .label = "Redo",
           .menu = "Edit",
           .help = "Redo the undone edit",
           .bindings = {{"", "", {"Ctrl+Shift+Z", "Ctrl+Y"}}},
           .enabled = canRedo,
           .exec = execRedo});
}

}  // namespace commands
}  // namespace pw

// The command table: every editor action as one command object (name, label, menu, shortcuts,
// enabled-when, run). The editor's menus, keyboard shortcuts, F1 help and command palette are
// generated from it, and `patchwork edit` runs the same commands from a script.
//
// A command runs on an EditSession through a CommandHost: the editor window (file dialogs, the
// unsaved-changes prompt, its panels) or a script host without a window. Commands that only make
// sense with a window (quit, help, palette, …) are marked windowOnly and refused by scripts.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/edit/edit_session.hpp"

namespace pw {

// What the editor window does for commands; a script host keeps the defaults.
enum class FileDialogKind { Open, SaveAs, Import, ExportGltf, Screenshot, DomainFigure, SweepAnimation, HeightMap };
enum class WindowToggle { Help, Palette, Presentation, DomainView, ShaderPanel, GroundGrid, JoinTool, XRay, CurveTool, FullDetail };

class CommandHost {
public:
    virtual ~CommandHost() = default;
    virtual bool hasWindow() const { return false; }
    // Before the command `words` (name and arguments) replaces a modified document: true to go on
    // now. A window asks the user and returns false; it runs the command again (unguarded) once the
    // user saved or discarded.
    virtual bool confirmDiscard(const std::vector<std::string>& words) {
        (void)words;
        return true;
    }
    // Writes `doc` to `path` (by extension). A script host keeps every write until the script ended
    // well, so that a failing script leaves no file behind.
    virtual void write(const Document& doc, const std::string& path) = 0;
    // An export (a copy of the document, not its file): a window writes it in the background and
    // reports when it is done; a script host writes it like any other output.
    virtual void exportFile(const Document& doc, const std::string& path) { write(doc, path); }
    // After `save` wrote the document to `path` (the session has taken it as its file when the
    // format keeps everything): a window updates its title, recent files and autosave.
    virtual void saved(const std::string& path) { (void)path; }
    // Window-only actions (never called for a host without a window).
    virtual void fileDialog(FileDialogKind) {}
    virtual void toggle(WindowToggle) {}
    virtual bool toggled(WindowToggle) const { return false; }
    virtual void quit() {}
    // Presentation mode's text size, times the interface's (limits::kMin/kMaxPresentationText).
    virtual float presentationTextScale() const { return 0.0f; }
    virtual void setPresentationTextScale(float scale) { (void)scale; }
    virtual void screenshot(const std::string& path) { (void)path; }
    // The domain view as a figure (.svg, .pdf, .png) and the Teaching sweep as an animation (.gif,
    // .mp4, .webm), as `render` and `sweep` write them.
    virtual void domainFigure(const std::string& path) { (void)path; }
    virtual void sweepAnimation(const std::string& path) { (void)path; }
    // Fits `box` into the 3D view (a window knows its panels and panes); false: no view, the
    // command frames for a 16:9 image.
    virtual bool frame(const Bounds& box) {
        (void)box;
        return false;
    }
    virtual void status(const std::string& message) { (void)message; }
    // What an edit left to say (a live construction whose inputs no longer fit): the status line.
    virtual void note(const std::string& message) { status(message); }
};

struct Command;
struct CommandContext {
    const Command& command;
    EditSession& session;
    CommandHost& host;
    std::vector<std::string> args;  // the words after the command's name
    bool guarded = true;            // false: the unsaved-changes prompt was already answered
    // A live preview while a panel's slider moves: the command changes the document but records no
    // undo step; the same command run without it when the slider is let go commits one. Only
    // commands marked `previewable` take it.
    bool preview = false;
};

// A menu entry and its shortcuts: a command with fixed arguments ("view front", "1").
struct CommandBinding {
    std::string label;                   // menu text; empty: the command's label
    std::string args;                    // words passed to the command
    std::vector<std::string> shortcuts;  // "Ctrl+Shift+Z", "Numpad1", "F12", "Shift+D"; first shown in menus
};

struct Command {
    std::string name;                      // script and palette name: "save", "view", "add-patch"
    std::string label;                     // "Save", "Add Flat Patch"
    std::string menu;                      // "File", "Edit", "Select", "Add", "Patch", "View", "Display", "Help"; "" = none
    std::string usage;                     // argument synopsis for scripts and F1: "[FILE]", "X Y Z"
    std::string help;                      // one sentence for tooltips, F1 and the palette
    std::vector<CommandBinding> bindings;  // menu entries with shortcuts; empty: one entry, no args
    bool windowOnly = false;
    bool previewable = false;                                             // takes CommandContext::preview
    std::function<bool(const EditSession&)> enabled;                      // null: always
    std::function<bool(const EditSession&, const CommandHost&)> checked;  // null: not a toggle
    std::function<void(CommandContext&)> run;
};

class CommandTable {
public:
    void add(Command c);  // throws std::logic_error on a duplicate name
    const Command* find(std::string_view name) const;
    const std::vector<Command>& commands() const { return commands_; }
    // Menus in the order their first command was added.
    std::vector<std::string> menus() const;

    // Runs one command line ("move 1 0 0"). Throws EditError for a bad line, an unknown or
    // disabled command, or one that needs a window the host has not got; the command's own
    // exceptions go on.
    void run(EditSession& session, CommandHost& host, std::string_view line, bool guarded = true) const;
    // The same with the line split already (a file name from a dialog needs no quoting).
    void run(EditSession& session, CommandHost& host, const std::vector<std::string>& words, bool guarded = true) const;
    // A previewable command as a live preview (CommandContext::preview); throws EditError for any
    // other command.
    void preview(EditSession& session, CommandHost& host, const std::vector<std::string>& words) const;
    bool isEnabled(const Command& c, const EditSession& session) const { return !c.enabled || c.enabled(session); }

    // A script: one command per line or `;`-separated, `#` starts a comment. Any failure throws
    // InputError(scriptName, message, line).
    void runScript(EditSession& session, CommandHost& host, std::string_view script, const std::string& scriptName) const;

private:
    std::vector<Command> commands_;
};

// Splits a command line into words (whitespace; "double quotes" keep spaces in one word).
std::vector<std::string> splitCommandWords(std::string_view line);

// The document, file, selection, transform, patch, view and display commands, and the
// window-only ones (their runs call the host).
CommandTable makeCommandTable();
void addFileCommands(CommandTable& t);       // core/commands/commands_file.cpp: new, open, import, save, undo, …
void addSelectCommands(CommandTable& t);     // core/commands/commands_select.cpp: select, move, rotate, scale, cursor
void addModelCommands(CommandTable& t);      // core/commands/commands_model.cpp: add, delete, duplicate, join, split, …
void addPrimitiveCommands(CommandTable& t);  // core/commands/commands_primitives.cpp: exact sphere, cylinder, cone, torus; weight
void addViewCommands(CommandTable& t);       // core/commands/commands_view.cpp: views, frame, overlays, shading, levels
void addSettingCommands(CommandTable& t);    // core/commands/commands_settings.cpp: `set KEY VALUE...` for every settings row
void addDisplacementCommands(CommandTable& t);
void addConstructCommands(CommandTable& t);  // core/commands/commands_construct.cpp: curves, revolve, loft, bake
// `extrude C DX DY DZ`: the curve or edge C extruded (the `extrude` command's second form).
void runCurveExtrude(CommandContext& ctx);  // core/commands/commands_displacement.cpp: height map, scale, bias, mapping

// Argument parsing for commands: a number, an index, an "A:EDGE" pair; EditError naming the word.
double commandNumber(const std::string& word, const char* what);
uint32_t commandIndex(const std::string& word, size_t count, const char* what);
int axisIndex(const std::string& word);  // X|Y|Z (either case) → 0|1|2
void expectArgs(const CommandContext& ctx, size_t min, size_t max);
// A window-only command that toggles `which` (checked in the menus while it is on), bound to `keys`.
Command windowToggle(const char* name, const char* label, const char* menu, WindowToggle which, std::vector<std::string> keys,
                     const char* help);

}  // namespace pw

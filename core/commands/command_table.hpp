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
inline namespace commands {

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
    // Before `save` replaces its document's file, which another program changed since it was opened
    // or saved here (a second editor): true to replace it now. A window asks (Overwrite, Save As,
    // Cancel) and returns false; the answer saves again. Without a window the save is refused,
    // naming `save FILE overwrite`.
    virtual bool confirmOverwriteChanged(const std::string& path) {
        (void)path;
        return false;
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

// The type of a command's argument, as the properties of a Blender operator: the table checks each
// word against it before the command runs, so a command's exec function reads values, not words.
enum class ArgType : uint8_t {
    Word,      // any word: a name, a key, a list, a point "X,Y,Z"
    Number,    // a finite number within the coordinate limit (commandNumber)
    Count,     // a whole number ≥ 0 ("5" or "5.0")
    Choice,    // one of the argument's `choices`, as written
    Axis,      // X, Y or Z (either case)
    Edge,      // a patch edge u0, v0, u1 or v1
    Patch,     // the index of a patch of the document
    Triangle,  // the index of a Bézier triangle
    Curve,     // the index of a curve
    Net,       // the index of a net surface
    Path,      // a file name
};

struct CommandArg {
    std::string name;  // shown in the usage: "DX", "FILE"; a Choice shows its choices
    ArgType type = ArgType::Word;
    std::vector<std::string> choices;  // ArgType::Choice
    bool optional = false;             // may be left out (with every argument after it)
    bool repeated = false;             // the last argument only: takes every word left (one or more)
    bool anyCase = false;              // a Choice taken in either case ("U" for "u")
    std::string shown;                 // the usage text where the name alone does not say it ("C C ... [closed]")
};
// One way to call a command: its arguments in order. A command with several forms ("scale S" and
// "scale SX SY SZ") lists each; the table takes the first that fits.
using CommandForm = std::vector<CommandArg>;

// Argument builders for the command definitions: `{number("DX"), number("DY"), number("DZ")}`,
// `{choice("MODE", {"on", "off"}), opt(number("R"))}`, `{many(word("SIDE"))}`.
namespace arg {
inline CommandArg word(std::string name) { return {std::move(name), ArgType::Word}; }
inline CommandArg number(std::string name) { return {std::move(name), ArgType::Number}; }
inline CommandArg count(std::string name) { return {std::move(name), ArgType::Count}; }
inline CommandArg path(std::string name = "FILE") { return {std::move(name), ArgType::Path}; }
inline CommandArg choice(std::string name, std::vector<std::string> choices) {
    return {std::move(name), ArgType::Choice, std::move(choices)};
}
inline CommandArg axis(std::string name = "AXIS") { return {std::move(name), ArgType::Axis}; }
inline CommandArg edge(std::string name = "EDGE") { return {std::move(name), ArgType::Edge}; }
inline CommandArg patch(std::string name = "P") { return {std::move(name), ArgType::Patch}; }
inline CommandArg triangle(std::string name = "T") { return {std::move(name), ArgType::Triangle}; }
inline CommandArg curve(std::string name = "C") { return {std::move(name), ArgType::Curve}; }
inline CommandArg net(std::string name = "N") { return {std::move(name), ArgType::Net}; }
inline CommandArg opt(CommandArg a) {
    a.optional = true;
    return a;
}
inline CommandArg many(CommandArg a) {
    a.repeated = true;
    return a;
}
inline CommandArg anyCase(CommandArg a) {
    a.anyCase = true;
    return a;
}
inline CommandArg shown(CommandArg a, std::string text) {
    a.shown = std::move(text);
    return a;
}
}  // namespace arg

// The checked value of one argument word.
struct ArgValue {
    double number = 0.0;  // Number, Count
    uint32_t index = 0;   // Count; Choice: which choice; Axis 0..2; Edge (as Edge); an item's index
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
    size_t form = 0;               // which of the command's forms the words fit
    std::vector<ArgValue> values;  // one per word, checked against that form

    // Typed access to word i, as the matched form declares it.
    bool has(size_t i) const { return i < args.size(); }
    const std::string& word(size_t i) const { return args.at(i); }
    double number(size_t i) const { return values.at(i).number; }
    uint32_t index(size_t i) const { return values.at(i).index; }  // Count, Choice, Axis, an item
    Edge edge(size_t i) const { return Edge(values.at(i).index); }
    // The words from i on (a repeated argument).
    std::vector<std::string> rest(size_t i) const {
        return i < args.size() ? std::vector<std::string>(args.begin() + long(i), args.end()) : std::vector<std::string>{};
    }
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
    std::vector<CommandForm> forms;        // its arguments, checked before exec; empty: none
    std::string help;                      // one sentence for tooltips, F1 and the palette
    std::vector<CommandBinding> bindings;  // menu entries with shortcuts; empty: one entry, no args
    bool windowOnly = false;
    bool previewable = false;                                             // takes CommandContext::preview
    std::function<bool(const EditSession&)> enabled;                      // null: always
    std::function<bool(const EditSession&, const CommandHost&)> checked;  // null: not a toggle
    std::function<void(CommandContext&)> exec;  // a named function (execMove, execJoin, …) or one a family shares
};

// The argument synopsis for scripts, F1 and errors, from the forms: "DX DY DZ", "S | SX SY SZ",
// "[u0|v0|u1|v1]", "SIDE SIDE SIDE …".
std::string commandUsage(const Command& c);
// True when every form of the command needs at least one word (a menu entry must give them).
bool commandNeedsWords(const Command& c);

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
void addFileCommands(CommandTable& t);          // core/commands/commands_file.cpp: new, open, import, save, undo, …
void addSelectCommands(CommandTable& t);        // core/commands/commands_select.cpp: select, move, rotate, scale, cursor
void addModelCommands(CommandTable& t);         // core/commands/commands_model.cpp: add, delete, duplicate, join, split, …
void addPrimitiveCommands(CommandTable& t);     // core/commands/commands_primitives.cpp: exact sphere, cylinder, cone, torus; weight
void addViewCommands(CommandTable& t);          // core/commands/commands_view.cpp: views, frame, overlays, shading, levels
void addSettingCommands(CommandTable& t);       // core/commands/commands_settings.cpp: `set KEY VALUE...` for every settings row
void addDisplacementCommands(CommandTable& t);  // core/commands/commands_displacement.cpp: height map, scale, bias, mapping, own
void addConstructCommands(CommandTable& t);     // core/commands/commands_construct.cpp: curves, revolve, loft, bake
void addItemCommands(CommandTable& t);          // core/commands/commands_items.cpp: rename, point
void addNetCommands(CommandTable& t);           // core/commands/commands_net.cpp: net basis, tension, closing, rows, conversions
void addTrimCommands(CommandTable& t);          // core/commands/commands_trim.cpp: project, trim, intersect, split-by, untrim
void addTessCommands(CommandTable& t);          // core/commands/commands_tess.cpp: items' own levels, kept levels, the notes' formulas
// `extrude C DX DY DZ`: the curve or edge C extruded (the `extrude` command's second form).
void runCurveExtrude(CommandContext& ctx);  // core/commands/commands_construct.cpp

// Argument parsing for commands: a number, an index, an "A:EDGE" pair; EditError naming the word.
double commandNumber(const std::string& word, const char* what);
uint32_t commandIndex(const std::string& word, size_t count, const char* what);
int axisIndex(const std::string& word);  // X|Y|Z (either case) → 0|1|2
// A window-only command that toggles `which` (checked in the menus while it is on), bound to `keys`.
Command windowToggle(const char* name, const char* label, const char* menu, WindowToggle which, std::vector<std::string> keys,
                     const char* help);

}  // namespace commands
}  // namespace pw

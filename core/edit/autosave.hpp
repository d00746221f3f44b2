// Autosave and crash recovery for the editor: while a document is modified it is written every
// 30 s to $XDG_STATE_HOME/patchwork (or ~/.local/state/patchwork) as autosave-<pid>.patchwork with a
// small JSON note naming the original file. A clean exit removes both; an autosave whose process
// no longer runs is offered for recovery at the next start.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace edit {

std::filesystem::path autosaveDirectory();

struct AutosaveEntry {
    std::filesystem::path document;  // the autosaved .patchwork
    std::filesystem::path note;      // its JSON note
    std::string originalPath;        // the file the user was editing ("" = untitled)
    long long savedAtUnix = 0;
    int pid = 0;
};

class Autosaver {
public:
    explicit Autosaver(std::filesystem::path dir = autosaveDirectory(), int pid = 0);
    // Writes the document now (atomic). Throws OutputError when the directory cannot be written.
    void save(const Document& doc, const std::string& originalPath);
    // Removes this process's autosave (after a save or a clean exit), and an adopted one.
    void discard();
    // The editor recovered `recovered`: keep its files until this autosaver's next successful save()
    // or discard(), so that a second crash in between does not lose the recovered work.
    void adopt(const AutosaveEntry& recovered);
    const std::filesystem::path& documentPath() const { return doc_; }
    const std::filesystem::path& notePath() const { return note_; }

private:
    std::filesystem::path dir_, doc_, note_;
    int pid_;
    std::optional<AutosaveEntry> adopted_;
};

// The JSON note beside an autosave, as findRecoverableAutosaves reads it: the file the user was
// editing, the process, the time now and the document's name; `emergency` marks one written by
// the emergency save (core/edit/emergency_save.hpp).
std::string autosaveNote(const std::string& originalPath, int pid, const std::string& name, bool emergency = false);

// Creates `dir` as a folder only this user can enter (0700), or checks an existing one: a real
// folder owned by this user, made private if it is not. Throws OutputError naming it otherwise.
void ensurePrivateDirectory(const std::filesystem::path& dir);
bool isPrivateDirectory(const std::filesystem::path& dir);

// Autosaves left by processes that no longer run, newest first; none from a folder that is not
// private (another user could have planted them).
std::vector<AutosaveEntry> findRecoverableAutosaves(const std::filesystem::path& dir = autosaveDirectory());
// Deletes an entry's files.
void removeAutosave(const AutosaveEntry& e);

}  // namespace edit
}  // namespace pw

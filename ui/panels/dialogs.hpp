// The editor's dialogs: the file browser (dialog_file_browser.cpp: Open, Import, Save As, Export
// glTF, Screenshot) and the modal prompts (dialog_modals.cpp: errors, the unsaved-changes prompt
// whose answer runs the command that asked, autosave recovery).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/edit/autosave.hpp"
#include "ui/panels/panel_context.hpp"

namespace pw::ui {
inline namespace panels {

enum class FileDialogMode { None, Open, SaveAs, Import, ExportGltf, Screenshot, DomainFigure, SweepAnimation, HeightMap };

class Dialogs {
public:
    Dialogs();  // browses from the current directory

    void openFileDialog(FileDialogKind kind, const std::string& documentName);
    // The unsaved-changes prompt; Save or Discard then run `words` unguarded.
    void askToDiscard(const std::vector<std::string>& words);
    void showError(const std::string& message);
    // Offers the first of these at the next frame (found at start-up).
    void offerRecovery(std::vector<AutosaveEntry> entries);

    void drawFileBrowser(PanelContext& ctx);
    // `recoverFirst`: recovers recoverable.front() (the editor replaces its document).
    void drawModals(PanelContext& ctx, const std::function<void()>& recoverFirst);

    std::vector<AutosaveEntry> recoverable;  // autosaves of sessions that did not exit cleanly
    bool unsavedPromptOpen() const { return !pendingCommand_.empty(); }
    const std::string& errorMessage() const { return errorMessage_; }

private:
    FileDialogMode fileMode_ = FileDialogMode::None;
    std::filesystem::path browseDir_;
    char fileName_[512] = {};
    std::string errorMessage_;
    bool openError_ = false;
    std::vector<std::string> pendingCommand_;  // waits for the unsaved-changes prompt (empty = none)
    bool focusName_ = false;                   // the file dialog's name field takes the keyboard when it opens
    bool runPendingAfterSave_ = false;         // Save As from that prompt: run it once the file is written
    bool openUnsavedPrompt_ = false;
    bool offerRecovery_ = false;
};

}  // namespace panels
}  // namespace pw::ui

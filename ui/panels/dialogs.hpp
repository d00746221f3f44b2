// The editor's dialogs: the file browser (dialog_file_browser.cpp: Open, Import, Save As, Export
// glTF, Screenshot) and the modal prompts (dialog_modals.cpp: errors, the unsaved-changes prompt
// whose answer runs the command that asked, autosave recovery, a save over a file another program
// changed).
//
// Dialogs is the one owner of the editor's modal popups (issue 72). A request (a file dialog, an
// error, the prompt, the recovery offer) may come at any point of a frame; it is queued, and
// drawModals shows one modal at a time, in the order asked: it opens it with OpenPopup right
// before its BeginPopupModal, in the same ID scope (the top level, outside any window), and never
// begins a modal that is not the top of Dear ImGui's popup stack. drawModals must be the last
// window code of the frame: Dear ImGui 1.86 aborts ("blocking_modal != NULL", imgui.cpp:6298)
// when a window appears (a tool panel, the palette, a tooltip) after a modal's first frame's
// Begin in the same frame; ImGui 1.87 fixed that (#4920), Debian ships 1.86.
#pragma once

#include <deque>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/edit/autosave.hpp"
#include "ui/panels/panel_context.hpp"

namespace pw::ui {
inline namespace panels {

enum class FileDialogMode { None, Open, SaveAs, Import, ExportGltf, Screenshot, DomainFigure, SweepAnimation, HeightMap };

// The modal popups the editor has; one is shown at a time.
enum class Modal { None, FileBrowser, Error, Unsaved, Recover, Changed };
// Its Dear ImGui popup name ("Error##error": traced as `error`); "" for None.
const char* modalPopupName(Modal m);

class Dialogs {
public:
    Dialogs();  // browses from the current directory

    void openFileDialog(FileDialogKind kind, const std::string& documentName);
    // The unsaved-changes prompt; Save or Discard then run `words` unguarded.
    void askToDiscard(const std::vector<std::string>& words);
    void showError(const std::string& message);
    // `save` over `path`, which another program changed since it was opened or saved here: Overwrite
    // (runs `save PATH overwrite`), Save As, or Cancel. A command waiting on the unsaved-changes
    // prompt goes on once the document is saved either way.
    void askOverwriteChanged(const std::string& path);
    // Offers the first of these at the next frame (found at start-up); none withdraws the offer.
    void offerRecovery(std::vector<AutosaveEntry> entries);

    // The modal shown now (or the first one asked for) and the rest in order; a frame draws one.
    // Call it at the top level (outside any ImGui window), after every other window of the frame.
    // `recoverFirst`: recovers recoverable.front() (the editor replaces its document).
    void drawModals(PanelContext& ctx, const std::function<void()>& recoverFirst);

    Modal shown() const { return shown_; }                         // the modal drawModals shows (None between modals)
    const std::deque<Modal>& waiting() const { return waiting_; }  // asked for, shown after it in this order

    std::vector<AutosaveEntry> recoverable;  // autosaves of sessions that did not exit cleanly
    bool unsavedPromptOpen() const { return !pendingCommand_.empty(); }
    const std::string& errorMessage() const { return errorMessage_; }
    const std::string& changedFile() const { return changedPath_; }  // the file askOverwriteChanged asks about ("" when none)

private:
    void request(Modal m);   // queued unless shown or queued already
    void withdraw(Modal m);  // no longer asked for (a shown recovery offer without entries closes itself)
    void closeShown();       // the shown modal closes (CloseCurrentPopup inside its Begin); the next one follows
    void drawFileBrowser(PanelContext& ctx);
    void drawError(PanelContext& ctx);
    void drawUnsaved(PanelContext& ctx);
    void drawRecover(const std::function<void()>& recoverFirst);
    void drawChanged(PanelContext& ctx);

    Modal shown_ = Modal::None;
    std::deque<Modal> waiting_;
    FileDialogMode fileMode_ = FileDialogMode::None;
    std::filesystem::path browseDir_;
    char fileName_[512] = {};
    std::string errorMessage_;
    std::string changedPath_;
    std::vector<std::string> pendingCommand_;  // waits for the unsaved-changes prompt (empty = none)
    bool focusName_ = false;                   // the file dialog's name field takes the keyboard when it opens
    bool runPendingAfterSave_ = false;         // Save As from that prompt: run it once the file is written
};

}  // namespace panels
}  // namespace pw::ui

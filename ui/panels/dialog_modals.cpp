// The modal prompts (ui/panels/dialogs.hpp): an error message, the unsaved-changes prompt (Save, Discard or
// Cancel; the first two go on with the command that asked), the offer to recover an autosave, and the
// question before a save replaces a file another program changed (Overwrite, Save As, Cancel); and
// the one place that opens, shows and closes every modal, the file browser's too (issue 72).
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <utility>

#include "core/io/document_io.hpp"
#include "ui/panels/dialogs.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {
namespace {

// Begins the prompt `name` centred in the window; true while it is shown (then the caller draws
// it and calls ImGui::EndPopup). drawModals opened it.
bool beginCentredModal(const char* name) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    return widget::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

}  // namespace

const char* modalPopupName(Modal m) {
    switch (m) {
        case Modal::FileBrowser:
            return "File browser##file";
        case Modal::Error:
            return "Error##error";
        case Modal::Unsaved:
            return "Unsaved changes##unsaved";
        case Modal::Recover:
            return "Recover autosave##recover";
        case Modal::Changed:
            return "File changed on disk##changed";
        case Modal::None:
            break;
    }
    return "";
}

void Dialogs::request(Modal m) {
    if (m == Modal::None || m == shown_ || std::find(waiting_.begin(), waiting_.end(), m) != waiting_.end()) return;
    waiting_.push_back(m);
}

void Dialogs::withdraw(Modal m) { waiting_.erase(std::remove(waiting_.begin(), waiting_.end(), m), waiting_.end()); }

void Dialogs::closeShown() {
    ImGui::CloseCurrentPopup();
    shown_ = Modal::None;
}

void Dialogs::askToDiscard(const std::vector<std::string>& words) {
    pendingCommand_ = words;
    request(Modal::Unsaved);
}

void Dialogs::showError(const std::string& message) {
    errorMessage_ = message;  // one shown now or waiting shows the latest
    request(Modal::Error);
}

void Dialogs::askOverwriteChanged(const std::string& path) {
    changedPath_ = path;
    request(Modal::Changed);
}

void Dialogs::offerRecovery(std::vector<AutosaveEntry> entries) {
    recoverable = std::move(entries);
    if (recoverable.empty())
        withdraw(Modal::Recover);
    else
        request(Modal::Recover);
}

void Dialogs::drawModals(PanelContext& ctx, const std::function<void()>& recoverFirst) {
    if (shown_ == Modal::None) {
        if (waiting_.empty()) return;
        shown_ = waiting_.front();
        waiting_.pop_front();
    }
    // The one OpenPopup, beside the BeginPopupModal that follows (the same ID scope, the same level
    // of the popup stack); again only if Dear ImGui closed it (a popup opened over it at its level),
    // never every frame.
    const char* name = modalPopupName(shown_);
    if (!ImGui::IsPopupOpen(name)) ImGui::OpenPopup(name);
    switch (shown_) {
        case Modal::FileBrowser:
            drawFileBrowser(ctx);
            break;
        case Modal::Error:
            drawError(ctx);
            break;
        case Modal::Unsaved:
            drawUnsaved(ctx);
            break;
        case Modal::Recover:
            drawRecover(recoverFirst);
            break;
        case Modal::Changed:
            drawChanged(ctx);
            break;
        case Modal::None:
            break;
    }
    if (shown_ == Modal::None && !waiting_.empty()) ctx.wake();  // the next one at the next frame
}

void Dialogs::drawError(PanelContext& ctx) {
    if (!beginCentredModal(modalPopupName(Modal::Error))) return;
    ImGui::PushTextWrapPos(560.0f);
    ImGui::TextUnformatted(errorMessage_.c_str());
    ImGui::PopTextWrapPos();
    const bool ok = widget::Button("OK##error.ok", ImVec2(120, 0));
    // Enter closes it, but not the Enter that caused it (a numeric field or the palette submitted this frame).
    if (ok || (ctx.keyPressed(GLFW_KEY_ENTER, 0) && !ImGui::IsWindowAppearing())) {
        errorMessage_.clear();
        closeShown();
    }
    tip("Close this message");
    ImGui::EndPopup();
}

void Dialogs::drawUnsaved(PanelContext& ctx) {
    if (!beginCentredModal(modalPopupName(Modal::Unsaved))) return;
    ImGui::Text("Save changes to %s?", ctx.session().path().empty() ? "the untitled document" : ctx.session().path().c_str());
    const bool save = widget::Button("Save##unsaved.save", ImVec2(100, 0));
    if (save) {
        closeShown();
        if (!ctx.session().path().empty() && saveKeepsEverything(ctx.session().path())) {
            ctx.runCommand(std::vector<std::string>{"save"});
            if (!ctx.session().isModified()) ctx.runCommand(std::exchange(pendingCommand_, {}), false);
        } else {
            runPendingAfterSave_ = true;  // the Save As dialog goes on with the command once written
            openFileDialog(FileDialogKind::SaveAs, ctx.session().doc.name);
            ctx.wake();
        }
    }
    tip("Save, then continue");
    ImGui::SameLine();
    const bool discard = widget::Button("Discard##unsaved.discard", ImVec2(100, 0));
    if (discard) {
        closeShown();
        ctx.runCommand(std::exchange(pendingCommand_, {}), false);
    }
    tip("Continue and lose the changes");
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(100, 0)) || ctx.keyPressed(GLFW_KEY_ESCAPE, 0)) {
        pendingCommand_.clear();
        closeShown();
    }
    tip("Keep editing");
    ImGui::EndPopup();
}

void Dialogs::drawChanged(PanelContext& ctx) {
    if (!beginCentredModal(modalPopupName(Modal::Changed))) return;
    ImGui::PushTextWrapPos(560.0f);
    ImGui::Text("%s was changed by another program since it was opened or saved here.", changedPath_.c_str());
    ImGui::TextUnformatted("Overwrite replaces that program's work with this document; Save As keeps both.");
    ImGui::PopTextWrapPos();
    const std::string path = changedPath_;
    if (widget::Button("Overwrite##changed.overwrite", ImVec2(120, 0))) {
        changedPath_.clear();
        closeShown();
        ctx.runCommand(std::vector<std::string>{"save", path, "overwrite"});
        if (!pendingCommand_.empty() && !ctx.session().isModified()) ctx.runCommand(std::exchange(pendingCommand_, {}), false);
    }
    tip("Replace the file with this document");
    ImGui::SameLine();
    if (widget::Button("Save As##changed.saveas", ImVec2(120, 0))) {
        changedPath_.clear();
        closeShown();
        runPendingAfterSave_ = !pendingCommand_.empty();  // a New / Open / Quit that asked goes on once written
        openFileDialog(FileDialogKind::SaveAs, ctx.session().doc.name);
        ctx.wake();
    }
    tip("Save under another name; the changed file stays as it is");
    ImGui::SameLine();
    if (widget::Button("Cancel##changed.cancel", ImVec2(120, 0)) || ctx.keyPressed(GLFW_KEY_ESCAPE, 0)) {
        changedPath_.clear();
        pendingCommand_.clear();
        closeShown();
    }
    tip("Keep editing; nothing is written");
    ImGui::EndPopup();
}

void Dialogs::drawRecover(const std::function<void()>& recoverFirst) {
    if (!beginCentredModal(modalPopupName(Modal::Recover))) return;
    if (recoverable.empty()) {  // the offer was withdrawn
        closeShown();
        ImGui::EndPopup();
        return;
    }
    {
        const AutosaveEntry& e = recoverable.front();
        ImGui::Text("Patchwork did not exit cleanly. An autosave of %s exists.",
                    e.originalPath.empty() ? "an untitled document" : e.originalPath.c_str());
        ImGui::TextDisabled("%s", e.document.string().c_str());
    }
    const bool recover = widget::Button("Recover##recover", ImVec2(120, 0));
    if (recover) {
        closeShown();
        recoverFirst();
    }
    tip("Open the autosaved document (marked modified; save it to keep it)");
    ImGui::SameLine();
    if (ImGui::Button("Discard", ImVec2(120, 0))) {
        for (const AutosaveEntry& e : recoverable) removeAutosave(e);
        recoverable.clear();
        closeShown();
    }
    tip("Delete the autosave");
    ImGui::SameLine();
    if (ImGui::Button("Later", ImVec2(120, 0))) closeShown();
    tip("Keep the autosave for the next start");
    ImGui::EndPopup();
}

}  // namespace panels
}  // namespace pw::ui

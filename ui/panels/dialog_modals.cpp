// The modal prompts (ui/panels/dialogs.hpp): an error message, the unsaved-changes prompt (Save, Discard or
// Cancel; the first two go on with the command that asked), and the offer to recover an autosave.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <utility>

#include "core/io/document_io.hpp"
#include "ui/panels/dialogs.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {
namespace {

// Opens the modal `name` when `openRequest` is set (and clears it), centred in the window; true
// while it is shown (then the caller draws it and calls ImGui::EndPopup).
bool beginCentredModal(const char* name, bool& openRequest) {
    if (std::exchange(openRequest, false)) ImGui::OpenPopup(name);
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    return widget::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

}  // namespace

void Dialogs::askToDiscard(const std::vector<std::string>& words) {
    pendingCommand_ = words;
    openUnsavedPrompt_ = true;
}

void Dialogs::showError(const std::string& message) {
    errorMessage_ = message;
    openError_ = true;
}

void Dialogs::offerRecovery(std::vector<AutosaveEntry> entries) {
    recoverable = std::move(entries);
    offerRecovery_ = !recoverable.empty();
}

void Dialogs::drawModals(PanelContext& ctx, const std::function<void()>& recoverFirst) {
    if (beginCentredModal("Error##error", openError_)) {
        ImGui::PushTextWrapPos(560.0f);
        ImGui::TextUnformatted(errorMessage_.c_str());
        ImGui::PopTextWrapPos();
        const bool ok = widget::Button("OK##error.ok", ImVec2(120, 0));
        // Enter closes it, but not the Enter that caused it (a numeric field submitted this frame).
        if (ok || (ctx.keyPressed(GLFW_KEY_ENTER, 0) && !ImGui::IsWindowAppearing())) {
            errorMessage_.clear();
            ImGui::CloseCurrentPopup();
        }
        tip("Close this message");
        ImGui::EndPopup();
    }

    if (beginCentredModal("Unsaved changes##unsaved", openUnsavedPrompt_)) {
        ImGui::Text("Save changes to %s?", ctx.session().path().empty() ? "the untitled document" : ctx.session().path().c_str());
        const bool save = widget::Button("Save##unsaved.save", ImVec2(100, 0));
        if (save) {
            ImGui::CloseCurrentPopup();
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
            ImGui::CloseCurrentPopup();
            ctx.runCommand(std::exchange(pendingCommand_, {}), false);
        }
        tip("Continue and lose the changes");
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(100, 0)) || ctx.keyPressed(GLFW_KEY_ESCAPE, 0)) {
            pendingCommand_.clear();
            ImGui::CloseCurrentPopup();
        }
        tip("Keep editing");
        ImGui::EndPopup();
    }

    if (beginCentredModal("Recover autosave##recover", offerRecovery_)) {
        if (!recoverable.empty()) {
            const AutosaveEntry& e = recoverable.front();
            ImGui::Text("Patchwork did not exit cleanly. An autosave of %s exists.",
                        e.originalPath.empty() ? "an untitled document" : e.originalPath.c_str());
            ImGui::TextDisabled("%s", e.document.string().c_str());
        }
        const bool recover = widget::Button("Recover##recover", ImVec2(120, 0));
        if (recover) {
            ImGui::CloseCurrentPopup();
            recoverFirst();
        }
        tip("Open the autosaved document (marked modified; save it to keep it)");
        ImGui::SameLine();
        if (ImGui::Button("Discard", ImVec2(120, 0))) {
            for (const AutosaveEntry& e : recoverable) removeAutosave(e);
            recoverable.clear();
            ImGui::CloseCurrentPopup();
        }
        tip("Delete the autosave");
        ImGui::SameLine();
        if (ImGui::Button("Later", ImVec2(120, 0))) ImGui::CloseCurrentPopup();
        tip("Keep the autosave for the next start");
        ImGui::EndPopup();
    }
}

}  // namespace panels
}  // namespace pw::ui

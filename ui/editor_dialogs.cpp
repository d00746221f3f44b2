// The editor's file browser (Open, Import, Save As, Export glTF, Screenshot) and its modal dialogs:
// errors, the unsaved-changes prompt (its answer runs the pending command), autosave recovery.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include <imgui.h>

#include "core/document_io.hpp"
#include "ui/editor.hpp"
#include "ui/imgui_tip.hpp"
#include "core/limits.hpp"

namespace pw::ui {

namespace fs = std::filesystem;

void Editor::drawFileDialog() {
    if (fileMode_ == FileDialogMode::None) return;
    const char* titles[] = {"", "Open", "Save As", "Import", "Export glTF", "Save Screenshot"};
    const char* title = titles[int(fileMode_)];
    ImGui::OpenPopup("File browser");
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, io.DisplaySize.x - 40), std::min(480.0f, io.DisplaySize.y - 40)), ImGuiCond_Always);
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("File browser", nullptr, ImGuiWindowFlags_NoResize)) return;
    openModal_ = "file";
    bool doubleClicked = false;
    ImGui::Text("%s: %s", title, browseDir_.string().c_str());
    if (ImGui::Button("Up")) browseDir_ = browseDir_.parent_path();
    tip("Parent directory");
    ImGui::BeginChild("entries", ImVec2(0, -90), true);
    std::vector<fs::directory_entry> entries;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(browseDir_, ec)) entries.push_back(e);
    std::sort(entries.begin(), entries.end(), [](const fs::directory_entry& a, const fs::directory_entry& b) {
        if (a.is_directory() != b.is_directory()) return a.is_directory();
        return a.path().filename() < b.path().filename();
    });
    for (const fs::directory_entry& e : entries) {
        const std::string name = e.path().filename().string();
        if (!name.empty() && name[0] == '.') continue;
        if (e.is_directory(ec)) {
            if (ImGui::Selectable((name + "/").c_str(), false, ImGuiSelectableFlags_AllowDoubleClick)) browseDir_ = e.path();
        } else if (ImGui::Selectable(name.c_str(), name == fileName_, ImGuiSelectableFlags_AllowDoubleClick)) {
            std::snprintf(fileName_, sizeof fileName_, "%s", name.c_str());
            doubleClicked = ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
        }
    }
    if (ec) ImGui::TextDisabled("(cannot list: %s)", ec.message().c_str());
    ImGui::EndChild();
    ImGui::InputText("File name", fileName_, sizeof fileName_);
    traceItem("file.name");
    tip("Name in the directory above, or an absolute path");
    if (fileMode_ == FileDialogMode::ExportGltf || fileMode_ == FileDialogMode::SaveAs) {
        ImGui::SetNextItemWidth(120);
        ImGui::SliderInt("Export level", &exportOptions_.level, 0, limits::kMaxExportLevel);
        tip("glTF tessellation level (0: the document's level)");
        ImGui::SameLine();
        ImGui::Checkbox("Merge", &exportOptions_.merge);
        tip("One mesh primitive for everything");
        ImGui::SameLine();
        ImGui::Checkbox("Cage", &exportOptions_.cage);
        tip("Also export the control cage as lines");
    }
    const bool ok = ImGui::Button("OK", ImVec2(100, 0)) || doubleClicked;
    traceItem("file.ok");
    tip("Confirm");
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel", ImVec2(100, 0)) || keyPressed(GLFW_KEY_ESCAPE, 0);
    tip("Close without doing anything");
    if (ok && fileName_[0]) {
        fs::path p = fileName_;
        if (p.is_relative()) p = browseDir_ / p;
        const FileDialogMode m = fileMode_;
        fileMode_ = FileDialogMode::None;
        ImGui::CloseCurrentPopup();
        // The unsaved-changes prompt came before the Open dialog: the open itself is unguarded.
        if (m == FileDialogMode::Open) runCommand({"open", p.string()}, false);
        else if (m == FileDialogMode::Import) runCommand({"import", p.string()});
        else if (m == FileDialogMode::ExportGltf) runCommand({"export-gltf", p.string()});
        else if (m == FileDialogMode::Screenshot) runCommand({"screenshot", p.string()});
        else if (m == FileDialogMode::SaveAs) {
            runCommand({"save", p.string()});
            // Save from the unsaved-changes prompt of an untitled document: go on with New / Open / Quit.
            if (runPendingAfterSave_ && !isModified()) runCommand(std::exchange(pendingCommand_, {}), false);
            runPendingAfterSave_ = false;
        }
    } else if (cancel) {
        fileMode_ = FileDialogMode::None;
        runPendingAfterSave_ = false;
        pendingCommand_.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void Editor::drawModals() {
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 centre(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f);
    if (openError_) {
        ImGui::OpenPopup("Error");
        openError_ = false;
    }
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        openModal_ = "error";
        ImGui::PushTextWrapPos(560.0f);
        ImGui::TextUnformatted(errorMessage_.c_str());
        ImGui::PopTextWrapPos();
        const bool ok = ImGui::Button("OK", ImVec2(120, 0));
        traceItem("error.ok");
        // Enter closes it, but not the Enter that caused it (a numeric field submitted this frame).
        if (ok || (keyPressed(GLFW_KEY_ENTER, 0) && !ImGui::IsWindowAppearing())) {
            errorMessage_.clear();
            ImGui::CloseCurrentPopup();
        }
        tip("Close this message");
        ImGui::EndPopup();
    }

    if (openUnsavedPrompt_) {
        ImGui::OpenPopup("Unsaved changes");
        openUnsavedPrompt_ = false;
    }
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        openModal_ = "unsaved";
        ImGui::Text("Save changes to %s?", session_.path().empty() ? "the untitled document" : session_.path().c_str());
        if (ImGui::Button("Save", ImVec2(100, 0))) {
            ImGui::CloseCurrentPopup();
            if (!session_.path().empty() && saveKeepsEverything(session_.path())) {
                runCommand(std::vector<std::string>{"save"});
                if (!isModified()) runCommand(std::exchange(pendingCommand_, {}), false);
            } else {
                runPendingAfterSave_ = true;  // the Save As dialog goes on with the command once written
                fileDialog(FileDialogKind::SaveAs);
            }
        }
        tip("Save, then continue");
        ImGui::SameLine();
        const bool discard = ImGui::Button("Discard", ImVec2(100, 0));
        traceItem("unsaved.discard");
        if (discard) {
            ImGui::CloseCurrentPopup();
            runCommand(std::exchange(pendingCommand_, {}), false);
        }
        tip("Continue and lose the changes");
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(100, 0)) || keyPressed(GLFW_KEY_ESCAPE, 0)) {
            pendingCommand_.clear();
            ImGui::CloseCurrentPopup();
        }
        tip("Keep editing");
        ImGui::EndPopup();
    }

    if (offerRecovery_) {
        ImGui::OpenPopup("Recover autosave");
        offerRecovery_ = false;
    }
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Recover autosave", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (!recoverable_.empty()) {
            const AutosaveEntry& e = recoverable_.front();
            ImGui::Text("Patchwork did not exit cleanly. An autosave of %s exists.",
                        e.originalPath.empty() ? "an untitled document" : e.originalPath.c_str());
            ImGui::TextDisabled("%s", e.document.string().c_str());
        }
        openModal_ = "recover";
        const bool recover = ImGui::Button("Recover", ImVec2(120, 0));
        traceItem("recover");
        if (recover) {
            ImGui::CloseCurrentPopup();
            recoverAutosave();
        }
        tip("Open the autosaved document (marked modified; save it to keep it)");
        ImGui::SameLine();
        if (ImGui::Button("Discard", ImVec2(120, 0))) {
            for (const AutosaveEntry& e : recoverable_) removeAutosave(e);
            recoverable_.clear();
            ImGui::CloseCurrentPopup();
        }
        tip("Delete the autosave");
        ImGui::SameLine();
        if (ImGui::Button("Later", ImVec2(120, 0))) ImGui::CloseCurrentPopup();
        tip("Keep the autosave for the next start");
        ImGui::EndPopup();
    }
}

}  // namespace pw::ui

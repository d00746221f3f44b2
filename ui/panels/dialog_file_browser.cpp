// The file browser (ui/panels/dialogs.hpp): Open, Import, Save As, Export (glTF, OBJ, STEP; with the export options)
// and Save Screenshot; OK runs the matching command. One of the modals drawModals owns (dialog_modals.cpp).
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "core/base/limits.hpp"
#include "core/io/formats.hpp"
#include "ui/panels/dialogs.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

namespace fs = std::filesystem;

Dialogs::Dialogs() : browseDir_(fs::current_path()) {}

void Dialogs::openFileDialog(FileDialogKind kind, const std::string& documentName) {
    const std::string name = documentName.empty() ? "untitled" : documentName;
    fileName_[0] = 0;
    focusName_ = true;
    switch (kind) {
        case FileDialogKind::Open:
            fileMode_ = FileDialogMode::Open;
            break;
        case FileDialogKind::Import:
            fileMode_ = FileDialogMode::Import;
            break;
        case FileDialogKind::SaveAs:
            fileMode_ = FileDialogMode::SaveAs;
            std::snprintf(fileName_, sizeof fileName_, "%s.patchwork", name.c_str());
            break;
        case FileDialogKind::ExportGltf:
            fileMode_ = FileDialogMode::ExportGltf;
            std::snprintf(fileName_, sizeof fileName_, "%s.glb", name.c_str());
            break;
        case FileDialogKind::Screenshot:
            fileMode_ = FileDialogMode::Screenshot;
            std::snprintf(fileName_, sizeof fileName_, "screenshot.png");
            break;
        case FileDialogKind::DomainFigure:
            fileMode_ = FileDialogMode::DomainFigure;
            std::snprintf(fileName_, sizeof fileName_, "domain.svg");
            break;
        case FileDialogKind::HeightMap:
            fileMode_ = FileDialogMode::HeightMap;
            break;
        case FileDialogKind::SweepAnimation:
            fileMode_ = FileDialogMode::SweepAnimation;
            std::snprintf(fileName_, sizeof fileName_, "sweep.gif");
            break;
    }
    request(Modal::FileBrowser);
}

void Dialogs::drawFileBrowser(PanelContext& ctx) {
    static const std::string exportTitle = "Export (" + formatList(FormatUse::Export, ", ") + ")";  // the format table's
    const char* titles[] = {"",
                            "Open",
                            "Save As",
                            "Import",
                            exportTitle.c_str(),
                            "Save Screenshot",
                            "Save Domain Figure (.svg, .pdf, .png)",
                            "Save Sweep Animation (.gif, .mp4, .webm)",
                            "Load Height Map (.png)"};
    const char* title = titles[int(fileMode_)];
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, io.DisplaySize.x - 40), std::min(480.0f, io.DisplaySize.y - 40)), ImGuiCond_Always);
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (!widget::BeginPopupModal(modalPopupName(Modal::FileBrowser), nullptr, ImGuiWindowFlags_NoResize)) return;
    if (fileMode_ == FileDialogMode::None) {  // nothing to browse for
        closeShown();
        ImGui::EndPopup();
        return;
    }
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
    // As in any file dialog, the name field starts with the keyboard and its text selected: typing
    // replaces the offered name.
    if (std::exchange(focusName_, false)) ImGui::SetKeyboardFocusHere();
    widget::InputText("File name##file.name", fileName_, sizeof fileName_, ImGuiInputTextFlags_AutoSelectAll);
    tip("Name in the directory above, or an absolute path");
    if (fileMode_ == FileDialogMode::ExportGltf || fileMode_ == FileDialogMode::SaveAs) {
        ExportOptions& eo = ctx.session().exportOptions;
        widget::Checkbox("As displayed##file.as_displayed", &eo.asDisplayed);
        tip("The triangles the 3D view draws: the document's per-edge levels, partitioning, adaptive levels and\n"
            "culling from this camera, read back from the GPU's tessellator (glTF and OBJ)");
        ImGui::SameLine();
        if (eo.asDisplayed) ImGui::BeginDisabled();
        ImGui::SetNextItemWidth(120);
        ImGui::SliderInt("Export level", &eo.level, 0, limits::kMaxExportLevel);
        if (eo.asDisplayed) ImGui::EndDisabled();
        tip("glTF and OBJ tessellation level (0: the document's level)");
        ImGui::SameLine();
        {
            static const char* kPrimitives[] = {"Per surface", "Per patch", "Single"};
            int g = static_cast<int>(ctx.session().exportOptions.primitives);
            ImGui::SetNextItemWidth(110);
            if (ImGui::Combo("Primitives", &g, kPrimitives, 3)) ctx.session().exportOptions.primitives = static_cast<MeshGrouping>(g);
            tip("Per surface: one welded primitive per connected surface (what Blender and assimp expect)\n"
                "Per patch: one primitive per patch, each with its own vertices\nSingle: one primitive for everything");
        }
        ImGui::SameLine();
        ImGui::Checkbox("Cage", &ctx.session().exportOptions.cage);
        tip("Also export the control cage as lines");
    }
    const bool ok = widget::Button("OK##file.ok", ImVec2(100, 0)) || doubleClicked;
    tip("Confirm");
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel", ImVec2(100, 0)) || ctx.keyPressed(GLFW_KEY_ESCAPE, 0);
    tip("Close without doing anything");
    if (ok && fileName_[0]) {
        fs::path p = fileName_;
        if (p.is_relative()) p = browseDir_ / p;
        const FileDialogMode m = fileMode_;
        fileMode_ = FileDialogMode::None;
        closeShown();
        // The unsaved-changes prompt came before the Open dialog: the open itself is unguarded.
        if (m == FileDialogMode::Open)
            ctx.runCommand({"open", p.string()}, false);
        else if (m == FileDialogMode::Import)
            ctx.runCommand({"import", p.string()});
        else if (m == FileDialogMode::ExportGltf)
            ctx.runCommand({"export-gltf", p.string()});
        else if (m == FileDialogMode::Screenshot)
            ctx.runCommand({"screenshot", p.string()});
        else if (m == FileDialogMode::DomainFigure)
            ctx.runCommand({"domain-figure", p.string()});
        else if (m == FileDialogMode::SweepAnimation)
            ctx.runCommand({"sweep-animation", p.string()});
        else if (m == FileDialogMode::HeightMap)
            ctx.runCommand({"displacement", p.string()});
        else if (m == FileDialogMode::SaveAs) {
            ctx.runCommand({"save", p.string()});
            // Save from the unsaved-changes prompt of an untitled document: go on with New / Open / Quit.
            if (runPendingAfterSave_ && !ctx.session().isModified()) ctx.runCommand(std::exchange(pendingCommand_, {}), false);
            runPendingAfterSave_ = false;
        }
    } else if (cancel) {
        fileMode_ = FileDialogMode::None;
        runPendingAfterSave_ = false;
        pendingCommand_.clear();
        closeShown();
    }
    ImGui::EndPopup();
}

}  // namespace panels
}  // namespace pw::ui

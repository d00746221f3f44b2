// The shader panel: the GLSL of the tessellation pipelines the current settings draw with (surface,
// triangles, wireframe, normal vectors, domain panes), stage by stage, read-only, with the glslc
// defines of each variant and the lines those defines switch off dimmed (render/shader_listing).
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <string>

#include "ui/editor.hpp"
#include "ui/imgui_tip.hpp"

namespace pw::ui {

namespace {

std::string tabLabel(const std::string& stage) {
    if (stage == "tessellation control") return "Tess control";
    if (stage.starts_with("tessellation evaluation")) return stage.size() > 23 ? "Tess eval (dots)" : "Tess evaluation";
    std::string s = stage;
    s[0] = char(std::toupper(static_cast<unsigned char>(s[0])));
    return s;
}

std::string listingText(const render::ShaderListing& l, bool activeOnly) {
    std::string text = "// " + l.variant + ": " + l.source + ", glslc";
    for (const auto& d : l.defines) text += " " + d;
    text += "\n";
    for (const auto& line : l.lines)
        if (line.active || !activeOnly) text += line.text + "\n";
    return text;
}

}  // namespace

void Editor::drawShaderWindow() {
    shaderShown_.clear();
    shaderVariantsInUse_.clear();
    if (!showShaders_) return;
    // First placed below where the domain view opens, between the side panels, so that the model,
    // the domain and the source are all in sight.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float top = std::min(ImGui::GetFrameHeight() + 16.0f + 440.0f * uiScale_, display.y * 0.5f);
    const float width = std::max(320.0f, display.x - leftPanelWidth_ - rightPanelWidth_ - 32.0f);
    ImGui::SetNextWindowPos(ImVec2(leftPanelWidth_ + 16.0f, top), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(width, std::max(200.0f, display.y - top - 16.0f)), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Shaders", &showShaders_)) {
        ImGui::End();
        return;
    }
    render::ShaderContext c;
    c.tess = doc_.tess;
    c.display = doc_.display;
    c.windows = !doc_.patches.empty() || !doc_.surfaces.empty();
    c.triangles = !doc_.triangles.empty();
    c.curves = !doc_.curves.empty();
    c.geometryShader = dev_->caps().geometryShader;
    for (const auto& o : domainPanes_) c.domainPanes.emplace_back(o.kind, o.spacing);
    const std::vector<render::PipelineUse> pipes = render::pipelinesInUse(c);
    for (const auto& p : pipes)
        for (const auto& s : p.stages) shaderVariantsInUse_.push_back(s.variant);
    if (pipes.empty()) {
        ImGui::TextWrapped("Nothing is tessellated: the document is empty and the domain view is closed.");
        ImGui::End();
        return;
    }
    const render::PipelineUse* pipe = &pipes.front();
    for (const auto& p : pipes)
        if (p.name == shaderPipeline_) pipe = &p;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    if (ImGui::BeginCombo("Pipeline", pipe->name.c_str())) {
        for (const auto& p : pipes)
            if (ImGui::Selectable(p.name.c_str(), &p == pipe)) {
                shaderPipeline_ = p.name;
                pipe = &p;
            }
        ImGui::EndCombo();
    }
    traceItem("shaders.pipeline");
    tip("The pipelines drawn with the current settings; wireframe, normals and the domain view add theirs");
    ImGui::SameLine();
    ImGui::Checkbox("Hide switched-off lines", &shaderHideInactive_);
    traceItem("shaders.hide");
    tip("Leave out the #ifdef branches this variant's defines switch off (shown dimmed otherwise)");
    ImGui::TextWrapped("%s", pipe->why.c_str());

    if (ImGui::BeginTabBar("stages")) {
        for (const auto& stage : pipe->stages) {
            const bool open = ImGui::BeginTabItem((tabLabel(stage.stage) + "##" + stage.stage).c_str());
            traceItem("shaders.tab." + stage.variant);
            if (!open) continue;
            auto it = shaderListings_.find(stage.variant);
            if (it == shaderListings_.end()) {
                auto l = render::shaderListing(stage.variant);
                it = shaderListings_.emplace(stage.variant, l ? std::move(*l) : render::ShaderListing{stage.variant, "?", {}, {}}).first;
            }
            const render::ShaderListing& l = it->second;
            shaderShown_ = l.variant;
            std::string defs;
            for (const auto& d : l.defines) defs += (defs.empty() ? "" : " ") + d;
            ImGui::Text("%s  (%s)", l.source.c_str(), l.variant.c_str());
            ImGui::SameLine();
            if (ImGui::SmallButton("Copy")) ImGui::SetClipboardText(listingText(l, shaderHideInactive_).c_str());
            tip("Copy this stage's source (with the defines as a first comment line) to the clipboard");
            ImGui::TextDisabled("defines: %s", defs.empty() ? "(none)" : defs.c_str());
            ImGui::BeginChild("source", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
            std::vector<int> shown;
            shown.reserve(l.lines.size());
            for (size_t i = 0; i < l.lines.size(); ++i)
                if (l.lines[i].active || !shaderHideInactive_) shown.push_back(int(i));
            const ImVec4 dim = ImGui::GetStyle().Colors[ImGuiCol_TextDisabled];
            const ImVec4 included(0.55f, 0.75f, 0.95f, 1.0f);
            ImGuiListClipper clipper;
            clipper.Begin(int(shown.size()));
            while (clipper.Step())
                for (int k = clipper.DisplayStart; k < clipper.DisplayEnd; ++k) {
                    const render::ListingLine& line = l.lines[size_t(shown[size_t(k)])];
                    ImGui::TextDisabled("%4d", line.line);
                    ImGui::SameLine();
                    const bool tint = !line.active || line.depth > 0;
                    if (tint) ImGui::PushStyleColor(ImGuiCol_Text, line.active ? included : dim);
                    ImGui::TextUnformatted(line.text.empty() ? " " : line.text.c_str());
                    if (tint) ImGui::PopStyleColor();
                    if (line.depth > 0 && ImGui::IsItemHovered()) ImGui::SetTooltip("%s line %d (included)", line.file.c_str(), line.line);
                }
            ImGui::EndChild();
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::End();
}

}  // namespace pw::ui

// The Shaders window (ui/panels/panel_shaders.hpp): the GLSL of the pipelines in use, a tab per stage.
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <string>

#include "ui/panels/panel_shaders.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

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

void ShaderPanel::draw(PanelContext& ctx, bool geometryShader, const TessSettings& shownTess,
                       const std::vector<render::DomainViewOptions>& domainPanes) {
    shown.clear();
    shownLines = 0;
    variantsInUse.clear();
    if (!open) return;
    // First placed below where the domain view opens, between the side panels, so that the model,
    // the domain and the source are all in sight.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float top = std::min(ImGui::GetFrameHeight() + 16.0f + 440.0f * ctx.uiScale(), display.y * 0.5f);
    const float width = std::max(320.0f, display.x - ctx.layout().left - ctx.layout().right - 32.0f);
    ImGui::SetNextWindowPos(ImVec2(ctx.layout().left + 16.0f, top), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(width, std::max(200.0f, display.y - top - 16.0f)), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Shaders", &open)) {
        ImGui::End();
        return;
    }
    render::ShaderContext c;
    c.tess = shownTess;  // a preset or sweep of the Teaching panel shows its own levels
    c.display = ctx.session().doc.display;
    c.windows = !ctx.session().doc.patches.empty() || !ctx.session().doc.surfaces.empty();
    c.triangles = !ctx.session().doc.triangles.empty();
    c.curves = !ctx.session().doc.curves.empty();
    c.geometryShader = geometryShader;
    for (const auto& o : domainPanes) c.domainPanes.emplace_back(o.kind, o.spacing);
    const std::vector<render::PipelineUse> pipes = render::pipelinesInUse(c);
    for (const auto& p : pipes)
        for (const auto& s : p.stages) variantsInUse.push_back(s.variant);
    if (pipes.empty()) {
        ImGui::TextWrapped("Nothing is tessellated: the document is empty and the domain view is closed.");
        ImGui::End();
        return;
    }
    const render::PipelineUse* pipe = &pipes.front();
    for (const auto& p : pipes)
        if (p.name == pipeline_) pipe = &p;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    if (widget::BeginCombo("Pipeline##shaders.pipeline", pipe->name.c_str())) {
        for (const auto& p : pipes)
            if (ImGui::Selectable(p.name.c_str(), &p == pipe)) {
                pipeline_ = p.name;
                pipe = &p;
            }
        widget::EndCombo("Pipeline##shaders.pipeline");
    }
    tip("The pipelines drawn with the current settings; wireframe, normals and the domain view add theirs");
    widget::Checkbox("Teaching listing##shaders.teaching", &teaching);
    tip("Only the parts a slide shows (the Bernstein sum, the tessellator's layout, main), with the defines substituted; the "
        "stages without marked parts are listed whole");
    ImGui::SameLine();
    widget::Checkbox("Hide switched-off lines##shaders.hide", &hideInactive_);
    tip("Leave out the #ifdef branches this variant's defines switch off (shown dimmed otherwise)");
    ImGui::TextWrapped("%s", pipe->why.c_str());

    if (ImGui::BeginTabBar("stages")) {
        for (const auto& stage : pipe->stages) {
            // The tab keeps its id by stage (the selected stage stays when the variant changes).
            const bool open =
                widget::BeginTabItem((tabLabel(stage.stage) + "##shaders.tab." + stage.variant + "###" + stage.stage).c_str());
            if (!open) continue;
            auto it = listings_.find(stage.variant);
            if (it == listings_.end()) {
                auto l = render::shaderListing(stage.variant);
                it = listings_.emplace(stage.variant, l ? std::move(*l) : render::ShaderListing{stage.variant, "?", {}, {}}).first;
            }
            const render::ShaderListing& l = it->second;
            shown = l.variant;
            std::string defs;
            for (const auto& d : l.defines) defs += (defs.empty() ? "" : " ") + d;
            ImGui::Text("%s  (%s)", l.source.c_str(), l.variant.c_str());
            ImGui::SameLine();
            if (ImGui::SmallButton("Copy")) ImGui::SetClipboardText(listingText(l, hideInactive_).c_str());
            tip("Copy this stage's source (with the defines as a first comment line) to the clipboard");
            ImGui::TextDisabled("defines: %s", defs.empty() ? "(none)" : defs.c_str());
            ImGui::BeginChild("source", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
            const std::vector<render::ListingLine> teachingLines =
                teaching ? render::teachingListing(l) : std::vector<render::ListingLine>{};
            const std::vector<render::ListingLine>& lines = teachingLines.empty() ? l.lines : teachingLines;
            std::vector<int> shown;
            shown.reserve(lines.size());
            for (size_t i = 0; i < lines.size(); ++i)
                if (lines[i].active || !hideInactive_) shown.push_back(int(i));
            shownLines = shown.size();
            const ImVec4 dim = ImGui::GetStyle().Colors[ImGuiCol_TextDisabled];
            const ImVec4 included(0.55f, 0.75f, 0.95f, 1.0f);
            ImGuiListClipper clipper;
            clipper.Begin(int(shown.size()));
            while (clipper.Step())
                for (int k = clipper.DisplayStart; k < clipper.DisplayEnd; ++k) {
                    const render::ListingLine& line = lines[size_t(shown[size_t(k)])];
                    if (line.line > 0)
                        ImGui::TextDisabled("%4d", line.line);
                    else
                        ImGui::TextDisabled("    ");  // a teaching part's heading
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

}  // namespace panels
}  // namespace pw::ui

// Presentation mode's overlay (F5, ui/panels/teaching.hpp): the levels, the partitioning and the counts in
// large type, high contrast, no editing panels.
#include <imgui.h>

#include <algorithm>
#include <string>

#include "render/domain/domain_labels.hpp"
#include "ui/panels/teaching.hpp"
#include "ui/platform/app_window.hpp"
#include "ui/platform/imgui_layer.hpp"

namespace pw::ui {

void Teaching::drawPresentationOverlay(PanelContext& ctx) {
    const TessSettings ts = shownTess(ctx.session().doc.tess);
    const render::FrameStats& stats = ctx.frameReport().stats;
    ImGui::SetNextWindowPos(ImVec2(16.0f, 16.0f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("##presentation", nullptr, flags)) {
        ImGui::PushFont(window_.imgui().presentationFont());
        // The text scale is relative to an 800-pixel-high window: a projector's 1920 x 1080 gets
        // it larger, a 1024 x 640 window smaller, so the overlay keeps its share of the screen.
        const float windowScale = std::clamp(ImGui::GetIO().DisplaySize.y / 800.0f, 0.6f, 3.0f);
        ImGui::SetWindowFontScale(presentationScale / 3.0f * windowScale);
        ImGui::BeginGroup();  // one item around the lines: where the widest ends (the test trace checks it fits)
        if (lesson.active) ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.1f, 1.0f), "%s", lesson.name.c_str());
        ImGui::Text("outer %s  %s  %s  %s", render::formatLevel(ts.outer[0]).c_str(), render::formatLevel(ts.outer[1]).c_str(),
                    render::formatLevel(ts.outer[2]).c_str(), render::formatLevel(ts.outer[3]).c_str());
        ImGui::Text("inner %s  %s", render::formatLevel(ts.inner[0]).c_str(), render::formatLevel(ts.inner[1]).c_str());
        ImGui::TextColored(
            ImVec4(1.0f, 0.85f, 0.1f, 1.0f), "%s%s", spacingName(ts.spacing).data(),
            ts.adaptive == AdaptiveMode::None ? "" : (std::string(", adaptive ") + adaptiveName(ts.adaptive).data()).c_str());
        ImGui::Text("%llu triangles", static_cast<unsigned long long>(stats.triangles()));
        ImGui::Text("%llu evaluations", static_cast<unsigned long long>(stats.tesInvocations));
        if (sweep.playing) ImGui::Text("sweep %.2f", double(sweep.level));
        ImGui::EndGroup();
        const float textRight = ImGui::GetItemRectMax().x;
        ImGui::PopFont();
        // Auto-resize fits the window to last frame's text: while it is still growing (the scale
        // just changed), draw another frame so the text is never left clipped.
        const ImVec2 size = ImGui::GetWindowSize();
        if (size.x != overlaySize[0] || size.y != overlaySize[1]) ctx.wake();
        overlaySize = {size.x, size.y};
        overlayTextRight = textRight - ImGui::GetWindowPos().x;
    }
    ImGui::End();
}

}  // namespace pw::ui

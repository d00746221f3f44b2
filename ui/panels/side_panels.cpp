// The side panels' windows and what goes in them, in order (ui/panels/side_panels.hpp).
#include "ui/panels/side_panels.hpp"

#include <imgui.h>

#include <algorithm>

#include "ui/panels/teaching.hpp"

namespace pw::ui {
inline namespace panels {

void SidePanels::begin(const char* name, float x, float width) {
    const ImGuiIO& io = ImGui::GetIO();
    const float top = ImGui::GetFrameHeight();
    const std::array<float, 4> rect{x, top, width, io.DisplaySize.y - top};
    ImGui::SetNextWindowPos(ImVec2(rect[0], rect[1]));
    ImGui::SetNextWindowSize(ImVec2(rect[2], rect[3]));
    ImGui::SetNextWindowBgAlpha(0.0f);  // the overlay pass fills it (fills_)
    fills_.push_back(rect);
    ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
}

void SidePanels::drawLeft(PanelContext& ctx) {
    const ImGuiIO& io = ImGui::GetIO();
    const float w = std::min(300.0f * ctx.uiScale(), io.DisplaySize.x * 0.3f);
    layout_.left = w;
    begin("Scene", 0.0f, w);
    drawOutliner(ctx);
    inspector.draw(ctx);
    patchOps_.draw(ctx);
    net_.draw(ctx);
    surfaces_.draw(ctx);
    ImGui::End();
}

void SidePanels::drawRight(PanelContext& ctx, Teaching& teaching) {
    const ImGuiIO& io = ImGui::GetIO();
    const float w = std::min(330.0f * ctx.uiScale(), io.DisplaySize.x * 0.3f);
    layout_.right = w;
    begin("Properties", io.DisplaySize.x - w, w);
    // Room right of the widgets for the longest label, so no label is clipped in a narrow window.
    ImGui::PushItemWidth(-(ImGui::CalcTextSize("Normal length").x + 2.0f * ImGui::GetStyle().ItemInnerSpacing.x));
    drawTessellationPanel(ctx);
    drawDisplayPanel(ctx);
    drawDisplacementPanel(ctx);
    drawStatsPanel(ctx.frameReport());
    continuity_.draw(ctx);
    teaching.drawControls(ctx);
    ImGui::PopItemWidth();
    ImGui::End();
}

}  // namespace panels
}  // namespace pw::ui

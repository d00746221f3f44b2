// The 3D view split into the teaching panes (ui/panels/teaching.hpp): where the panes are, the pane the
// mouse works in, one render per pane with its own partitioning and level under one camera, and
// each pane's caption (partitioning, level, triangles).
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <string>

#include "render/figures/domain_figure.hpp"
#include "render/figures/stage_bars.hpp"
#include "render/scene/renderer.hpp"
#include "ui/panels/teaching.hpp"
#include "ui/platform/app_window.hpp"
#include "ui/platform/imgui_layer.hpp"

namespace pw::ui {
inline namespace panels {

std::vector<std::array<float, 4>> Teaching::viewPaneRects(const PanelLayout& layout) const {
    const ImGuiIO& io = ImGui::GetIO();
    if (!viewSplit()) return {{0.0f, 0.0f, io.DisplaySize.x, io.DisplaySize.y}};
    // Between the side panels and below the menu bar (in presentation mode, the whole window right
    // of the levels box, which lists every pane's counts).
    const float left = presentation ? presentationLeft() : layout.left, right = presentation ? 0.0f : layout.right;
    const float top = presentation ? 0.0f : ImGui::GetFrameHeight();
    const float w = std::max(io.DisplaySize.x - left - right, 64.0f), h = std::max(io.DisplaySize.y - top, 64.0f);
    return render::splitPanes(paneCount, {left, top, w, h});
}

std::array<float, 4> Teaching::interactionPane(const PanelLayout& layout, double mx, double my, bool hold) {
    const auto rects = viewPaneRects(layout);
    if (!hold)
        for (size_t i = 0; i < rects.size(); ++i) {
            const auto& r = rects[i];
            if (mx >= r[0] && mx < r[0] + r[2] && my >= r[1] && my < r[1] + r[3]) activePane = int(i);
        }
    activePane = std::clamp(activePane, 0, int(rects.size()) - 1);
    return rects[size_t(activePane)];
}

render::FrameStats Teaching::renderView(render::Renderer& renderer, const render::RenderOptions& o, const PanelLayout& layout) {
    viewPanes.clear();
    viewTess = o.tess;
    if (!viewSplit()) return renderer.render(o);
    const ImGuiIO& io = ImGui::GetIO();
    const float sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
    const auto rects = viewPaneRects(layout);
    for (size_t i = 0; i < rects.size(); ++i) {
        const std::array<float, 4> fb{rects[i][0] * sx, rects[i][1] * sy, rects[i][2] * sx, rects[i][3] * sy};
        const render::ModelPane pane{kPaneSpacings[size_t(paneSpacing[i])], paneLevel[i]};
        const render::RenderOptions po = render::paneOptions(o, pane, fb, i);
        viewPanes.push_back({po.tess, po.pane, renderer.render(po)});
    }
    return viewPanes.front().stats;
}

void Teaching::drawPaneCaptions(const PanelLayout& layout) {
    if (!viewSplit()) return;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    ImFont* font = presentation && window_.imgui().presentationFont() ? window_.imgui().presentationFont() : ImGui::GetFont();
    const float size = presentation ? presentationTextPixels() : ImGui::GetFontSize();
    const auto rects = viewPaneRects(layout);
    for (size_t i = 0; i < rects.size() && i < viewPanes.size(); ++i) {
        const auto& r = rects[i];
        const std::string text = render::paneCaption(viewPanes[i].tess, viewPanes[i].stats.triangles(), true);
        const ImVec2 ts2 = font->CalcTextSizeA(size, FLT_MAX, 0.0f, text.c_str());
        // Top centre; at the bottom in presentation mode.
        const ImVec2 at(r[0] + 0.5f * (r[2] - ts2.x), presentation ? r[1] + r[3] - ts2.y - 12.0f : r[1] + 8.0f);
        dl->AddRectFilled(ImVec2(at.x - 6.0f, at.y - 3.0f), ImVec2(at.x + ts2.x + 6.0f, at.y + ts2.y + 3.0f), IM_COL32(0, 0, 0, 150), 4.0f);
        dl->AddText(font, size, at, presentation ? IM_COL32(255, 220, 40, 255) : IM_COL32(235, 235, 235, 255), text.c_str());
        if (i > 0 || r[0] > 0.0f)  // a thin line between panes
            dl->AddLine(ImVec2(r[0], r[1]), ImVec2(r[0], r[1] + r[3]), IM_COL32(150, 150, 150, 200));
        if (r[1] > (presentation ? 0.0f : ImGui::GetFrameHeight()) + 1.0f)
            dl->AddLine(ImVec2(r[0], r[1]), ImVec2(r[0] + r[2], r[1]), IM_COL32(150, 150, 150, 200));
    }
}

void Teaching::drawStageBars(const PanelLayout& layout, const render::FrameStats& single) {
    stageBarRows = 0;
    if (!stageBars) return;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    ImFont* font = presentation && window_.imgui().presentationFont() ? window_.imgui().presentationFont() : ImGui::GetFont();
    const float px = presentation ? presentationTextPixels() * 0.8f : ImGui::GetFontSize();
    const auto rects = viewPaneRects(layout);
    for (size_t i = 0; i < rects.size(); ++i) {
        const auto counts = render::stageCounts(viewSplit() ? (i < viewPanes.size() ? viewPanes[i].stats : render::FrameStats{}) : single);
        if (counts.empty()) continue;
        // Right of the panes' left edge, clear of the right panel when it is there.
        const float right = viewSplit() || presentation ? rects[i][0] + rects[i][2] : ImGui::GetIO().DisplaySize.x - layout.right;
        // Bottom right, clear of the captions at the top; presenting, top right (the captions are at the bottom).
        const render::StageBarsLayout l = render::layoutStageBars(
            counts, px, [&](const std::string& t) { return font->CalcTextSizeA(px, FLT_MAX, 0.0f, t.c_str()).x; },
            {rects[i][0], rects[i][1], right - rects[i][0], rects[i][3]}, presentation);
        dl->AddRectFilled(ImVec2(l.box[0], l.box[1]), ImVec2(l.box[0] + l.box[2], l.box[1] + l.box[3]), IM_COL32(0, 0, 0, 170), 4.0f);
        for (size_t k = 0; k < counts.size(); ++k) {
            const render::StageBarsLayout::Row& r = l.rows[k];
            const auto c = render::stageColor(k);
            dl->AddText(font, px, ImVec2(r.labelX, r.textY - 0.5f * px), IM_COL32(235, 235, 235, 255), counts[k].stage.c_str());
            dl->AddRectFilled(ImVec2(r.bar[0], r.bar[1]), ImVec2(r.bar[2], r.bar[3]), IM_COL32(c[0], c[1], c[2], 255));
            dl->AddText(font, px, ImVec2(r.numberX, r.textY - 0.5f * px), IM_COL32(235, 235, 235, 255), r.number.c_str());
            ++stageBarRows;
        }
    }
}

}  // namespace panels
}  // namespace pw::ui

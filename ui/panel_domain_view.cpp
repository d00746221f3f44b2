// The domain view window (ui/teaching.hpp): the quad, triangle or isoline domain tessellated by the
// GPU with the document's levels in 1, 2 or 4 panes, drawn into a background-less window before
// the ImGui pass, with each edge's level and the vertex and triangle counts labelled by ImGui.
#include <imgui.h>

#include "render/domain_figure.hpp"
#include "render/domain_labels.hpp"
#include "render/swapchain_target.hpp"
#include "ui/app_window.hpp"
#include "ui/teaching.hpp"

namespace pw::ui {

void Teaching::drawDomainWindow(PanelContext& ctx) {
    domainPanes.clear();
    if (!showDomain) return;
    const ImGuiIO& io = ImGui::GetIO();
    const PanelLayout& layout = ctx.layout();
    const Document& doc = ctx.session().doc;
    ImGui::SetNextWindowPos(ImVec2(layout.left + 16.0f, ImGui::GetFrameHeight() + 16.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(430.0f * ctx.uiScale(), 430.0f * ctx.uiScale()), ImGuiCond_FirstUseEver);
    // No window background: the GPU draws the domain into this rectangle before ImGui draws the
    // labels over it (drawDomainPanes).
    if (ImGui::Begin("Domain view", &showDomain, ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoScrollbar)) {
        const ImVec2 wp = ImGui::GetWindowPos(), a = ImGui::GetWindowContentRegionMin(), b = ImGui::GetWindowContentRegionMax();
        const std::array<float, 4> area{wp.x + a.x, wp.y + a.y, b.x - a.x, b.y - a.y};
        const auto rects = render::splitPanes(paneCount, area);
        const float px = ImGui::GetFontSize(), sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
        ImDrawList* dl = ImGui::GetWindowDrawList();
        for (size_t i = 0; i < rects.size(); ++i) {
            render::DomainViewOptions o;
            o.kind = DomainKind(domainKind);
            o.levels = {doc.tess.outer, doc.tess.inner};
            o.spacing = paneCount > 1 ? kPaneSpacings[paneSpacing[i]] : doc.tess.spacing;
            if (paneCount > 1 && paneLevel[i] > 0.0f) o.levels = withUniformLevel(o.levels, paneLevel[i]);
            o.rect = rects[i];
            o.margin = render::domainLabelMargin(px);
            const render::DomainPane pane{o.kind, o.levels, o.spacing};
            const auto counts = render::shownCounts(i < domainStats.size() ? domainStats[i] : render::DomainStats{}, pane);
            for (const render::DomainLabel& l : render::domainLabels(o, counts[0], counts[1], px)) {
                const ImVec2 size = ImGui::CalcTextSize(l.text.c_str());
                const ImU32 col = l.role == render::DomainLabel::Role::Edge ? IM_COL32(170, 30, 20, 255) : IM_COL32(25, 30, 40, 255);
                dl->AddText(ImVec2(l.x - l.ax * size.x, l.y - l.ay * size.y), col, l.text.c_str());
            }
            // In framebuffer pixels for the GPU pass.
            o.rect = {o.rect[0] * sx, o.rect[1] * sy, o.rect[2] * sx, o.rect[3] * sy};
            o.margin *= sx;
            o.pointSize = 4.0f * sx;
            domainPanes.push_back(o);
        }
    }
    ImGui::End();
}

void Teaching::drawDomainPanes() {
    if (domainPanes.empty()) return;
    if (!domainView_)
        domainView_ = std::make_unique<render::DomainView>(window_.device(), window_.target().colorFormat(), window_.target().depthFormat(), window_.target().samples());
    domainStats = domainView_->draw(window_.target(), domainPanes, false);
}

}  // namespace pw::ui

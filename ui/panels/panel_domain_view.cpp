// The domain view window (ui/panels/teaching.hpp): the quad, triangle or isoline domain tessellated by the
// GPU with the document's levels in 1, 2 or 4 panes, drawn into a background-less window before
// the ImGui pass, with each edge's level and the vertex and triangle counts labelled by ImGui.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "render/domain/domain_labels.hpp"
#include "render/figures/domain_figure.hpp"
#include "ui/panels/teaching.hpp"
#include "ui/platform/app_window.hpp"
#include "ui/platform/imgui_layer.hpp"
#include "ui/platform/swapchain_target.hpp"

namespace pw::ui {
inline namespace panels {

void Teaching::drawDomainWindow(PanelContext& ctx) {
    domainPanes.clear();
    domainCounts.clear();
    windowRect = {0, 0, 0, 0};
    labelBoxes.clear();
    if (!showDomain) return;
    const ImGuiIO& io = ImGui::GetIO();
    const PanelLayout& layout = ctx.layout();
    const TessSettings ts = shownTess(ctx.session().doc.tess);
    // Presentation mode: the whole window right of the levels box, no title bar; else a window
    // the user moves and sizes.
    ImGuiWindowFlags flags = ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoScrollbar;
    if (presentation) {
        const float x0 = presentationLeft();
        ImGui::SetNextWindowPos(ImVec2(x0, 4.0f));
        ImGui::SetNextWindowSize(ImVec2(std::max(160.0f, io.DisplaySize.x - x0 - 4.0f), std::max(160.0f, io.DisplaySize.y - 8.0f)));
        flags |= ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;
    } else {
        ImGui::SetNextWindowPos(ImVec2(layout.left + 16.0f, ImGui::GetFrameHeight() + 16.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(430.0f * ctx.uiScale(), 430.0f * ctx.uiScale()), ImGuiCond_FirstUseEver);
    }
    // No window background: the GPU draws the domain into this rectangle before ImGui draws the
    // labels over it (drawDomainPanes).
    if (ImGui::Begin("Domain view", &showDomain, flags)) {
        if (!presentation) {
            // Kept between the side panels and under the menu bar at any window size (the panels
            // would hide part of it, and the 3D view's axis gizmo moves out of its way).
            const float x0 = layout.left + 4.0f, x1 = io.DisplaySize.x - layout.right - 4.0f;
            const float y0 = ImGui::GetFrameHeight() + 4.0f, y1 = io.DisplaySize.y - 4.0f;
            const ImVec2 size(std::min(ImGui::GetWindowSize().x, std::max(160.0f, x1 - x0)),
                              std::min(ImGui::GetWindowSize().y, std::max(160.0f, y1 - y0)));
            if (size.x != ImGui::GetWindowSize().x || size.y != ImGui::GetWindowSize().y) ImGui::SetWindowSize(size);
            const ImVec2 pos(std::clamp(ImGui::GetWindowPos().x, x0, std::max(x0, x1 - size.x)),
                             std::clamp(ImGui::GetWindowPos().y, y0, std::max(y0, y1 - size.y)));
            if (pos.x != ImGui::GetWindowPos().x || pos.y != ImGui::GetWindowPos().y) ImGui::SetWindowPos(pos);
        }
        windowRect = {ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowSize().x, ImGui::GetWindowSize().y};
        const ImVec2 wp = ImGui::GetWindowPos(), a = ImGui::GetWindowContentRegionMin(), b = ImGui::GetWindowContentRegionMax();
        const std::array<float, 4> area{wp.x + a.x, wp.y + a.y, b.x - a.x, b.y - a.y};
        const auto rects = render::splitPanes(paneCount, area);
        // Labels, captions and vertex dots grow with presentation mode's text.
        ImFont* font = presentation && window_.imgui().presentationFont() ? window_.imgui().presentationFont() : ImGui::GetFont();
        const float px = presentation ? presentationTextPixels() : ImGui::GetFontSize();
        const float sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
        domainTextPixels = px;
        for (size_t i = 0; i < rects.size(); ++i) {
            render::DomainViewOptions o;
            o.kind = DomainKind(domainKind);
            o.levels = {ts.outer, ts.inner};
            o.spacing = paneCount > 1 ? kPaneSpacings[paneSpacing[i]] : ts.spacing;
            o.upperLeft = ctx.session().doc.display.domainUpperLeft;  // the document's convention (domain-origin)
            if (paneCount > 1 && paneLevel[i] > 0.0f) o.levels = withUniformLevel(o.levels, paneLevel[i]);
            o.rect = rects[i];
            o.margin = render::domainLabelMargin(px);
            // Dots grow with the text, but stay under a third of the shortest segment's length.
            const float finest = std::ceil(std::max(*std::max_element(o.levels.outer.begin(), o.levels.outer.end()),
                                                    *std::max_element(o.levels.inner.begin(), o.levels.inner.end())));
            o.pointSize =
                sx * std::clamp(placeDomain(o).size / std::max(finest + 1.0f, 1.0f) / 3.0f, 3.0f, 4.0f * px / ImGui::GetFontSize());
            domainPanes.push_back(o);
        }
        render::titleByPartitioning(domainPanes);
        ImDrawList* dl = ImGui::GetWindowDrawList();
        const auto measure = [&](const std::string& t, float size) { return font->CalcTextSizeA(size, FLT_MAX, 0.0f, t.c_str()); };
        for (size_t i = 0; i < domainPanes.size(); ++i) {
            render::DomainViewOptions& o = domainPanes[i];
            // The GPU's counts where they are of this very pane; while its levels change (a sweep,
            // a slider) the rules' counts for this frame's levels, which equal the GPU's (the
            // teaching tests), until the next frame has drawn them.
            const bool drawn = i < drawnDomain_.size() && i < domainStats.size() && drawnDomain_[i] == o;
            if (!drawn) ctx.wake();
            const auto counts = render::shownCounts(drawn ? domainStats[i] : render::DomainStats{}, o);
            domainCounts.push_back(counts);
            const auto widthOf = [&](const std::string& t) { return measure(t, px).x; };
            for (const render::DomainLabel& l : render::domainLabels(o, counts[0], counts[1], px, widthOf)) {
                // A label still wider than its pane (a very narrow window) is drawn smaller to fit.
                const float size0 = l.role == render::DomainLabel::Role::Title ? px * 1.1f : px;
                const ImVec2 full = measure(l.text, size0);
                const float fit = std::min(1.0f, (o.rect[2] - 4.0f) / std::max(1.0f, full.x));
                const ImVec2 size(full.x * fit, full.y * fit), at(l.x - l.ax * size.x, l.y - l.ay * size.y);
                const ImU32 col = l.role == render::DomainLabel::Role::Edge ? IM_COL32(170, 30, 20, 255) : IM_COL32(25, 30, 40, 255);
                dl->AddText(font, size0 * fit, at, col, l.text.c_str());
                labelBoxes.push_back({at.x, at.y, size.x, size.y});
            }
            // In framebuffer pixels for the GPU pass.
            o.rect = {o.rect[0] * sx, o.rect[1] * sy, o.rect[2] * sx, o.rect[3] * sy};
            o.margin *= sx;
        }
    }
    ImGui::End();
}

void Teaching::drawDomainPanes() {
    if (domainPanes.empty()) return;
    if (!domainView_)
        domainView_ = std::make_unique<render::DomainView>(window_.device(), window_.target().colorFormat(), window_.target().depthFormat(),
                                                           window_.target().samples());
    domainStats = domainView_->draw(window_.target(), domainPanes, false);
    drawnDomain_.assign(domainPanes.begin(), domainPanes.end());
}

}  // namespace panels
}  // namespace pw::ui

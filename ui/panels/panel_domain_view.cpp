// The domain view window (ui/panels/teaching.hpp): the quad, triangle or isoline domain tessellated by the
// GPU with the document's levels in 1, 2 or 4 panes, drawn into a background-less window before
// the ImGui pass, with each edge's level and the vertex and triangle counts labelled by ImGui.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "core/gpu/trim_math.h"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"
#include "render/domain/domain_labels.hpp"
#include "render/figures/domain_figure.hpp"
#include "ui/panels/teaching.hpp"
#include "ui/platform/app_window.hpp"
#include "ui/platform/imgui_layer.hpp"
#include "ui/platform/swapchain_target.hpp"

namespace pw::ui {
inline namespace panels {

namespace {
// The selected patch's or net's trims over a quad pane (issue 64): its loops in the (u, v) square,
// and for a net its windows, those the trims cull wholly (not tessellated) hatched and named.
void drawTrimmedDomain(PanelContext& ctx, const render::DomainViewOptions& o, ImDrawList* dl) {
    if (o.kind != DomainKind::Quad) return;
    const EditSession& s = ctx.session();
    const Document& doc = s.doc;
    SurfaceRef ref;
    if (s.sel.patch >= 0 && size_t(s.sel.patch) < doc.patches.size())
        ref = {false, uint32_t(s.sel.patch)};
    else if (s.sel.surface >= 0 && size_t(s.sel.surface) < doc.surfaces.size())
        ref = {true, uint32_t(s.sel.surface)};
    else
        return;
    const std::vector<TrimLoop>& loops = trimsOf(doc, ref);
    if (loops.empty()) return;
    const render::DomainPlacement at = render::placeDomain(o);
    auto px = [&](double u, double v) {
        const auto p = at.toPixels(float(u), float(v));
        return ImVec2(p[0], p[1]);
    };
    if (ref.net) {  // the windows, and those wholly trimmed away
        const Surface& n = doc.surfaces[ref.index];
        const uint32_t step = netStep(n.basis);
        const uint32_t wu = uint32_t(netWindowCount(n.cols, n.closedU, step)), wv = uint32_t(netWindowCount(n.rows, n.closedV, step));
        const std::vector<TrimSegment> segs = monotoneSegments(loops);
        const bool outer = hasOuterLoop(loops);
        for (uint32_t r = 0; r < wv; ++r)
            for (uint32_t c = 0; c < wu; ++c) {
                const WindowTrim t = windowTrim(segs, outer, r, c, wu, wv);
                const ImVec2 a = px(double(c) / wu, double(r) / wv), b = px(double(c + 1) / wu, double(r + 1) / wv);
                const ImVec2 lo(std::min(a.x, b.x), std::min(a.y, b.y)), hi(std::max(a.x, b.x), std::max(a.y, b.y));
                dl->AddRect(lo, hi, IM_COL32(90, 110, 140, 160));
                if (t.flags & gpu::kTrimAllGone) dl->AddRectFilled(lo, hi, IM_COL32(120, 120, 120, 90));
            }
    }
    for (const TrimLoop& l : loops) {
        const std::vector<glm::dvec2> uv = loopPolyline(l, 24);
        const ImU32 col = signedUvArea(l) < 0.0 ? IM_COL32(220, 90, 30, 255) : IM_COL32(30, 140, 60, 255);
        for (size_t k = 0; k < uv.size(); ++k)
            dl->AddLine(px(uv[k].x, uv[k].y), px(uv[(k + 1) % uv.size()].x, uv[(k + 1) % uv.size()].y), col, 2.5f * ctx.uiScale());
    }
    const ImVec2 corner = px(0.0, 1.0);
    dl->AddText(ImVec2(corner.x + 4.0f, corner.y + 2.0f), IM_COL32(25, 30, 40, 255),
                (std::string(ref.net ? "net " : "patch ") + std::to_string(ref.index) + ": green keeps, orange cuts" +
                 (ref.net ? "; grey windows are not tessellated" : ""))
                    .c_str());
}
}  // namespace

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
            drawTrimmedDomain(ctx, o, dl);
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

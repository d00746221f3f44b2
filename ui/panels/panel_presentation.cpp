// Presentation mode's overlay (F5, ui/panels/teaching.hpp): the levels, the partitioning and every
// pane's counts in large type, high contrast, no editing panels. Counts and levels come from the
// same frame: the domain panes' counts are this frame's (drawDomainWindow), the 3D view's are
// shown with the levels it was drawn with (viewTess, the split panes' own).
#include <imgui.h>

#include <algorithm>
#include <string>
#include <utility>

#include "render/domain/domain_labels.hpp"
#include "ui/panels/teaching.hpp"
#include "ui/platform/app_window.hpp"
#include "ui/platform/imgui_layer.hpp"

namespace pw::ui {
inline namespace panels {

namespace {

std::string countText(uint64_t n, const char* word) { return std::to_string(n) + " " + word; }

}  // namespace

float Teaching::presentationTextPixels() const {
    const ImGuiIO& io = ImGui::GetIO();
    const float ui = io.Fonts->Fonts.empty() ? 13.0f : io.Fonts->Fonts[0]->FontSize;
    return 0.75f * ui * presentationScale * std::clamp(io.DisplaySize.y / 800.0f, 0.6f, 3.0f);
}

void Teaching::drawPresentationOverlay(PanelContext& ctx) {
    // The levels the counts below belong to: this frame's for the domain panes, else the 3D view's last.
    const bool domain = !domainPanes.empty();
    const TessSettings ts = domain ? shownTess(ctx.session().doc.tess) : viewTess;
    if (!domain && !viewSplit() && ts != shownTess(ctx.session().doc.tess)) ctx.wake();  // the next frame catches up
    const render::FrameStats& stats = ctx.frameReport().stats;
    const ImVec4 yellow(1.0f, 0.85f, 0.1f, 1.0f), white(1, 1, 1, 1);
    std::vector<std::pair<std::string, ImVec4>> lines;
    if (lesson.active) lines.emplace_back(lesson.name, yellow);
    using render::formatLevel;
    lines.emplace_back("outer " + formatLevel(ts.outer[0]) + "  " + formatLevel(ts.outer[1]) + "  " + formatLevel(ts.outer[2]) + "  " +
                           formatLevel(ts.outer[3]),
                       white);
    lines.emplace_back("inner " + formatLevel(ts.inner[0]) + "  " + formatLevel(ts.inner[1]), white);
    // The partitioning, unless the panes each name their own below.
    if ((!domain || domainPanes.size() == 1) && !viewSplit())
        lines.emplace_back(std::string(spacingName(ts.spacing)) +
                               (ts.adaptive == AdaptiveMode::None ? "" : ", adaptive " + std::string(adaptiveName(ts.adaptive))),
                           yellow);
    if (domain) {
        const char* word = domainPanes.front().kind == DomainKind::Isoline ? "segments" : "triangles";
        for (size_t i = 0; i < domainPanes.size() && i < domainCounts.size(); ++i) {
            const render::DomainViewOptions& o = domainPanes[i];
            if (domainPanes.size() == 1) {
                lines.emplace_back(countText(domainCounts[i][1], word), white);
                lines.emplace_back(countText(domainCounts[i][0], "vertices"), white);
                break;
            }
            const std::string level = paneLevel[i] > 0.0f ? " " + formatLevel(paneLevel[i]) : std::string();
            lines.emplace_back(std::string(spacingName(o.spacing)) + level + ": " + countText(domainCounts[i][1], word), white);
        }
    } else if (viewSplit()) {
        for (size_t i = 0; i < viewPanes.size(); ++i) {
            const std::string level = paneLevel[i] > 0.0f ? " " + formatLevel(viewPanes[i].tess.outer[0]) : std::string();
            lines.emplace_back(
                std::string(spacingName(viewPanes[i].tess.spacing)) + level + ": " + countText(viewPanes[i].stats.triangles(), "triangles"),
                white);
        }
    } else {
        lines.emplace_back(countText(stats.triangles(), "triangles"), white);
        lines.emplace_back(countText(stats.tesInvocations, "evaluations"), white);
    }
    if (sweep.playing) lines.emplace_back("sweep " + formatLevel(sweep.from) + " \u2192 " + formatLevel(sweep.to), yellow);

    ImGui::SetNextWindowPos(ImVec2(16.0f, 16.0f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    overlayLines.clear();
    if (ImGui::Begin("##presentation", nullptr, flags)) {
        ImFont* font = window_.imgui().presentationFont();
        ImGui::PushFont(font);
        // A third larger than the labels (presentationTextPixels): the big font is drawn scaled.
        ImGui::SetWindowFontScale(presentationTextPixels() / 0.75f / font->FontSize);
        ImGui::BeginGroup();  // one item around the lines: where the widest ends (the test trace checks it fits)
        for (const auto& [text, colour] : lines) {
            ImGui::TextColored(colour, "%s", text.c_str());
            overlayLines.push_back(text);
        }
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

}  // namespace panels
}  // namespace pw::ui

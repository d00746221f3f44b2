// Teaching: the live domain view (the quad, triangle or isoline domain tessellated by the GPU with
// the document's levels, in 1, 2 or 4 panes with their own partitioning), the notes' presets, an
// animated level sweep (popping under integer spacing, sliding under fractional), and presentation
// mode (F5: no editing chrome, large levels and counts, high contrast).
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>

#include "render/domain_figure.hpp"
#include "render/domain_labels.hpp"
#include "ui/editor.hpp"
#include "ui/imgui_layer.hpp"
#include "ui/imgui_tip.hpp"
#include "render/swapchain_target.hpp"
#include "core/tess_presets.hpp"

namespace pw::ui {

namespace {

const char* const kSpacingNames[] = {"equal", "fractional_odd", "fractional_even", "pow2"};
const char* const kDomainNames[] = {"quad", "triangle", "isoline"};

// Presentation mode's theme: black panels, white text, yellow accents.
void highContrastTheme() {
    ImGui::StyleColorsDark();
    ImVec4* c = ImGui::GetStyle().Colors;
    c[ImGuiCol_Text] = ImVec4(1, 1, 1, 1);
    c[ImGuiCol_WindowBg] = ImVec4(0, 0, 0, 0.92f);
    c[ImGuiCol_Border] = ImVec4(1.0f, 0.85f, 0.1f, 1.0f);
    c[ImGuiCol_TitleBgActive] = c[ImGuiCol_TitleBg] = ImVec4(0.2f, 0.2f, 0.0f, 1.0f);
    c[ImGuiCol_FrameBg] = ImVec4(0.15f, 0.15f, 0.15f, 1.0f);
    c[ImGuiCol_Button] = c[ImGuiCol_Header] = ImVec4(0.45f, 0.38f, 0.0f, 1.0f);
}

}  // namespace

void Editor::setPresentation(bool on) {
    presentation_ = on;
    if (on) highContrastTheme();
    else ImGui::StyleColorsDark();
    wake();
}

void Editor::teachingInput() {
    if (!sweep_.playing) return;
    // The sweep drives the uniform level; one undo step when it stops.
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - sweep_.start).count();
    double f = t / std::max(0.05f, sweep_.seconds);
    if (f >= 1.0) {
        if (sweep_.loop) {
            sweep_.start = std::chrono::steady_clock::now();
            f = 0.0;
        } else {
            f = 1.0;
            sweep_.playing = false;
        }
    }
    sweep_.level = sweep_.from + (sweep_.to - sweep_.from) * float(f);
    doc_.tess.adaptive = AdaptiveMode::None;
    doc_.tess.outer = {sweep_.level, sweep_.level, sweep_.level, sweep_.level};
    doc_.tess.inner = {sweep_.level, sweep_.level};
    ++docVersion_;
    if (!sweep_.playing) commit("Sweep level");
    wake();
}

void Editor::drawTeachingControls() {
    const bool open = ImGui::CollapsingHeader("Teaching");
    traceItem("panel.teaching");
    if (!open) return;
    TessSettings& ts = doc_.tess;
    ImGui::Checkbox("Domain view", &showDomain_);
    traceItem("teach.domain");
    tip("The parametric domain tessellated by the GPU with the current levels and partitioning");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
    ImGui::Combo("##domain", &domainKind_, kDomainNames, 3);
    tip("Quad: outer u0, v0, u1, v1 and inner u, v. Triangle: outer 1-3 and inner 1. Isoline: outer 1 = lines, outer 2 = segments");
    ImGui::Checkbox("Shaders", &showShaders_);
    traceItem("teach.shaders");
    tip("The GLSL of the tessellation stages in use, read-only, with the active defines");
    ImGui::TextUnformatted("Panes");
    for (int n : {1, 2, 4}) {
        ImGui::SameLine();
        char label[8];
        std::snprintf(label, sizeof label, "%d", n);
        if (ImGui::RadioButton(label, domainPaneCount_ == n)) {
            domainPaneCount_ = n;
            if (splitView_) frameBox(computeBounds(doc_.points));  // fit the new pane shape
        }
        traceItem("teach.panes" + std::to_string(n));
    }
    tip("Compare partitionings (or levels) side by side: the domain view, and the 3D view when split");
    if (domainPaneCount_ > 1) {
        if (ImGui::Checkbox("Split 3D view", &splitView_)) frameBox(computeBounds(doc_.points));  // fit the new pane shape
        traceItem("teach.splitView");
        tip("Show the model once per pane, each with its own partitioning and level, under one camera");
        const float w = ImGui::GetContentRegionAvail().x;
        for (int i = 0; i < domainPaneCount_; ++i) {
            char label[24];
            std::snprintf(label, sizeof label, "##paneSpacing%d", i);
            ImGui::SetNextItemWidth(w * 0.5f);
            ImGui::Combo(label, &paneSpacing_[size_t(i)], kSpacingNames, 4);
            traceItem("teach.paneSpacing" + std::to_string(i));
            tip("Partitioning of this pane");
            ImGui::SameLine();
            std::snprintf(label, sizeof label, "##paneLevel%d", i);
            float& level = paneLevel_[size_t(i)];
            ImGui::SetNextItemWidth(-1.0f);
            if (ImGui::SliderFloat(label, &level, 0.0f, 64.0f, level < 1.0f ? "doc levels" : "level %.2f")) wake();
            if (level < 1.0f) level = 0.0f;  // below 1: the document's levels
            traceItem("teach.paneLevel" + std::to_string(i));
            tip("This pane's own uniform level; at the left end the pane uses the document's levels (Ctrl+click to type)");
        }
    }

    // Presets: the notes' factor sets, their Bézier patch, their distance formula.
    const auto& presets = tessPresets();
    if (ImGui::BeginCombo("Preset", "choose...", ImGuiComboFlags_HeightLargest)) {
        for (const TessPreset& p : presets) {
            const bool chosen = ImGui::Selectable(p.label.c_str());
            traceItem("preset." + p.name);
            if (chosen) {
                const auto& L = p.levels;
                ts.adaptive = AdaptiveMode::None;
                ts.linked = false;
                ts.spacing = p.spacing;
                ts.outer = L.outer;
                ts.inner = L.inner;
                if (p.kind == DomainKind::Triangle) {  // the quad's unused 4th edge and 2nd inner follow
                    ts.outer[3] = L.outer[2];
                    ts.inner[1] = L.inner[0];
                }
                domainKind_ = int(p.kind);
                domainPaneCount_ = 1;
                showDomain_ = true;
                ++docVersion_;
                commit("Preset " + p.label);
            }
            tip(p.note.c_str());
        }
        ImGui::Separator();
        if (ImGui::Selectable("Bézier patch of the notes")) runCommand("open-notes-patch");
        tip("The notes' 16 control points at level 25 (replaces the document; asks first if it has changes)");
        if (ImGui::Selectable("Distance formula of the notes")) {
            applyNotesDistanceFormula(ts);
            ++docVersion_;
            commit("Distance formula");
        }
        tip("level = 64 * saturate((d1 - d) / (d1 - d0)) per edge, d0 = 20, d1 = 100");
        ImGui::EndCombo();
    }
    traceItem("teach.preset");
    tip("Factor sets and models from the lecture notes");

    // Sweep.
    ImGui::DragFloatRange2("From / to", &sweep_.from, &sweep_.to, 0.05f, 1.0f, 64.0f, "%.2f", "%.2f", ImGuiSliderFlags_AlwaysClamp);
    tip("The uniform level animated from the first to the second value");
    ImGui::DragFloat("Seconds", &sweep_.seconds, 0.05f, 0.5f, 60.0f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
    tip("Length of one pass");
    if (ImGui::Button(sweep_.playing ? "Pause" : "Play")) {
        sweep_.playing = !sweep_.playing;
        if (sweep_.playing) {
            const float span = sweep_.to - sweep_.from;
            const float f = span != 0.0f ? std::clamp((sweep_.level - sweep_.from) / span, 0.0f, 0.999f) : 0.0f;
            sweep_.start = std::chrono::steady_clock::now() -
                           std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(f * sweep_.seconds));
            wake();
        } else {
            commit("Sweep level");
        }
    }
    traceItem("teach.play");
    tip("Play or pause the sweep: integer spacing pops vertices in, fractional spacing slides them");
    ImGui::SameLine();
    ImGui::Checkbox("Loop", &sweep_.loop);
    tip("Start again at the first value");
    ImGui::SameLine();
    ImGui::Text("level %.2f", double(sweep_.level));

    bool present = presentation_;
    if (ImGui::Checkbox("Presentation (F5)", &present)) setPresentation(present);
    tip("Hide the editing panels; show levels and counts large in high contrast. F5 toggles.");
    ImGui::SliderFloat("Text scale", &presentationScale_, 1.5f, 3.0f, "%.1fx");
    tip("Size of the presentation text relative to the interface");
}

void Editor::drawTeachingWindow() {
    domainPanes_.clear();
    if (!showDomain_) return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(leftPanelWidth_ + 16.0f, ImGui::GetFrameHeight() + 16.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(430.0f * uiScale_, 430.0f * uiScale_), ImGuiCond_FirstUseEver);
    // No window background: the GPU draws the domain into this rectangle before ImGui draws the
    // labels over it (drawDomainPanes).
    if (ImGui::Begin("Domain view", &showDomain_, ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoScrollbar)) {
        const ImVec2 wp = ImGui::GetWindowPos(), a = ImGui::GetWindowContentRegionMin(), b = ImGui::GetWindowContentRegionMax();
        const std::array<float, 4> area{wp.x + a.x, wp.y + a.y, b.x - a.x, b.y - a.y};
        const auto rects = render::splitPanes(domainPaneCount_, area);
        const float px = ImGui::GetFontSize(), sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
        ImDrawList* dl = ImGui::GetWindowDrawList();
        for (size_t i = 0; i < rects.size(); ++i) {
            render::DomainViewOptions o;
            o.kind = DomainKind(domainKind_);
            o.levels = {doc_.tess.outer, doc_.tess.inner};
            o.spacing = domainPaneCount_ > 1 ? kPaneSpacings[paneSpacing_[i]] : doc_.tess.spacing;
            if (domainPaneCount_ > 1 && paneLevel_[i] > 0.0f) o.levels = withUniformLevel(o.levels, paneLevel_[i]);
            o.rect = rects[i];
            o.margin = render::domainLabelMargin(px);
            const render::DomainPane pane{o.kind, o.levels, o.spacing};
            const auto counts = render::shownCounts(i < domainStats_.size() ? domainStats_[i] : render::DomainStats{}, pane);
            for (const render::DomainLabel& l : render::domainLabels(o, counts[0], counts[1], px)) {
                const ImVec2 size = ImGui::CalcTextSize(l.text.c_str());
                const ImU32 col = l.role == render::DomainLabel::Role::Edge ? IM_COL32(170, 30, 20, 255) : IM_COL32(25, 30, 40, 255);
                dl->AddText(ImVec2(l.x - l.ax * size.x, l.y - l.ay * size.y), col, l.text.c_str());
            }
            // In framebuffer pixels for the GPU pass.
            o.rect = {o.rect[0] * sx, o.rect[1] * sy, o.rect[2] * sx, o.rect[3] * sy};
            o.margin *= sx;
            o.pointSize = 4.0f * sx;
            domainPanes_.push_back(o);
        }
    }
    ImGui::End();
}

std::vector<std::array<float, 4>> Editor::viewPaneRects() const {
    const ImGuiIO& io = ImGui::GetIO();
    if (!viewSplit()) return {{0.0f, 0.0f, io.DisplaySize.x, io.DisplaySize.y}};
    // Between the side panels and below the menu bar (the whole window in presentation mode).
    const float left = presentation_ ? 0.0f : leftPanelWidth_, right = presentation_ ? 0.0f : rightPanelWidth_;
    const float top = presentation_ ? 0.0f : ImGui::GetFrameHeight();
    const float w = std::max(io.DisplaySize.x - left - right, 64.0f), h = std::max(io.DisplaySize.y - top, 64.0f);
    return render::splitPanes(domainPaneCount_, {left, top, w, h});
}

std::array<float, 4> Editor::interactionPane(double mx, double my) {
    const auto rects = viewPaneRects();
    if (mode_ == Interaction::None)
        for (size_t i = 0; i < rects.size(); ++i) {
            const auto& r = rects[i];
            if (mx >= r[0] && mx < r[0] + r[2] && my >= r[1] && my < r[1] + r[3]) activePane_ = int(i);
        }
    activePane_ = std::clamp(activePane_, 0, int(rects.size()) - 1);
    return rects[size_t(activePane_)];
}

void Editor::renderView(const render::RenderOptions& o) {
    viewPanes_.clear();
    if (!viewSplit()) {
        stats_ = renderer_->render(o);
        return;
    }
    const ImGuiIO& io = ImGui::GetIO();
    const float sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
    const auto rects = viewPaneRects();
    for (size_t i = 0; i < rects.size(); ++i) {
        const std::array<float, 4> fb{rects[i][0] * sx, rects[i][1] * sy, rects[i][2] * sx, rects[i][3] * sy};
        const render::ModelPane pane{kPaneSpacings[size_t(paneSpacing_[i])], paneLevel_[i]};
        const render::RenderOptions po = render::paneOptions(o, pane, fb, i);
        viewPanes_.push_back({po.tess, po.pane, renderer_->render(po)});
    }
    stats_ = viewPanes_.front().stats;
}

void Editor::drawPaneCaptions() {
    if (!viewSplit()) return;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    ImFont* font = presentation_ && imgui_->presentationFont() ? imgui_->presentationFont() : ImGui::GetFont();
    const float size = presentation_ ? ImGui::GetFontSize() * presentationScale_ * 0.9f : ImGui::GetFontSize();
    const auto rects = viewPaneRects();
    for (size_t i = 0; i < rects.size() && i < viewPanes_.size(); ++i) {
        const auto& r = rects[i];
        const std::string text = render::paneCaption(viewPanes_[i].tess, viewPanes_[i].stats.triangles(), true);
        const ImVec2 ts2 = font->CalcTextSizeA(size, FLT_MAX, 0.0f, text.c_str());
        // Top centre; at the bottom in presentation mode, clear of the large levels at the top left.
        const ImVec2 at(r[0] + 0.5f * (r[2] - ts2.x), presentation_ ? r[1] + r[3] - ts2.y - 12.0f : r[1] + 8.0f);
        dl->AddRectFilled(ImVec2(at.x - 6.0f, at.y - 3.0f), ImVec2(at.x + ts2.x + 6.0f, at.y + ts2.y + 3.0f), IM_COL32(0, 0, 0, 150), 4.0f);
        dl->AddText(font, size, at, presentation_ ? IM_COL32(255, 220, 40, 255) : IM_COL32(235, 235, 235, 255), text.c_str());
        if (i > 0 || r[0] > 0.0f)  // a thin line between panes
            dl->AddLine(ImVec2(r[0], r[1]), ImVec2(r[0], r[1] + r[3]), IM_COL32(150, 150, 150, 200));
        if (r[1] > (presentation_ ? 0.0f : ImGui::GetFrameHeight()) + 1.0f)
            dl->AddLine(ImVec2(r[0], r[1]), ImVec2(r[0] + r[2], r[1]), IM_COL32(150, 150, 150, 200));
    }
}

void Editor::drawDomainPanes() {
    if (domainPanes_.empty()) return;
    if (!domainView_)
        domainView_ = std::make_unique<render::DomainView>(*dev_, target_->colorFormat(), target_->depthFormat(), target_->samples());
    domainStats_ = domainView_->draw(*target_, domainPanes_, false);
}

void Editor::drawPresentationOverlay() {
    const TessSettings& ts = doc_.tess;
    ImGui::SetNextWindowPos(ImVec2(16.0f, 16.0f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("##presentation", nullptr, flags)) {
        ImGui::PushFont(imgui_->presentationFont());
        ImGui::SetWindowFontScale(presentationScale_ / 3.0f);
        ImGui::Text("outer %s  %s  %s  %s", render::formatLevel(ts.outer[0]).c_str(), render::formatLevel(ts.outer[1]).c_str(),
                    render::formatLevel(ts.outer[2]).c_str(), render::formatLevel(ts.outer[3]).c_str());
        ImGui::Text("inner %s  %s", render::formatLevel(ts.inner[0]).c_str(), render::formatLevel(ts.inner[1]).c_str());
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.1f, 1.0f), "%s%s", spacingName(ts.spacing).data(),
                           ts.adaptive == AdaptiveMode::None ? "" : (std::string(", adaptive ") + adaptiveName(ts.adaptive).data()).c_str());
        ImGui::Text("%llu triangles", static_cast<unsigned long long>(stats_.triangles()));
        ImGui::Text("%llu evaluations", static_cast<unsigned long long>(stats_.tesInvocations));
        if (sweep_.playing) ImGui::Text("sweep %.2f", double(sweep_.level));
        ImGui::PopFont();
    }
    ImGui::End();
}

}  // namespace pw::ui

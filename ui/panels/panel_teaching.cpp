// The Teaching section of the right panel (ui/panels/teaching.hpp): the domain view and its panes, the
// split 3D view, the notes' presets, the level sweep, presentation mode on and off.
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "core/base/limits.hpp"
#include "core/tess/tess_presets.hpp"
#include "ui/panels/teaching.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

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

void Teaching::setPresentation(PanelContext& ctx, bool on) {
    presentation = on;
    if (on)
        highContrastTheme();
    else
        ImGui::StyleColorsDark();
    ctx.wake();
}

TessSettings Teaching::shownTess(const TessSettings& doc) const {
    if (!lesson.active) return doc;
    TessSettings t = doc;
    t.adaptive = AdaptiveMode::None;
    t.outer = lesson.outer;
    t.inner = lesson.inner;
    t.spacing = lesson.spacing;
    return t;
}

void Teaching::endLesson(PanelContext& ctx, bool keep) {
    if (!lesson.active) return;
    sweep.playing = false;
    if (keep) {  // one undo step: the tess-fixed command
        const TessSettings ts = shownTess(ctx.session().doc.tess);
        std::vector<std::string> words{"tess-fixed", std::string(spacingName(ts.spacing))};
        for (float v : ts.outer) words.push_back(commandWord(v));
        for (float v : ts.inner) words.push_back(commandWord(v));
        ctx.runCommand(words);
    }
    lesson.active = false;
    ctx.wake();
}

void Teaching::input(PanelContext& ctx) {
    if (!sweep.playing) return;
    // The sweep drives the lesson's uniform level (the document's levels stay as they are).
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - sweep.start).count();
    double f = t / std::max(0.05f, sweep.seconds);
    if (f >= 1.0) {
        if (sweep.loop) {
            sweep.start = std::chrono::steady_clock::now();
            f = 0.0;
        } else {
            f = 1.0;
            sweep.playing = false;
        }
    }
    sweep.level = sweep.from + (sweep.to - sweep.from) * float(f);
    const Spacing spacing = lesson.active ? lesson.spacing : ctx.session().doc.tess.spacing;
    lesson = {true, "Sweep", {sweep.level, sweep.level, sweep.level, sweep.level}, {sweep.level, sweep.level}, spacing};
    ctx.wake();
}

void Teaching::drawControls(PanelContext& ctx) {
    if (!widget::CollapsingHeader("Teaching##panel.teaching")) return;
    const Document& doc = ctx.session().doc;
    widget::Checkbox("Domain view##teach.domain", &showDomain);
    tip("The parametric domain tessellated by the GPU with the current levels and partitioning");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
    ImGui::Combo("##domain", &domainKind, kDomainNames, 3);
    tip("Quad: outer u0, v0, u1, v1 and inner u, v. Triangle: outer 1-3 and inner 1. Isoline: outer 1 = lines, outer 2 = segments");
    widget::Checkbox("Shaders##teach.shaders", &shadersOpen_);
    tip("The GLSL of the tessellation stages in use, read-only, with the active defines");
    ImGui::SameLine();
    commandButton(ctx, "Save figure...", "domain-figure", "teach.saveFigure");
    ImGui::SameLine();
    bool upperLeft = doc.display.domainUpperLeft;
    if (widget::Checkbox("Upper-left##teach.upperLeft", &upperLeft))
        ctx.runLine(upperLeft ? "domain-origin upper-left" : "domain-origin lower-left");
    tip("Draw the domain as the D3D notes and Vulkan's default do: v = 0 on top, every edge tagged with its index [i] "
        "(SV_TessFactor[i] = gl_TessLevelOuter[i]); off: GL's lower-left origin. Kept with the document");
    ImGui::TextUnformatted("Panes");
    for (int n : {1, 2, 4}) {
        ImGui::SameLine();
        char label[24];
        std::snprintf(label, sizeof label, "%d##teach.panes%d", n, n);
        if (widget::RadioButton(label, paneCount == n)) {
            paneCount = n;
            if (splitView) ctx.frameBox(computeBounds(doc.points));  // fit the new pane shape
        }
    }
    tip("Compare partitionings (or levels) side by side: the domain view, and the 3D view when split");
    if (paneCount > 1) {
        if (widget::Checkbox("Split 3D view##teach.splitView", &splitView))
            ctx.frameBox(computeBounds(doc.points));  // fit the new pane shape
        tip("Show the model once per pane, each with its own partitioning and level, under one camera");
        const float w = ImGui::GetContentRegionAvail().x;
        for (int i = 0; i < paneCount; ++i) {
            char label[32];
            std::snprintf(label, sizeof label, "##teach.paneSpacing%d", i);
            ImGui::SetNextItemWidth(w * 0.5f);
            widget::Combo(label, &paneSpacing[size_t(i)], kSpacingNames, 4);
            tip("Partitioning of this pane");
            ImGui::SameLine();
            std::snprintf(label, sizeof label, "##teach.paneLevel%d", i);
            float& level = paneLevel[size_t(i)];
            ImGui::SetNextItemWidth(-1.0f);
            if (widget::SliderFloat(label, &level, 0.0f, 64.0f, level < 1.0f ? "doc levels" : "level %.2f")) ctx.wake();
            if (level < 1.0f) level = 0.0f;  // below 1: the document's levels
            tip("This pane's own uniform level; at the left end the pane uses the document's levels (Ctrl+click to type)");
        }
    }

    // Presets: the notes' factor sets, their Bézier patch, their distance formula.
    const auto& presets = tessPresets();
    if (widget::BeginCombo("Preset##teach.preset", "choose...", ImGuiComboFlags_HeightLargest)) {
        for (const TessPreset& p : presets) {
            const bool chosen = widget::Selectable((p.label + "##preset." + p.name).c_str());
            if (chosen) {  // shown as a lesson: the document keeps its levels
                const auto& L = p.levels;
                sweep.playing = false;
                lesson = {true, "Preset " + p.label, L.outer, L.inner, p.spacing};
                if (p.kind == DomainKind::Triangle) {  // the quad's unused 4th edge and 2nd inner follow
                    lesson.outer[3] = L.outer[2];
                    lesson.inner[1] = L.inner[0];
                }
                domainKind = int(p.kind);
                paneCount = 1;
                showDomain = true;
                ctx.wake();
            }
            tip(p.note.c_str());
        }
        ImGui::Separator();
        if (ImGui::Selectable("Bézier patch of the notes")) ctx.runLine("open-notes-patch 1");
        tip("The first notes' 16 control points at level 25 (replaces the document; asks first if it has changes)");
        if (widget::Selectable("Bézier patch of the notes, second version##preset.notesPatch2")) ctx.runLine("open-notes-patch 2");
        tip("The second notes' 16 control points (raised higher) at level 15, integer partitioning (replaces the document)");
        // The notes' distance formulas: adaptivity is the document's, so each is a visible undo step.
        const auto formula = [&](const char* label, const char* preset, const char* said, const char* help) {
            if (widget::Selectable(label)) {
                endLesson(ctx, false);
                ctx.runCommand({"adaptive-preset", preset});
                ctx.host().status(std::string(said) + " is now the document's adaptive tessellation (Ctrl+Z undoes it)");
            }
            tip(help);
        };
        formula("Distance formula of the notes##preset.notesDistance", "notes", "The notes' distance formula",
                "level = 64 * saturate((d1 - d) / (d1 - d0)) from each patch's centre, d0 = 20, d1 = 100, culled beyond: as the notes "
                "write it, so neighbours at different distances crack (one undo step)");
        formula("Distance formula of the notes, per edge##preset.notesDistanceEdges", "notes-edges", "The notes' formula per edge",
                "The same formula measured at each edge's midpoint: both patches on an edge agree, no crack (one undo step)");
        formula("Terrain formula of the notes##preset.notesTerrain", "notes-terrain", "The terrain notes' formula",
                "level = 2^lerp(20, 4, saturate((d - 10) / (200 - 10))), edges from their midpoints and the inside from the centre, "
                "fractional_even; the height map only moves the vertices. data/terrain_notes.patchwork is the notes' terrain with it "
                "(one undo step)");
        widget::EndCombo("Preset##teach.preset");
    }
    tip("Factor sets from the lecture notes, shown without changing the document's levels");
    if (lesson.active) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
        ImGui::TextWrapped("Showing %s; the document keeps its own levels.", lesson.name.c_str());
        ImGui::PopStyleColor();
        if (widget::Button("Back to document##teach.lessonBack")) endLesson(ctx, false);
        tip("Show the document's own levels again");
        ImGui::SameLine();
        if (widget::Button("Keep in document##teach.lessonKeep")) endLesson(ctx, true);
        tip("Make these levels the document's (one undo step)");
    }

    // Sweep.
    ImGui::DragFloatRange2("From / to", &sweep.from, &sweep.to, 0.05f, 1.0f, 64.0f, "%.2f", "%.2f", ImGuiSliderFlags_AlwaysClamp);
    tip("The uniform level animated from the first to the second value");
    ImGui::DragFloat("Seconds", &sweep.seconds, 0.05f, 0.5f, 60.0f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
    tip("Length of one pass");
    if (widget::Button(sweep.playing ? "Pause##teach.play" : "Play##teach.play")) {
        sweep.playing = !sweep.playing;
        if (sweep.playing) {
            const float span = sweep.to - sweep.from;
            const float f = span != 0.0f ? std::clamp((sweep.level - sweep.from) / span, 0.0f, 0.999f) : 0.0f;
            sweep.start = std::chrono::steady_clock::now() -
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(f * sweep.seconds));
            ctx.wake();
        }
    }
    tip("Play or pause the sweep: integer spacing pops vertices in, fractional spacing slides them (the document's levels stay)");
    ImGui::SameLine();
    ImGui::Checkbox("Loop", &sweep.loop);
    tip("Start again at the first value");
    ImGui::SameLine();
    ImGui::Text("level %.2f", double(sweep.level));
    commandButton(ctx, "Save animation...", "sweep-animation", "teach.saveAnimation");

    if (widget::Checkbox("Stage counters##teach.stageBars", &stageBars)) ctx.wake();
    tip("Each pane's per-stage counters from the GPU: vertex shader invocations, control shader patches, evaluation shader "
        "invocations, triangles (log-scaled bars)");
    ImGui::SameLine();
    bool debug = debugCamera.has_value();
    if (widget::Checkbox("Debug camera##teach.debugCamera", &debug)) {
        debugCamera = debug ? std::optional<Camera>(ctx.viewCamera()) : std::nullopt;
        if (debug) ctx.host().status("Debug camera: this view decides levels and culling; orbit away");
        ctx.wake();
    }
    tip("Freeze this view as the camera that decides the levels and culling, then move the view away: the patches it culls "
        "are drawn greyed (hatched) in place and its frustum in orange. Off: the view decides again");
    // The Bézier math of one patch at (u, v), on its control net.
    if (widget::Checkbox("Bezier math##teach.math", &math.on)) ctx.wake();
    tip("Show one patch's evaluation at (u, v): the 16 Bernstein weights on its control points, the de Casteljau rows and "
        "column, the point, its tangents and normal. Click the surface to pick the patch and (u, v)");
    if (math.on) {
        const float w = ImGui::GetContentRegionAvail().x * 0.5f - 4.0f;
        ImGui::SetNextItemWidth(w);
        if (widget::SliderFloat("##teach.mathU", &math.u, 0.0f, 1.0f, "u %.3f", ImGuiSliderFlags_AlwaysClamp)) ctx.wake();
        ImGui::SameLine();
        ImGui::SetNextItemWidth(w);
        if (widget::SliderFloat("##teach.mathV", &math.v, 0.0f, 1.0f, "v %.3f", ImGuiSliderFlags_AlwaysClamp)) ctx.wake();
    }

    bool present = presentation;
    if (ImGui::Checkbox("Presentation (F5)", &present)) setPresentation(ctx, present);
    tip("Hide the editing panels; show levels and counts large in high contrast. F5 toggles.");
    ImGui::SliderFloat("Text scale", &presentationScale, limits::kMinPresentationText, limits::kMaxPresentationText, "%.2fx",
                       ImGuiSliderFlags_AlwaysClamp);
    tip("Size of the presentation text relative to the interface (Ctrl+= and Ctrl+- in presentation mode)");
}

}  // namespace panels
}  // namespace pw::ui

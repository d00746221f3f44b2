// The Bézier math overlay (Teaching > Bezier math, ui/panels/teaching.hpp): one patch's evaluation
// at (u, v) drawn over the 3D view in every pane (core/eval/bezier_math's diagram: each control
// point sized by and labelled with its Bernstein weight, the de Casteljau rows and column, the
// point with its tangents and normal), and its numbers in a box. Drawn in presentation mode too.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <string>

#include "core/eval/bezier_math.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/model/camera_math.hpp"
#include "ui/editor/editor.hpp"
#include "ui/platform/imgui_layer.hpp"

namespace pw::ui {
inline namespace editor {

namespace {

ImU32 colourOf(MathDiagram::Role role) {
    const auto c = mathColor(role);
    return IM_COL32(c[0], c[1], c[2], c[3]);
}

}  // namespace

void Editor::drawMathOverlay() {
    Teaching::MathView& mv = teaching_.math;
    teaching_.mathLines.clear();
    teaching_.mathLabels = 0;
    if (!mv.on || doc_.patches.empty()) return;
    if (mv.patch >= int(doc_.patches.size())) mv.patch = -1;
    const int p = mv.patch >= 0 ? mv.patch : sel_.patch >= 0 && sel_.patch < int(doc_.patches.size()) ? sel_.patch : 0;
    const Patch& patch = doc_.patches[size_t(p)];
    std::vector<std::string>& lines = teaching_.mathLines;
    std::vector<MathDiagram::Role> roles;  // of the lines after the title
    const std::string name = patch.name.empty() ? "patch " + std::to_string(p) : "patch " + std::to_string(p) + " (" + patch.name + ")";
    lines.push_back("Bezier math \u00b7 " + name);
    const bool presenting = teaching_.presentation;
    ImFont* font = presenting && window_.imgui().presentationFont() ? window_.imgui().presentationFont() : ImGui::GetFont();
    const float px = presenting ? teaching_.presentationTextPixels() * 0.8f : ImGui::GetFontSize();
    if (patch.basis != Basis::Bezier) {
        lines.push_back("a " + std::string(basisName(patch.basis)) + " window: the math view shows Bezier patches");
    } else {
        const WindowNet net = gatherWindow(doc_, patch.idx);
        const BezierMath m = bezierMath(net.points, net.weights, double(mv.u), double(mv.v));
        const MathDiagram d = bezierMathDiagram(net.points, m);
        lines.insert(lines.end(), d.legend.begin(), d.legend.end());
        roles = d.legendRoles;
        ImDrawList* dl = ImGui::GetBackgroundDrawList();
        const float dot = mathDotRadius(px);
        for (const auto& r : teaching_.viewPaneRects(sidePanels_.layout())) {
            const int W = std::max(int(r[2]), 1), H = std::max(int(r[3]), 1);
            const ViewMatrices vm = viewMatrices(cam_, double(W) / H);
            const auto proj = [&](const Vec3& q) -> std::optional<ImVec2> {
                const auto s = projectToPixel(vm, q, W, H);
                if (!s) return std::nullopt;
                return ImVec2(float(s->x) + r[0], float(s->y) + r[1]);
            };
            dl->PushClipRect(ImVec2(r[0], r[1]), ImVec2(r[0] + r[2], r[1] + r[3]), true);
            for (const MathDiagram::Stroke& s : d.strokes) {
                const auto a = proj(s.a), b = proj(s.b);
                if (a && b) dl->AddLine(*a, *b, colourOf(s.role), mathStrokeWidth(s.role, px));
            }
            for (const MathDiagram::Dot& o : d.dots) {
                const auto c = proj(o.p);
                if (!c) continue;
                dl->AddCircleFilled(*c, dot * float(o.radius), colourOf(o.role));
                if (o.label.empty()) continue;
                const ImVec2 size = font->CalcTextSizeA(px, FLT_MAX, 0.0f, o.label.c_str());
                const ImVec2 at(c->x + dot * float(o.radius) + 2.0f, c->y - size.y - 1.0f);
                dl->AddRectFilled(ImVec2(at.x - 2.0f, at.y - 1.0f), ImVec2(at.x + size.x + 2.0f, at.y + size.y + 1.0f),
                                  IM_COL32(0, 0, 0, 170), 3.0f);
                dl->AddText(font, px, at, colourOf(o.role), o.label.c_str());
                ++teaching_.mathLabels;
            }
            dl->PopClipRect();
        }
    }
    // The numbers: bottom left of the view, or under the levels box when presenting.
    const ImGuiIO& io = ImGui::GetIO();
    const PanelLayout& layout = sidePanels_.layout();
    if (presenting)
        ImGui::SetNextWindowPos(ImVec2(16.0f, 16.0f + teaching_.overlaySize[1] + 12.0f));
    else
        ImGui::SetNextWindowPos(ImVec2(layout.left + 12.0f, io.DisplaySize.y - 40.0f), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoSavedSettings;
    if (ImGui::Begin("##bezierMath", nullptr, flags)) {
        ImGui::PushFont(font);
        ImGui::SetWindowFontScale(px / font->FontSize);
        // Each line in the colour of what it describes (the diagram's legend roles; the title white).
        for (size_t i = 0; i < lines.size(); ++i) {
            const auto role = i >= 1 && i - 1 < roles.size() ? roles[i - 1] : MathDiagram::Role::Point;
            ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(colourOf(role)), "%s", lines[i].c_str());
        }
        ImGui::PopFont();
    }
    ImGui::End();
}

}  // namespace editor
}  // namespace pw::ui

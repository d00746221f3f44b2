// Join by picking in the window (J, Patch > Join by Picking): the edge under the mouse, clicks and
// keys fed to the tool's steps (ui/panels/join_tool: pick, preview through the `join` command,
// change its continuity, apply, cancel), its panel and its highlights in the view.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <string>

#include "core/base/errors.hpp"

#include "ui/editor/editor.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace editor {

namespace {
constexpr double kEdgePickPx = 10.0;
}

void Editor::setJoinTool(bool on) { join_.setOn(*this, on); }

void Editor::joinToolInput(double mx, double my, bool overUi) {
    join_.followSession(session_);
    const JoinToolState& j = join_.state();
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureKeyboard) {
        if (keyPressed(GLFW_KEY_ESCAPE, 0)) return join_.back(*this);
        if (j.preview && (keyPressed(GLFW_KEY_ENTER, 0) || keyPressed(GLFW_KEY_KP_ENTER, 0))) return join_.apply(*this);
    }
    const auto [W, H] = viewSize();
    join_.setHover(std::nullopt);
    if (overUi || !ImGui::IsMousePosValid() || j.preview) return;
    join_.setHover(pickBoundaryEdge(doc_, cam_, mx, my, W, H, kEdgePickPx, j.first ? int(j.first->patch) : -1));
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.KeyAlt && j.hover) join_.pick(*this, *j.hover);
}

void Editor::drawJoinPanel() {
    const JoinToolState& join = join_.state();
    if (!join.on) return;
    const ImGuiIO& io = ImGui::GetIO();
    const float left = sidePanels_.layout().left, right = io.DisplaySize.x - sidePanels_.layout().right;
    ImGui::SetNextWindowPos(ImVec2(0.5f * (left + right), ImGui::GetFrameHeight() + 8.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::Begin(
        "Join by picking", nullptr,
        ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove);
    if (!join.preview) {
        if (!join.first)
            ImGui::TextUnformatted("1/2  Click an open edge (it lights up under the mouse)");
        else
            ImGui::Text("2/2  %s picked: click the edge to join it to", patchEdgeName(*join.first).c_str());
        if (widget::Button(join.first ? "Back (Esc)##join.back" : "Close (Esc)##join.back")) join_.back(*this);
    } else {
        ImGui::Text("Joined %s to %s: the preview shows the result", patchEdgeName(join.a).c_str(), patchEdgeName(join.b).c_str());
        for (Continuity c : {Continuity::C0, Continuity::C1, Continuity::G1, Continuity::C2, Continuity::G2}) {
            ImGui::SameLine();
            const std::string name(continuityName(c));
            if (widget::RadioButton((name + "##join." + name).c_str(), join.continuity == c)) join_.choose(*this, c);
        }
        if (widget::Button("Apply (Enter)##join.apply")) join_.apply(*this);
        ImGui::SameLine();
        if (widget::Button("Cancel (Esc)##join.cancel")) join_.cancel(*this);
    }
    ImGui::End();
}

void Editor::drawJoinOverlay(const std::function<void(const Vec3&, const Vec3&, unsigned, float)>& line) const {
    const JoinToolState& join = join_.state();
    if (!join.on) return;
    auto edge = [&](const PatchEdge& e, ImU32 col, float width) {
        if (e.patch >= doc_.patches.size()) return;
        const std::vector<Vec3> c = boundaryCurve(doc_, e.patch, e.edge);
        for (size_t k = 0; k + 1 < c.size(); ++k) line(c[k], c[k + 1], col, width);
    };
    auto middle = [&](const PatchEdge& e) { return boundaryCurve(doc_, e.patch, e.edge, 2)[1]; };
    if (join.first) edge(*join.first, IM_COL32(90, 230, 255, 255), 5.0f);
    if (join.hover) edge(*join.hover, IM_COL32(255, 220, 60, 255), 5.0f);
    if (join.first && join.hover && join.first->patch < doc_.patches.size() && join.hover->patch < doc_.patches.size())
        line(middle(*join.first), middle(*join.hover), IM_COL32(255, 220, 60, 180), 1.5f);
    if (join.preview && join.a.patch < doc_.patches.size()) edge(join.a, IM_COL32(80, 255, 120, 255), 4.0f);
}

}  // namespace editor
}  // namespace pw::ui

// Join by picking (J, Patch > Join by Picking): hover highlights an open boundary edge; click it,
// then click the edge to join it to. The join runs at once through the `join` command (C1) as a
// preview: the panel changes its continuity (the join is taken back and run again), keeps it
// (Enter, Apply) or takes it back (Esc, Cancel) and goes back to the second pick. Rhino's Join and
// MatchSrf in one tool; the orientation and the match are the command's (core/ops/patch_ops.hpp).
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

void Editor::setJoinTool(bool on) {
    if (join_.preview) endJoinPreview(true);
    join_ = JoinToolState{};
    join_.on = on;
    if (on) status("Join: click an open edge of the first patch");
    wake();
}

void Editor::joinPreview(Continuity c) {
    const size_t before = doc_.joins.size();
    runCommand({"join", patchEdgeName(join_.a), patchEdgeName(join_.b), std::string(continuityName(c))});
    join_.hover.reset();
    if (doc_.joins.size() != before + 1) {  // refused: the message is shown; pick the second edge again
        join_.first = join_.a;
        return;
    }
    join_.first.reset();
    join_.preview = true;
    join_.continuity = c;
    join_.version = session_.version();
}

void Editor::endJoinPreview(bool keep) {
    if (!join_.preview) return;
    join_.preview = false;
    if (keep) {
        status("Joined " + patchEdgeName(join_.a) + " and " + patchEdgeName(join_.b) + " " + std::string(continuityName(join_.continuity)));
        return;
    }
    if (session_.version() == join_.version) runCommand({"undo"});
    join_.first = join_.a;  // back to the second pick
}

void Editor::joinToolInput(double mx, double my, bool overUi) {
    // Any other edit while the preview shows keeps it.
    if (join_.preview && session_.version() != join_.version) {
        join_.preview = false;
        join_.first.reset();
    }
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureKeyboard) {
        if (keyPressed(GLFW_KEY_ESCAPE, 0)) {
            if (join_.preview)
                endJoinPreview(false);
            else if (join_.first)
                join_.first.reset();
            else
                setJoinTool(false);
            return;
        }
        if (join_.preview && (keyPressed(GLFW_KEY_ENTER, 0) || keyPressed(GLFW_KEY_KP_ENTER, 0))) {
            setJoinTool(false);
            return;
        }
    }
    const auto [W, H] = viewSize();
    join_.hover.reset();
    if (overUi || !ImGui::IsMousePosValid() || join_.preview) return;
    join_.hover = pickBoundaryEdge(doc_, cam_, mx, my, W, H, kEdgePickPx, join_.first ? int(join_.first->patch) : -1);
    if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left) || io.KeyAlt || !join_.hover) return;
    if (!join_.first) {
        join_.first = join_.hover;
        status("Join: " + patchEdgeName(*join_.first) + " picked; click the edge to join it to (Esc: back)");
        return;
    }
    join_.a = *join_.first;
    join_.b = *join_.hover;
    joinPreview(Continuity::C1);
}

void Editor::drawJoinPanel() {
    if (!join_.on) return;
    const ImGuiIO& io = ImGui::GetIO();
    const float left = sidePanels_.layout().left, right = io.DisplaySize.x - sidePanels_.layout().right;
    ImGui::SetNextWindowPos(ImVec2(0.5f * (left + right), ImGui::GetFrameHeight() + 8.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::Begin(
        "Join by picking", nullptr,
        ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove);
    if (!join_.preview) {
        if (!join_.first)
            ImGui::TextUnformatted("1/2  Click an open edge (it lights up under the mouse)");
        else
            ImGui::Text("2/2  %s picked: click the edge to join it to", patchEdgeName(*join_.first).c_str());
        if (widget::Button(join_.first ? "Back (Esc)##join.back" : "Close (Esc)##join.back"))
            join_.first ? join_.first.reset() : setJoinTool(false);
    } else {
        ImGui::Text("Joined %s to %s: the preview shows the result", patchEdgeName(join_.a).c_str(), patchEdgeName(join_.b).c_str());
        for (Continuity c : {Continuity::C0, Continuity::C1, Continuity::G1, Continuity::C2, Continuity::G2}) {
            ImGui::SameLine();
            const std::string name(continuityName(c));
            if (widget::RadioButton((name + "##join." + name).c_str(), join_.continuity == c) && join_.continuity != c) {
                endJoinPreview(false);  // take it back, run it again with c
                joinPreview(c);
            }
        }
        if (widget::Button("Apply (Enter)##join.apply")) setJoinTool(false);
        ImGui::SameLine();
        if (widget::Button("Cancel (Esc)##join.cancel")) endJoinPreview(false);
    }
    ImGui::End();
}

void Editor::drawJoinOverlay(const std::function<void(const Vec3&, const Vec3&, unsigned, float)>& line) const {
    if (!join_.on) return;
    auto edge = [&](const PatchEdge& e, ImU32 col, float width) {
        if (e.patch >= doc_.patches.size()) return;
        const std::vector<Vec3> c = boundaryCurve(doc_, e.patch, e.edge);
        for (size_t k = 0; k + 1 < c.size(); ++k) line(c[k], c[k + 1], col, width);
    };
    auto middle = [&](const PatchEdge& e) { return boundaryCurve(doc_, e.patch, e.edge, 2)[1]; };
    if (join_.first) edge(*join_.first, IM_COL32(90, 230, 255, 255), 5.0f);
    if (join_.hover) edge(*join_.hover, IM_COL32(255, 220, 60, 255), 5.0f);
    if (join_.first && join_.hover && join_.first->patch < doc_.patches.size() && join_.hover->patch < doc_.patches.size())
        line(middle(*join_.first), middle(*join_.hover), IM_COL32(255, 220, 60, 180), 1.5f);
    if (join_.preview && join_.a.patch < doc_.patches.size()) edge(join_.a, IM_COL32(80, 255, 120, 255), 4.0f);
}

}  // namespace editor
}  // namespace pw::ui

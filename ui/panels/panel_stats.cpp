// Stats (right panel): the frame's time and where it went, the 3D view's render and GPU times,
// triangles, evaluations, patches drawn and culled, draws.
#include <imgui.h>

#include "ui/panels/side_panels.hpp"
#include "ui/platform/imgui_tip.hpp"

namespace pw::ui {
inline namespace panels {

void drawStatsPanel(const FrameReport& report) {
    if (!ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const FrameTimes& t = report.times;
    const render::FrameStats& stats = report.stats;
    ImGui::Text("Frame       %.2f ms (work %.2f)", report.frameMs, t.total);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Time between the last two frames (paced to at most 60 fps; idle when nothing changes).\n"
            "Work: the frame's own time, pacing excluded: UI %.2f ms (of it drag solve + upload %.3f),\n"
            "swapchain image %.2f, 3D view %.2f, ImGui + present %.2f",
            t.ui, t.drag, t.acquire, t.view, t.present);
    ImGui::Text("Render      %.2f ms (CPU wall)", stats.wallMs);
    tip("Record + submit + wait of the 3D view");
    if (stats.gpuMs >= 0)
        ImGui::Text("GPU         %.2f ms", stats.gpuMs);
    else
        ImGui::TextDisabled("GPU         (no timestamps)");
    tip("Timestamp queries around the frame");
    ImGui::Text("Triangles   %llu", (unsigned long long)stats.triangles());
    tip("Triangles reaching the clipper in the surface pass");
    ImGui::Text("Evaluations %llu", (unsigned long long)stats.tesInvocations);
    tip("Tessellation evaluation shader invocations");
    ImGui::Text("Patches     %u (culled %u)", stats.patches, stats.patchesCulled);
    tip("Patches drawn and patches culled by the control shader");
    if (stats.mergedWindows) {
        ImGui::Text("Merged      %u windows in %u patches", stats.mergedWindows, stats.mergedBlocks);
        tip("Net windows at one power-of-two level drawn several to a tessellated patch: the same vertices, fewer "
            "patches for this CPU renderer, which pays per patch (render --merge-windows)");
    }
    if (stats.displacedEdges) {
        ImGui::Text("Displaced   %u edges raised (to %u)", stats.displacedEdges, stats.displacementLevel);
        tip("Adaptive levels: window edges whose level the height map's detail along them raised, and the highest such level");
    }
    ImGui::Text("Draws       %u", stats.draws);
    tip("vkCmdDraw calls this frame");
}

}  // namespace panels
}  // namespace pw::ui

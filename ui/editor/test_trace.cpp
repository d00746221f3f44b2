// The test trace (ui/editor/test_trace.hpp): widgets' centres and the open modal gathered during the
// frame, the editor's state read after it, one JSON file rewritten atomically.
#include "ui/editor/test_trace.hpp"

#include <imgui.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "core/base/file_io.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/picking.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/tess/tess_domain.hpp"
#include "render/vk/device.hpp"
#include "ui/editor/editor.hpp"

namespace pw::ui {
inline namespace editor {

TestTrace::TestTrace() {
    if (const char* t = std::getenv("PATCHWORK_EDITOR_TRACE"); t && *t) {
        path_ = t;
        setItemTrace(&items_);
    }
}

TestTrace::~TestTrace() {
    if (itemTrace() == &items_) setItemTrace(nullptr);
}

void TestTrace::beginFrame() { items_.clear(); }

void TestTrace::write(const EditorSnapshot& e) {
    nlohmann::json j;
    const auto [ww, wh] = e.windowSize;
    const auto [fw, fh] = e.framebufferSize;
    const Document& doc = e.session.doc;
    const Selection& sel = e.session.sel;
    const Teaching& teaching = e.teaching;
    const render::FrameStats& stats = e.report.stats;
    j["frame"] = e.frame;
    j["generation"] = e.generation;
    j["emergencyPublished"] = e.emergencyPublished;
    j["window"] = {ww, wh};
    j["framebuffer"] = {fw, fh};
    j["file"] = e.session.path();
    j["modified"] = e.session.isModified();
    j["mode"] = int(e.mode);
    j["softOn"] = e.session.soft.on;
    j["softRadiusPx"] = e.softRadiusPixels;
    j["degraded"] = e.degraded;
    j["undoSteps"] = e.session.history().size();
    j["canUndo"] = e.session.history().canUndo();
    j["hovered"] = e.hovered;
    j["selection"] = sel.points;
    j["selectedPatch"] = sel.patch;
    j["recoverable"] = e.dialogs.recoverable.size();
    j["modal"] = items_.modal;
    j["textInput"] = ImGui::GetIO().WantTextInput;
    j["presentation"] = teaching.presentation;
    j["presentationOverlay"] = {teaching.overlaySize[0], teaching.overlaySize[1], teaching.overlayTextRight};
    j["presentationLines"] = teaching.overlayLines;
    j["stageBarRows"] = teaching.stageBarRows;
    j["debugCamera"] = teaching.debugCamera.has_value();
    j["patchesCulled"] = stats.patchesCulled;
    j["mergedWindows"] = stats.mergedWindows;
    j["vsInvocations"] = stats.vsInvocations;
    j["tcsPatches"] = stats.tcsPatches;
    j["tesInvocations"] = stats.tesInvocations;
    j["math"] = {{"on", teaching.math.on}, {"patch", teaching.math.patch}, {"u", teaching.math.u},
                 {"v", teaching.math.v},   {"lines", teaching.mathLines},  {"labels", teaching.mathLabels}};
    j["presentationScale"] = teaching.presentationScale;
    j["domainTextPixels"] = teaching.domainTextPixels;
    j["tessOuter"] = doc.tess.outer;
    j["lesson"] = {{"active", teaching.lesson.active}, {"name", teaching.lesson.name}, {"outer", teaching.shownTess(doc.tess).outer}};
    j["sweep"] = {{"playing", teaching.sweep.playing}, {"level", teaching.sweep.level}, {"seconds", teaching.sweep.seconds}};
    j["domain"] = nlohmann::json::array();
    for (size_t i = 0; i < teaching.domainPanes.size() && i < teaching.domainStats.size(); ++i) {
        const auto& o = teaching.domainPanes[i];
        const DomainCounts want = expectedDomainCounts(o.kind, o.levels, o.spacing);
        j["domain"].push_back({{"spacing", spacingName(o.spacing)},
                               {"kind", domainName(o.kind)},
                               {"vertices", teaching.domainStats[i].vertices},
                               {"primitives", teaching.domainStats[i].primitives},
                               {"title", o.title},
                               {"upperLeft", o.upperLeft},
                               {"levels", {o.levels.outer, o.levels.inner}},
                               {"shown", i < teaching.domainCounts.size() ? teaching.domainCounts[i] : std::array<uint64_t, 2>{}},
                               {"expectedVertices", want.vertices},
                               {"expectedPrimitives", want.primitives}});
    }
    j["viewPanes"] = nlohmann::json::array();
    const auto viewRects = teaching.viewPaneRects(e.layout);
    for (size_t i = 0; teaching.viewSplit() && i < viewRects.size() && i < teaching.viewPanes.size(); ++i)
        j["viewPanes"].push_back({{"spacing", spacingName(teaching.viewPanes[i].tess.spacing)},
                                  {"level", teaching.paneLevel[i]},
                                  {"rect", viewRects[i]},
                                  {"triangles", teaching.viewPanes[i].stats.triangles()}});
    j["activePane"] = teaching.activePane;
    j["layout"] = {{"domainWindow", teaching.windowRect},
                   {"domainLabels", teaching.labelBoxes},
                   {"axisGizmo", e.axisGizmo},
                   {"left", e.layout.left},
                   {"right", e.layout.right}};
    j["shaders"] = {{"open", e.shaders.open},
                    {"shown", e.shaders.shown},
                    {"inUse", e.shaders.variantsInUse},
                    {"teaching", e.shaders.teaching},
                    {"lines", e.shaders.shownLines}};
    j["items"] = items_.items;
    j["unsavedPrompt"] = e.dialogs.unsavedPromptOpen();
    j["palette"] = e.palette.open;
    j["help"] = e.help;
    j["error"] = e.dialogs.errorMessage();
    j["changedFile"] = e.dialogs.changedFile();
    j["frameMs"] = e.report.frameMs;
    j["renderMs"] = stats.wallMs;
    j["gpuMs"] = stats.gpuMs;
    j["triangles"] = stats.triangles();
    j["validationMessages"] = render::Device::validationMessageCount();
    j["patches"] = doc.patches.size();
    j["joins"] = doc.joins.size();
    j["patchIdx"] = nlohmann::json::array();
    for (const Patch& p : doc.patches) j["patchIdx"].push_back(p.idx);
    j["cursor"] = {e.session.cursor.x, e.session.cursor.y, e.session.cursor.z};
    auto edgeJson = [](const std::optional<PatchEdge>& pe) { return pe ? nlohmann::json(patchEdgeName(*pe)) : nlohmann::json(nullptr); };
    j["joinTool"] = {{"on", e.join.on},
                     {"first", edgeJson(e.join.first)},
                     {"hover", edgeJson(e.join.hover)},
                     {"preview", e.join.preview},
                     {"continuity", std::string(continuityName(e.join.continuity))}};
    j["curveTool"] = {{"on", e.curveTool.on},
                      {"points", e.curveTool.points.size()},
                      {"plane", e.curveTool.planeAxis},
                      {"snapped", e.curveTool.snapped},
                      {"hover", e.curveTool.hover ? nlohmann::json{e.curveTool.hover->x, e.curveTool.hover->y, e.curveTool.hover->z}
                                                  : nlohmann::json(nullptr)}};
    j["surfaces"] = doc.surfaces.size();
    j["curves"] = doc.curves.size();
    j["bezierTriangles"] = doc.triangles.size();
    j["selectedTriangle"] = sel.triangle;
    j["isocurves"] = doc.display.showIsocurves;
    j["maxConstraintResidual"] = e.mode == Interaction::None ? maxConstraintResidual(doc) : -1.0;
    // The live continuity readout (what the Continuity panel and the orange seams show).
    j["joinsOutOfTolerance"] = e.continuity.outOfTolerance();
    nlohmann::json curv = nlohmann::json::array();
    for (const JoinContinuity& c : e.continuity.report()) curv.push_back(c.curvatureDeviationPct);
    j["curvatureDeviationPct"] = std::move(curv);
    j["combs"] = doc.display.showCombs;
    // Where the points are on screen, in the pane the mouse works in (the whole window unless split).
    const std::array<float, 4> pane = teaching.viewSplit() ? e.viewArea : std::array<float, 4>{0.0f, 0.0f, float(ww), float(wh)};
    const auto proj = projectPoints(e.session.camera, doc.points, int(pane[2]), int(pane[3]));
    nlohmann::json pts = nlohmann::json::array();
    for (size_t i = 0; i < proj.size(); ++i) {
        if (proj[i] && i < e.usedMask.size() && e.usedMask[i])
            pts.push_back({proj[i]->x + pane[0], proj[i]->y + pane[1]});
        else
            pts.push_back(nullptr);
    }
    j["points"] = std::move(pts);
    // The interaction pane and its view-projection (column-major): tests place world points on screen.
    const ViewMatrices vm = viewMatrices(e.session.camera, double(std::max(pane[2], 1.0f)) / double(std::max(pane[3], 1.0f)));
    j["pane"] = pane;
    j["viewProj"] = nlohmann::json::array();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) j["viewProj"].push_back(vm.viewProj[c][r]);
    nlohmann::json world = nlohmann::json::array();
    for (const Vec3& p : doc.points) world.push_back({p.x, p.y, p.z});
    j["world"] = std::move(world);
    try {
        writeFileAtomic(path_, j.dump());
    } catch (...) {
    }
}

}  // namespace editor
}  // namespace pw::ui

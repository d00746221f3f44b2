// `patchwork bench --editor`: the editor's own frames while a control point is dragged, against a
// bare offscreen render of the same view, frame by frame in one run (issue 4's frame budget: the
// editor's overhead over the bare render). The drag goes through the editor's input path: the G key
// grabs the point under test and the mouse moves on a circle, one step a frame, unpaced.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include <imgui.h>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/picking.hpp"
#include "core/solve/constraint_solver.hpp"
#include "render/scene/renderer.hpp"
#include "render/targets/offscreen_target.hpp"
#include "render/vk/device.hpp"
#include "ui/editor/editor.hpp"
#include "ui/platform/app_window.hpp"
#include "ui/platform/swapchain_target.hpp"

namespace pw::ui {
inline namespace editor {

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int Editor::runBench(const EditorBenchOptions& opt) {
    if (opt.frames < 1 || opt.frames > 100000) throw InputError("bench", "--frames: must be from 1 to 100000");
    // A benchmark measures the document it was given: another session's autosave is neither offered
    // (its modal would take the keys) nor touched.
    dialogs_.offerRecovery({});
    // Step 1: the document at the benchmark's level (or a file's own settings), and a bare renderer of
    // the same size and format.
    const bool uniform = opt.level.has_value() || opt.file.empty();
    const float level = opt.level.value_or(16.0f);
    if (uniform) {
        doc_.tess.outer = {level, level, level, level};
        doc_.tess.inner = {level, level};
        doc_.tess.spacing = Spacing::Equal;
        doc_.tess.adaptive = AdaptiveMode::None;
        session_.commit("Benchmark levels");
        documentChanged(false);
    }
    char levels[96];
    if (uniform)
        std::snprintf(levels, sizeof levels, "level %g", double(level));
    else
        std::snprintf(levels, sizeof levels, "its own levels (adaptive: %s)", std::string(adaptiveName(doc_.tess.adaptive)).c_str());
    const VkExtent2D ext = window_.target().extent();
    render::OffscreenTarget bareTarget(window_.device(), ext.width, ext.height, window_.target().samples() > VK_SAMPLE_COUNT_1_BIT);
    bareTarget.setReadback(false);
    render::Renderer bare(window_.device(), bareTarget);
    bare.warmUp();
    bare.setDocument(doc_);

    // Step 2: the point to drag: the used control point nearest the middle of the view.
    const auto [W, H] = viewSize();
    const ViewMatrices vm = viewMatrices(cam_, double(W) / H);
    int point = -1;
    glm::dvec2 at{0.0};
    double best = 1e300;
    for (size_t i = 0; i < doc_.points.size(); ++i) {
        if (i >= usedMask_.size() || !usedMask_[i]) continue;
        const auto s = projectToPixel(vm, doc_.points[i], W, H);
        if (!s) continue;
        const double d = std::hypot(s->x - 0.5 * W, s->y - 0.5 * H);
        if (d < best) best = d, point = int(i), at = *s;
    }
    if (point < 0) throw InputError("bench", "--editor: no control point is in view");
    const Vec3 start = doc_.points[size_t(point)];

    // Step 3: settle (fonts, panels, first frames), then G grabs the selected point.
    sel_.clear();
    sel_.points = {uint32_t(point)};
    window_.overrideMouse(std::array<double, 2>{at.x, at.y});
    for (int i = 0; i < 10; ++i) drawFrame();
    // A frame timed as the user waits for it: input to presented (drawFrame's own total).
    const auto timedFrame = [this] {
        drawFrame();
        return report_.times.total;
    };
    window_.keyEvent(GLFW_KEY_G, 0);
    const double grabMs = timedFrame();  // the drag's start: the solver factorised for the grabbed point
    if (mode_ != Interaction::Grab) throw InputError("bench", "--editor: the G grab did not start (is the window focused?)");

    // Step 4: measured frames; the mouse moves 40 px around the point, one step a frame, and each
    // editor frame is followed by the bare render of the view it drew.
    std::vector<double> total, ui, drag, acquire, view, present, bareMs;
    double moved = 0.0, residual = 0.0;
    const double size = modelSize(doc_);
    for (int i = 0; i < opt.frames; ++i) {
        const double a = 2.0 * M_PI * double(i + 1) / 60.0;
        window_.overrideMouse(std::array<double, 2>{at.x + 40.0 * std::sin(a), at.y + 40.0 * (1.0 - std::cos(a))});
        glfwPollEvents();
        drawFrame();
        total.push_back(report_.times.total);
        ui.push_back(report_.times.ui);
        drag.push_back(report_.times.drag);
        acquire.push_back(report_.times.acquire);
        view.push_back(report_.times.view);
        present.push_back(report_.times.present);
        bareMs.push_back(bare.render(drawnOptions()).wallMs);
        moved = std::max(moved, glm::length(doc_.points[size_t(point)] - start));
        residual = std::max(residual, maxConstraintResidual(doc_));
    }
    const render::FrameStats stats = report_.stats;

    // Step 5: Esc cancels the grab; the document is as it was.
    window_.keyEvent(GLFW_KEY_ESCAPE, 0);
    drawFrame();
    window_.overrideMouse(std::nullopt);
    bool restored = mode_ == Interaction::None && doc_.points[size_t(point)] == start;
    // Step 5b: a drag that is kept: G, one step, Enter. The confirming frame commits the edit (and
    // whatever the release re-uploads), then Ctrl+Z undoes it; both frames timed.
    window_.keyEvent(GLFW_KEY_G, 0);
    drawFrame();
    window_.overrideMouse(std::array<double, 2>{at.x + 20.0, at.y});
    glfwPollEvents();
    drawFrame();
    window_.keyEvent(GLFW_KEY_ENTER, 0);
    const double releaseMs = timedFrame();
    const bool kept = mode_ == Interaction::None && doc_.points[size_t(point)] != start;
    const double afterReleaseMs = timedFrame();
    window_.keyEvent(GLFW_KEY_Z, GLFW_MOD_CONTROL);
    const double undoMs = timedFrame();
    window_.overrideMouse(std::nullopt);
    restored = restored && kept && doc_.points[size_t(point)] == start;

    // Step 6: report.
    const double frameMed = median(total), bareMed = median(bareMs);
    std::printf("editor bench: %s, %zu patches at %s, %ux%u window, %s, %d frames of a G drag, medians\n",
                session_.path().empty() ? "built-in teapot" : session_.path().c_str(), expandPatches(doc_).size(), levels, ext.width,
                ext.height, window_.device().name().c_str(), opt.frames);
    std::printf(
        "  editor frame     %8.2f ms   (UI %.2f, of it drag solve + upload %.3f; acquire %.2f; 3D view %.2f; ImGui + present %.2f)\n",
        frameMed, median(ui), median(drag), median(acquire), median(view), median(present));
    std::printf("  bare render      %8.2f ms   (the same view offscreen: record, submit, wait)\n", bareMed);
    std::printf("  editor overhead  %8.2f ms   (frame - bare render); %llu triangles a frame\n", frameMed - bareMed,
                (unsigned long long)stats.triangles());
    std::printf("  drag start %.2f ms, release %.2f ms (the next frame %.2f ms), undo %.2f ms\n", grabMs, releaseMs, afterReleaseMs,
                undoMs);
    std::printf("  point %d moved up to %.4g (model size %.4g), largest join residual %.3g, restored by Esc and by undo: %s\n", point,
                moved, size, residual, restored ? "yes" : "no");
    if (!opt.json.empty()) {
        const nlohmann::json j{{"device", window_.device().name()},
                               {"width", ext.width},
                               {"height", ext.height},
                               {"frames", opt.frames},
                               {"level", uniform ? nlohmann::json(level) : nlohmann::json(nullptr)},
                               {"adaptive", adaptiveName(doc_.tess.adaptive)},
                               {"patches", expandPatches(doc_).size()},
                               {"triangles", stats.triangles()},
                               {"frame_ms", frameMed},
                               {"ui_ms", median(ui)},
                               {"drag_ms", median(drag)},
                               {"acquire_ms", median(acquire)},
                               {"view_ms", median(view)},
                               {"present_ms", median(present)},
                               {"bare_render_ms", bareMed},
                               {"overhead_ms", frameMed - bareMed},
                               {"grab_ms", grabMs},
                               {"release_ms", releaseMs},
                               {"after_release_ms", afterReleaseMs},
                               {"undo_ms", undoMs},
                               {"point", point},
                               {"moved", moved},
                               {"model_size", size},
                               {"max_residual", residual},
                               {"restored", restored}};
        writeFileAtomic(opt.json, j.dump(2) + "\n");
    }
    if (!restored) {
        std::cerr << "patchwork bench: Esc, or Enter then undo, did not restore the dragged point\n";
        return 1;
    }
    if (window_.device().validationEnabled() && render::Device::validationMessageCount() > 0) {
        std::cerr << "patchwork bench: " << render::Device::validationMessageCount() << " Vulkan validation message(s)\n";
        return 1;
    }
    return 0;
}

}  // namespace editor
}  // namespace pw::ui

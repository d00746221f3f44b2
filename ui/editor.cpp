// Editor window, frame loop, files, undo/redo, autosave and the test trace.
#include "ui/editor.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <optional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include <imgui.h>

#include "core/camera_math.hpp"
#include "render/device.hpp"
#include "core/document_io.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "ui/imgui_layer.hpp"
#include "core/join_detect.hpp"
#include "core/limits.hpp"
#include "core/patch_ops.hpp"
#include "core/tess_presets.hpp"
#include "render/png_writer.hpp"
#include "render/renderer.hpp"
#include "render/swapchain_target.hpp"
#include "ui/x11_present.hpp"

namespace pw::ui {

namespace fs = std::filesystem;

namespace {

Editor* g_editor = nullptr;

// Our callbacks only wake the loop; the ImGui backend (installed after) chains to them.
// Cursor position as of the last motion event (event order, unlike glfwGetCursorPos on X11).
double g_cursorX = 0, g_cursorY = 0;
void onCursor(GLFWwindow*, double x, double y) {
    g_cursorX = x, g_cursorY = y;
    if (g_editor) g_editor->wake();
}
void onButton(GLFWwindow* w, int button, int action, int) {
    if (!g_editor) return;
    if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS) {
        (void)w;
        g_editor->leftPress(g_cursorX, g_cursorY);
    }
    g_editor->wake();
}
void onScroll(GLFWwindow*, double, double) { if (g_editor) g_editor->wake(); }
void onKey(GLFWwindow*, int key, int, int action, int mods) {
    if (!g_editor) return;
    if (action != GLFW_RELEASE) g_editor->keyEvent(key, mods);
    g_editor->wake();
}
void onChar(GLFWwindow*, unsigned int) { if (g_editor) g_editor->wake(); }
void onSize(GLFWwindow*, int, int) { if (g_editor) g_editor->wake(); }
void onRefresh(GLFWwindow*) { if (g_editor) g_editor->wake(); }
void onFocus(GLFWwindow*, int) { if (g_editor) g_editor->wake(); }
void onEnter(GLFWwindow*, int) { if (g_editor) g_editor->wake(); }

const char* kNoDisplay =
    "patchwork: no display (DISPLAY/WAYLAND_DISPLAY unset or unreachable); use `patchwork render FILE -o out.png` for "
    "headless images\n";

fs::path recentFile() { return autosaveDirectory() / "recent.txt"; }

}  // namespace

namespace {

// Opens the editor's window and runs `body` on it, then closes GLFW. The size is `fixed` (pixels at
// content scale 1) or 1600x900 scaled to the monitor (PATCHWORK_WINDOW_SIZE overrides). Exit 2 with
// a message when there is no display.
int withEditorWindow(const std::optional<std::array<int, 2>>& fixed, const std::function<int(GLFWwindow*)>& body) {
    const char* d = std::getenv("DISPLAY");
    const char* w = std::getenv("WAYLAND_DISPLAY");
    if ((!d || !*d) && (!w || !*w)) {
        std::cerr << kNoDisplay;
        return 2;
    }
    glfwSetErrorCallback([](int, const char* msg) { std::fprintf(stderr, "patchwork: glfw: %s\n", msg); });
    if (!glfwInit()) {
        std::cerr << kNoDisplay;
        return 2;
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw InputError("editor", "GLFW found no Vulkan loader/driver with window-system support");
    }
    // 1600x900, or 90 % of the monitor's work area where that is smaller (the size is scaled by
    // the content scale below, GLFW_SCALE_TO_MONITOR).
    int width = 1600, height = 900;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        int wx = 0, wy = 0, ww = 0, wh = 0;
        float sx = 1.0f, sy = 1.0f;
        glfwGetMonitorWorkarea(monitor, &wx, &wy, &ww, &wh);
        glfwGetMonitorContentScale(monitor, &sx, &sy);
        if (ww > 0 && wh > 0 && sx > 0.0f && sy > 0.0f) {
            width = std::max(640, std::min(width, int(0.9f * float(ww) / sx)));
            height = std::max(400, std::min(height, int(0.9f * float(wh) / sy)));
        }
    }
    if (const char* ws = std::getenv("PATCHWORK_WINDOW_SIZE"); ws && *ws && !fixed) {
        if (std::sscanf(ws, "%dx%d", &width, &height) != 2 || width < 64 || height < 64 || width > 16384 || height > 16384) {
            glfwTerminate();
            throw InputError("PATCHWORK_WINDOW_SIZE", std::string("expected WIDTHxHEIGHT (64..16384), got '") + ws + "'");
        }
    }
    if (fixed) width = (*fixed)[0], height = (*fixed)[1];
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, fixed ? GLFW_FALSE : GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(width, height, "Patchwork", nullptr, nullptr);
    if (!window) {
        glfwTerminate();
        std::cerr << kNoDisplay;
        return 2;
    }
    int rc = 0;
    try {
        rc = body(window);
    } catch (...) {
        glfwDestroyWindow(window);
        glfwTerminate();
        throw;
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return rc;
}

}  // namespace

int runEditor(const std::string& file) {
    return withEditorWindow(std::nullopt, [&](GLFWwindow* window) {
        Editor editor(window, file);
        return editor.run();
    });
}

int runEditorBench(const EditorBenchOptions& options) {
    return withEditorWindow(std::array<int, 2>{options.width, options.height}, [&](GLFWwindow* window) {
        Editor editor(window, options.file);
        return editor.runBench(options);
    });
}

Editor::Editor(GLFWwindow* window, const std::string& file) : window_(window) {
    g_editor = this;
    if (const char* t = std::getenv("PATCHWORK_EDITOR_TRACE"); t && *t) tracePath_ = t;
    if (const char* a = std::getenv("PATCHWORK_AUTOSAVE_SECONDS"); a && *a) autosaveSeconds_ = std::max(0.5, std::atof(a));

    // Step 1: device with the window-system extensions, surface, swapchain target.
    render::DeviceOptions opt;
    uint32_t n = 0;
    const char** exts = glfwGetRequiredInstanceExtensions(&n);
    for (uint32_t i = 0; i < n; ++i) opt.instanceExtensions.push_back(exts[i]);
    opt.deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    dev_ = std::make_unique<render::Device>(opt);
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window_, &fbw, &fbh);
    // A CPU device on X11 puts its frames into the window itself (ui/x11_present.hpp says why);
    // everything else presents through a Vulkan swapchain.
    if (dev_->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) hostPresenter_ = X11Presenter::create(window_);
    if (hostPresenter_) {
        target_ = std::make_unique<render::SwapchainTarget>(
            *dev_, VK_NULL_HANDLE, VkExtent2D{uint32_t(fbw), uint32_t(fbh)},
            [p = hostPresenter_.get()](const uint8_t* bgra, VkExtent2D ext, uint32_t rowBytes) { p->present(bgra, ext, rowBytes); });
    } else {
        if (glfwCreateWindowSurface(dev_->instance(), window_, nullptr, &surface_) != VK_SUCCESS)
            throw render::VulkanError("cannot create a Vulkan surface for the window");
        target_ = std::make_unique<render::SwapchainTarget>(*dev_, surface_, VkExtent2D{uint32_t(fbw), uint32_t(fbh)});
    }
    renderer_ = std::make_unique<render::Renderer>(*dev_, *target_);

    // Step 2: input callbacks (before ImGui so it chains to them), then ImGui.
    glfwSetCursorPosCallback(window_, onCursor);
    glfwSetMouseButtonCallback(window_, onButton);
    glfwSetScrollCallback(window_, onScroll);
    glfwSetKeyCallback(window_, onKey);
    glfwSetCharCallback(window_, onChar);
    glfwSetWindowSizeCallback(window_, onSize);
    glfwSetFramebufferSizeCallback(window_, onSize);
    glfwSetWindowRefreshCallback(window_, onRefresh);
    glfwSetWindowFocusCallback(window_, onFocus);
    glfwSetCursorEnterCallback(window_, onEnter);
    float sx = 1.0f, sy = 1.0f;
    glfwGetWindowContentScale(window_, &sx, &sy);
    uiScale_ = std::max(1.0f, std::max(sx, sy));
    imgui_ = std::make_unique<ImGuiLayer>(*dev_, window_, *target_, uiScale_);
    bindShortcuts();

    // Step 3: the document, recent files, crash recovery.
    browseDir_ = fs::current_path();
    {
        std::ifstream in(recentFile());
        for (std::string line; std::getline(in, line);)
            if (!line.empty()) recent_.push_back(line);
    }
    recoverable_ = findRecoverableAutosaves();
    offerRecovery_ = !recoverable_.empty();
    // A bad file on the command line throws InputError: reported with exit 2 like the other commands.
    if (file.empty())
        setDocument(builtinTeapot(), "");
    else
        setDocument(loadDocument(file), file);
    // Warm the pipelines on the first acquired image (the first real frame then pays no JIT).
    if (target_->acquire()) {
        renderer_->warmUp();
        swapchainDirty_ = false;
        // Present it through the normal path on the first frame.
        imgui_->newFrame();
        ImGui::Render();
        target_->submitAndPresent(imgui_->record({}, {}));
    }
    lastAutosave_ = std::chrono::steady_clock::now();
}

Editor::~Editor() {
    if (dev_) vkDeviceWaitIdle(dev_->device());
    imgui_.reset();
    renderer_.reset();
    target_.reset();
    hostPresenter_.reset();
    if (surface_) vkDestroySurfaceKHR(dev_->instance(), surface_, nullptr);
    g_editor = nullptr;
}

void Editor::setDocument(Document doc, const std::string& path) {
    session_.reset(std::move(doc), path);
    documentReplaced();
}

void Editor::documentReplaced() {
    seenSerial_ = session_.documentSerial();
    hovered_ = -1;
    inspectorSolver_.reset();
    // Files without a stored view (or the teapot) are framed; PATCHWORK_EDITOR_VIEW (tests) names a view.
    const char* fixed = std::getenv("PATCHWORK_EDITOR_VIEW");
    if (fixed && *fixed)
        if (auto c = applyNamedView(cam_, fixed)) cam_ = *c;
    if (cam_ == Camera{} || (fixed && *fixed)) frameBox(computeBounds(doc_.points));
    // New geometry goes where the view looks until the user places the 3D cursor.
    session_.cursor = Vec3(cam_.target[0], cam_.target[1], cam_.target[2]);
    documentChanged(true);
    if (!session_.path().empty()) addRecent(session_.path());
    glfwSetWindowTitle(window_, ("Patchwork — " + session_.title()).c_str());
}

void Editor::documentChanged(bool topology) {
    renderer_->setDocument(doc_);
    if (topology) usedMask_ = usedPointMask(doc_);
    clampSelection(sel_, doc_);
    seenVersion_ = session_.version();
    seenTopology_ = session_.topologyVersion();
    ++docVersion_;
    wake();
}

void Editor::runCommand(const std::vector<std::string>& words, bool guarded) {
    try {
        commands_.run(session_, *this, words, guarded);
    } catch (const std::exception& e) {
        showError(std::string("The command did not run; the document is unchanged.\n\n") + e.what());
    }
    if (session_.documentSerial() != seenSerial_)
        documentReplaced();
    else if (session_.version() != seenVersion_)
        documentChanged(session_.topologyVersion() != seenTopology_);
    wake();
}

void Editor::setPointHeld(uint32_t p, const Vec3& position) {
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(position[k]) || std::abs(position[k]) > limits::kMaxCoordinate) {
            char msg[160];
            std::snprintf(msg, sizeof msg, "A point coordinate must be a finite number within ±%g; %g was not applied.",
                          limits::kMaxCoordinate, position[k]);
            showError(msg);
            return;
        }
    // Numeric edits go through the solver like a drag, with this point held; the factorisation is
    // kept while the same point is edited against the same committed document.
    if (!inspectorSolver_ || inspectorPoint_ != p || inspectorGeneration_ != session_.generation()) {
        inspectorSolver_ = std::make_unique<DragSolver>(session_.committed(), std::vector<uint32_t>{p});
        inspectorPoint_ = p;
        inspectorGeneration_ = session_.generation();
    }
    std::vector<Vec3> pts = session_.committed().points;
    pts[p] = position;
    inspectorSolver_->project(pts);
    doc_.points = std::move(pts);
    documentChanged(false);
}

void Editor::showError(const std::string& message) {
    errorMessage_ = message;
    openError_ = true;
    wake();
}

void Editor::addRecent(const std::string& path) {
    std::string abs = path;
    std::error_code ec;
    const fs::path a = fs::absolute(path, ec);
    if (!ec) abs = a.string();
    std::erase(recent_, abs);
    recent_.insert(recent_.begin(), abs);
    if (recent_.size() > 10) recent_.resize(10);
    try {
        fs::create_directories(recentFile().parent_path(), ec);
        std::string text;
        for (const std::string& r : recent_) text += r + "\n";
        writeFileAtomic(recentFile(), text);
    } catch (...) {
        // Recent files are a convenience: an unwritable state directory is not an error.
    }
}

void Editor::recoverAutosave() {
    if (recoverable_.empty()) return;
    const AutosaveEntry e = recoverable_.front();
    try {
        setDocument(loadDocument(e.document), e.originalPath);
        session_.setForceModified(true);  // the recovered state differs from the file on disk
        removeAutosave(e);
        recoverable_.erase(recoverable_.begin());
        status("Recovered autosave of " + (e.originalPath.empty() ? std::string("untitled") : e.originalPath));
    } catch (const std::exception& ex) {
        showError(std::string("Could not recover the autosave.\n\n") + ex.what());
    }
}

void Editor::autosaveTick() {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - lastAutosave_).count() < autosaveSeconds_) return;
    lastAutosave_ = now;
    if (!isModified() || mode_ == Interaction::DragPoints || mode_ == Interaction::Grab) return;
    try {
        const Document out = session_.documentToSave();
        autosaver_.save(out, session_.path());
    } catch (const std::exception& e) {
        status_ = std::string("Autosave failed: ") + e.what();
        statusTime_ = now;
    }
}

int Editor::run() {
    using clock = std::chrono::steady_clock;
    while (!quit_) {
        // Step 1: events. Idle (nothing to redraw): block until an event or the autosave tick.
        if (wakeFrames_ > 0)
            glfwPollEvents();
        else
            glfwWaitEventsTimeout(0.5);
        autosaveTick();
        if (glfwWindowShouldClose(window_)) {
            glfwSetWindowShouldClose(window_, GLFW_FALSE);
            runCommand("quit");
            if (quit_) break;
        }
        // Step 2: size changes; a minimised (iconified or zero-size) window waits and draws nothing.
        int fbw = 0, fbh = 0;
        glfwGetFramebufferSize(window_, &fbw, &fbh);
        if (fbw == 0 || fbh == 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED)) {
            glfwWaitEventsTimeout(0.5);
            continue;
        }
        const VkExtent2D ext = target_->extent();
        if (swapchainDirty_ || !target_->valid() || ext.width != uint32_t(fbw) || ext.height != uint32_t(fbh)) {
            target_->recreate({uint32_t(fbw), uint32_t(fbh)});
            imgui_->swapchainRecreated();
            swapchainDirty_ = false;
            wake();
        }
        if (wakeFrames_ <= 0 && !screenshotRequested_) continue;  // nothing changed: draw nothing
        // Step 3: pace (FIFO is not paced under Xvfb): at most ~60 frames per second.
        const auto next = lastFrame_ + std::chrono::microseconds(16667);
        if (clock::now() < next) std::this_thread::sleep_until(next);
        const auto t0 = clock::now();
        frameMs_ = std::chrono::duration<double, std::milli>(t0 - lastFrame_).count();
        lastFrame_ = t0;
        frame();
        if (wakeFrames_ > 0) --wakeFrames_;
    }
    autosaver_.discard();
    return 0;
}

render::RenderOptions Editor::viewOptions() const {
    render::RenderOptions o = render::optionsFromDocument(doc_);
    o.camera = cam_;
    o.hoveredPoint = hovered_;
    o.selectedPoint = sel_.points.empty() ? -1 : int(sel_.points.front());
    if (showGround_) o.groundGridStep = niceGridStep(modelSize(doc_));
    return o;
}

void Editor::frame() {
    using clock = std::chrono::steady_clock;
    auto ms = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
    const auto t0 = clock::now();
    dragMs_ = 0.0;
    // Step 1: UI and viewport input. ImGui 1.86 only sees key *state*: a key pressed and released
    // between two frames (fast typing, xdotool) is held down for this one frame so it is not lost.
    ImGuiIO& io = ImGui::GetIO();
    std::vector<int> forced;
    for (const auto& [key, mods] : keyQueue_) {
        if (key < 0 || key >= int(IM_ARRAYSIZE(io.KeysDown)) || io.KeysDown[key]) continue;
        io.KeysDown[key] = true;
        forced.push_back(key);
        io.KeyCtrl = io.KeyCtrl || (mods & GLFW_MOD_CONTROL);
        io.KeyShift = io.KeyShift || (mods & GLFW_MOD_SHIFT);
        io.KeyAlt = io.KeyAlt || (mods & GLFW_MOD_ALT);
    }
    panelRects_.clear();
    imgui_->newFrame();
    if (benchMouse_) io.MousePos = ImVec2(float((*benchMouse_)[0]), float((*benchMouse_)[1]));
    viewportInput();
    teachingInput();
    if (!presentation_) drawViewportOverlays();
    drawPaneCaptions();
    drawUi();
    ImGui::Render();
    keyQueue_.clear();
    if (!forced.empty()) {
        for (int key : forced) io.KeysDown[key] = glfwGetKey(window_, key) == GLFW_PRESS;
        io.KeyCtrl = glfwGetKey(window_, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(window_, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
        io.KeyShift = glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
        io.KeyAlt = glfwGetKey(window_, GLFW_KEY_LEFT_ALT) == GLFW_PRESS || glfwGetKey(window_, GLFW_KEY_RIGHT_ALT) == GLFW_PRESS;
        wake();  // one more frame sees the release
    }
    leftPressed_ = false;
    const auto t1 = clock::now();

    // Step 2: the 3D view into the swapchain image.
    if (!target_->acquire()) {
        swapchainDirty_ = true;
        return;
    }
    const auto t2 = clock::now();
    renderView(viewOptions());
    drawDomainPanes();
    if (screenshotRequested_) {
        screenshotRequested_ = false;
        try {
            const std::vector<uint8_t> px = target_->readCurrentImage();
            if (px.empty()) throw OutputError(screenshotPath_, "the swapchain images cannot be read back on this device");
            render::writePng(screenshotPath_, target_->extent().width, target_->extent().height, px);
            status_ = "Screenshot saved to " + screenshotPath_;
            statusTime_ = std::chrono::steady_clock::now();
        } catch (const std::exception& e) {
            showError(std::string("Could not save the screenshot.\n\n") + e.what());
        }
    }
    // Step 3: ImGui on top, present.
    const auto t3 = clock::now();
    const ImVec4 panel = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    if (!target_->submitAndPresent(imgui_->record(panelRects_, {panel.x, panel.y, panel.z, 1.0f}))) swapchainDirty_ = true;
    const auto t4 = clock::now();
    frameTimes_ = {ms(t0, t1), dragMs_, ms(t1, t2), ms(t2, t3), ms(t3, t4), ms(t0, t4)};
    ++frameCount_;
    if (!tracePath_.empty()) writeTrace();
}

void Editor::writeTrace() {
    nlohmann::json j;
    int ww = 0, wh = 0, fw = 0, fh = 0;
    glfwGetWindowSize(window_, &ww, &wh);
    glfwGetFramebufferSize(window_, &fw, &fh);
    j["frame"] = frameCount_;
    j["window"] = {ww, wh};
    j["framebuffer"] = {fw, fh};
    j["file"] = session_.path();
    j["modified"] = isModified();
    j["mode"] = int(mode_);
    j["undoSteps"] = session_.history().size();
    j["canUndo"] = session_.history().canUndo();
    j["hovered"] = hovered_;
    j["selection"] = sel_.points;
    j["selectedPatch"] = sel_.patch;
    j["recoverable"] = recoverable_.size();
    j["modal"] = openModal_;
    j["textInput"] = ImGui::GetIO().WantTextInput;
    j["presentation"] = presentation_;
    j["tessOuter"] = doc_.tess.outer;
    j["sweep"] = {{"playing", sweep_.playing}, {"level", sweep_.level}};
    j["domain"] = nlohmann::json::array();
    for (size_t i = 0; i < domainPanes_.size() && i < domainStats_.size(); ++i) {
        const auto& o = domainPanes_[i];
        const DomainCounts want = expectedDomainCounts(o.kind, o.levels, o.spacing);
        j["domain"].push_back({{"spacing", spacingName(o.spacing)}, {"kind", domainName(o.kind)}, {"vertices", domainStats_[i].vertices},
                               {"primitives", domainStats_[i].primitives}, {"expectedVertices", want.vertices},
                               {"expectedPrimitives", want.primitives}});
    }  // a text field has the keyboard
    j["viewPanes"] = nlohmann::json::array();
    const auto viewRects = viewPaneRects();
    for (size_t i = 0; viewSplit() && i < viewRects.size() && i < viewPanes_.size(); ++i)
        j["viewPanes"].push_back({{"spacing", spacingName(viewPanes_[i].tess.spacing)},
                                  {"level", paneLevel_[i]},
                                  {"rect", viewRects[i]},
                                  {"triangles", viewPanes_[i].stats.triangles()}});
    j["activePane"] = activePane_;
    j["shaders"] = {{"open", showShaders_}, {"shown", shaderShown_}, {"inUse", shaderVariantsInUse_}};
    j["items"] = traceItems_;
    j["unsavedPrompt"] = !pendingCommand_.empty();
    j["palette"] = showPalette_;
    j["help"] = showHelp_;
    j["error"] = errorMessage_;
    j["frameMs"] = frameMs_;
    j["renderMs"] = stats_.wallMs;
    j["gpuMs"] = stats_.gpuMs;
    j["triangles"] = stats_.triangles();
    j["validationMessages"] = render::Device::validationMessageCount();
    j["patches"] = doc_.patches.size();
    j["joins"] = doc_.joins.size();
    j["surfaces"] = doc_.surfaces.size();
    j["curves"] = doc_.curves.size();
    j["bezierTriangles"] = doc_.triangles.size();
    j["selectedTriangle"] = sel_.triangle;
    j["isocurves"] = doc_.display.showIsocurves;
    j["maxConstraintResidual"] = mode_ == Interaction::None ? maxConstraintResidual(doc_) : -1.0;
    // Where the points are on screen, in the pane the mouse works in (the whole window unless split).
    const std::array<float, 4> pane = viewSplit() ? viewArea_ : std::array<float, 4>{0.0f, 0.0f, float(ww), float(wh)};
    const auto proj = projectPoints(cam_, doc_.points, int(pane[2]), int(pane[3]));
    nlohmann::json pts = nlohmann::json::array();
    for (size_t i = 0; i < proj.size(); ++i) {
        if (proj[i] && i < usedMask_.size() && usedMask_[i])
            pts.push_back({proj[i]->x + pane[0], proj[i]->y + pane[1]});
        else
            pts.push_back(nullptr);
    }
    j["points"] = std::move(pts);
    nlohmann::json world = nlohmann::json::array();
    for (const Vec3& p : doc_.points) world.push_back({p.x, p.y, p.z});
    j["world"] = std::move(world);
    try {
        writeFileAtomic(tracePath_, j.dump());
    } catch (...) {
    }
}

}  // namespace pw::ui

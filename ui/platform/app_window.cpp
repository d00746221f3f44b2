// The editor's window: GLFW, the Vulkan device, surface and swapchain target, host presentation,
// ImGui, input callbacks and the paced frame loop (ui/platform/app_window.hpp).
#include "ui/platform/app_window.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/edit/autosave.hpp"
#include "render/targets/png_writer.hpp"
#include "render/vk/device.hpp"
#include "ui/platform/imgui_layer.hpp"
#include "ui/platform/swapchain_target.hpp"
#include "ui/platform/x11_present.hpp"

namespace pw::ui {
inline namespace platform {

namespace {

AppWindow* g_window = nullptr;

// Our callbacks only wake the loop; the ImGui backend (installed after) chains to them.
// Cursor position as of the last motion event (event order, unlike glfwGetCursorPos on X11).
double g_cursorX = 0, g_cursorY = 0;
void onCursor(GLFWwindow*, double x, double y) {
    g_cursorX = x, g_cursorY = y;
    if (g_window) g_window->wake();
}
void onButton(GLFWwindow*, int button, int action, int) {
    if (!g_window) return;
    if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS) g_window->leftPressAt(g_cursorX, g_cursorY);
    g_window->wake();
}
void onScroll(GLFWwindow*, double, double) {
    if (g_window) g_window->wake();
}
void onKey(GLFWwindow*, int key, int, int action, int mods) {
    if (!g_window) return;
    if (action != GLFW_RELEASE) g_window->keyEvent(key, mods);
    g_window->wake();
}
void onChar(GLFWwindow*, unsigned int) {
    if (g_window) g_window->wake();
}
void onSize(GLFWwindow*, int, int) {
    if (g_window) g_window->wake();
}
void onRefresh(GLFWwindow*) {
    if (g_window) g_window->wake();
}
void onFocus(GLFWwindow*, int) {
    if (g_window) g_window->wake();
}
void onEnter(GLFWwindow*, int) {
    if (g_window) g_window->wake();
}

const char* kNoDisplay =
    "patchwork: no display (DISPLAY/WAYLAND_DISPLAY unset or unreachable); use `patchwork render FILE -o out.png` for "
    "headless images\n";

// Where the size of the last editor window is kept ("WIDTHxHEIGHT" before content scaling).
std::filesystem::path windowSizeFile() { return autosaveDirectory() / "window.txt"; }

std::optional<std::array<int, 2>> rememberedWindowSize() {
    // Not a small regular file (a FIFO kept the editor from opening): the default size.
    std::istringstream in;
    try {
        if (std::error_code ec; !std::filesystem::exists(windowSizeFile(), ec)) return std::nullopt;
        in.str(readFileLimited(windowSizeFile(), 4096));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "patchwork: the last window size was not read (%s); the default size is used\n", e.what());
        return std::nullopt;
    }
    int w = 0, h = 0;
    char x = 0;
    if (!(in >> w >> x >> h) || x != 'x' || w < 640 || h < 400 || w > 16384 || h > 16384) return std::nullopt;
    return std::array<int, 2>{w, h};
}

// The size the window had, or 1600x900 the first time; at most 90 % of the monitor's work area
// (the size is scaled by the content scale, GLFW_SCALE_TO_MONITOR); PATCHWORK_WINDOW_SIZE
// overrides unless the size is fixed.
std::array<int, 2> windowSizeToOpen(const std::optional<std::array<int, 2>>& fixed) {
    if (fixed) return *fixed;
    int width = 1600, height = 900;
    if (const auto last = rememberedWindowSize()) {
        width = (*last)[0];
        height = (*last)[1];
    }
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
    if (const char* ws = std::getenv("PATCHWORK_WINDOW_SIZE"); ws && *ws) {
        if (std::sscanf(ws, "%dx%d", &width, &height) != 2 || width < 64 || height < 64 || width > 16384 || height > 16384)
            throw InputError("PATCHWORK_WINDOW_SIZE", std::string("expected WIDTHxHEIGHT (64..16384), got '") + ws + "'");
    }
    return {width, height};
}

}  // namespace

int AppWindow::open(const std::optional<std::array<int, 2>>& fixed, const std::function<int(AppWindow&)>& body) {
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
    std::array<int, 2> size{};
    try {
        size = windowSizeToOpen(fixed);
    } catch (...) {
        glfwTerminate();
        throw;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, fixed ? GLFW_FALSE : GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(size[0], size[1], "Patchwork", nullptr, nullptr);
    if (!window) {
        glfwTerminate();
        std::cerr << kNoDisplay;
        return 2;
    }
    int rc = 0;
    try {
        AppWindow app(window);
        rc = body(app);
        if (!fixed) app.rememberSize();
    } catch (...) {
        glfwDestroyWindow(window);
        glfwTerminate();
        throw;
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return rc;
}

void AppWindow::rememberSize() const {
    const auto [w, h] = windowSize();
    float sx = 1.0f, sy = 1.0f;
    glfwGetWindowContentScale(window_, &sx, &sy);
    if (w <= 0 || h <= 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED)) return;
    try {
        ensurePrivateDirectory(windowSizeFile().parent_path());
        writeFileAtomic(windowSizeFile(), std::to_string(int(float(w) / std::max(sx, 1.0f))) + "x" +
                                              std::to_string(int(float(h) / std::max(sy, 1.0f))) + "\n");
    } catch (const std::exception&) {
        // A convenience, like the recent files: an unwritable state directory is not an error.
    }
}

AppWindow::AppWindow(GLFWwindow* window) : window_(window) {
    g_window = this;
    // Step 1: device with the window-system extensions, surface, swapchain target.
    render::DeviceOptions opt;
    uint32_t n = 0;
    const char** exts = glfwGetRequiredInstanceExtensions(&n);
    for (uint32_t i = 0; i < n; ++i) opt.instanceExtensions.push_back(exts[i]);
    opt.deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    dev_ = std::make_unique<render::Device>(opt);
    const auto [fbw, fbh] = framebufferSize();
    // A CPU device on X11 puts its frames into the window itself (ui/platform/x11_present.hpp says why);
    // everything else presents through a Vulkan swapchain.
    if (dev_->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) hostPresenter_ = X11Presenter::create(window_);
    if (hostPresenter_) {
        target_ = std::make_unique<SwapchainTarget>(
            *dev_, VK_NULL_HANDLE, VkExtent2D{uint32_t(fbw), uint32_t(fbh)},
            [p = hostPresenter_.get()](const uint8_t* bgra, VkExtent2D ext, uint32_t rowBytes) { p->present(bgra, ext, rowBytes); });
    } else {
        if (glfwCreateWindowSurface(dev_->instance(), window_, nullptr, &surface_) != VK_SUCCESS)
            throw render::VulkanError("cannot create a Vulkan surface for the window");
        target_ = std::make_unique<SwapchainTarget>(*dev_, surface_, VkExtent2D{uint32_t(fbw), uint32_t(fbh)});
    }

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
}

AppWindow::~AppWindow() {
    if (dev_) vkDeviceWaitIdle(dev_->device());
    imgui_.reset();
    target_.reset();
    hostPresenter_.reset();
    if (surface_) vkDestroySurfaceKHR(dev_->instance(), surface_, nullptr);
    g_window = nullptr;
}

std::array<int, 2> AppWindow::windowSize() const {
    int w = 0, h = 0;
    glfwGetWindowSize(window_, &w, &h);
    return {w, h};
}

std::array<int, 2> AppWindow::framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {w, h};
}

void AppWindow::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

bool AppWindow::keyPressed(int key, int mods) const {
    constexpr int kMask = GLFW_MOD_CONTROL | GLFW_MOD_SHIFT | GLFW_MOD_ALT | GLFW_MOD_SUPER;
    for (const auto& [k, m] : keyQueue_)
        if (k == key && (m & kMask) == mods) return true;
    return false;
}

std::optional<std::array<double, 2>> AppWindow::leftPress() const {
    if (!leftPressed_) return std::nullopt;
    return leftPress_;
}

void AppWindow::run(WindowClient& client) {
    using clock = std::chrono::steady_clock;
    while (!client.quitRequested()) {
        // Step 1: events. Idle (nothing to redraw): block until an event or the autosave tick.
        if (wakeFrames_ > 0)
            glfwPollEvents();
        else
            glfwWaitEventsTimeout(0.5);
        client.idleTick();
        if (glfwWindowShouldClose(window_)) {
            glfwSetWindowShouldClose(window_, GLFW_FALSE);
            client.closeRequested();
            if (client.quitRequested()) break;
        }
        // Step 2: size changes; a minimised (iconified or zero-size) window waits and draws nothing.
        const auto [fbw, fbh] = framebufferSize();
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
        if (wakeFrames_ <= 0 && !client.frameWanted()) continue;  // nothing changed: draw nothing
        // Step 3: pace (FIFO is not paced under Xvfb): at most ~60 frames per second.
        const auto next = lastFrame_ + std::chrono::microseconds(16667);
        if (clock::now() < next) std::this_thread::sleep_until(next);
        const auto t0 = clock::now();
        frameMs_ = std::chrono::duration<double, std::milli>(t0 - lastFrame_).count();
        lastFrame_ = t0;
        client.drawFrame();
        if (wakeFrames_ > 0) --wakeFrames_;
    }
}

void AppWindow::beginUi() {
    // ImGui 1.86 only sees key *state*: a key pressed and released between two frames (fast
    // typing, xdotool) is held down for this one frame so it is not lost.
    ImGuiIO& io = ImGui::GetIO();
    forcedKeys_.clear();
    for (const auto& [key, mods] : keyQueue_) {
        if (key < 0 || key >= int(IM_ARRAYSIZE(io.KeysDown)) || io.KeysDown[key]) continue;
        io.KeysDown[key] = true;
        forcedKeys_.push_back(key);
        io.KeyCtrl = io.KeyCtrl || (mods & GLFW_MOD_CONTROL);
        io.KeyShift = io.KeyShift || (mods & GLFW_MOD_SHIFT);
        io.KeyAlt = io.KeyAlt || (mods & GLFW_MOD_ALT);
    }
    imgui_->newFrame();
    if (mouseOverride_) io.MousePos = ImVec2(float((*mouseOverride_)[0]), float((*mouseOverride_)[1]));
}

void AppWindow::endUi() {
    ImGui::Render();
    keyQueue_.clear();
    if (!forcedKeys_.empty()) {
        ImGuiIO& io = ImGui::GetIO();
        auto down = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS; };
        for (int key : forcedKeys_) io.KeysDown[key] = down(key);
        io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL) || down(GLFW_KEY_RIGHT_CONTROL);
        io.KeyShift = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
        io.KeyAlt = down(GLFW_KEY_LEFT_ALT) || down(GLFW_KEY_RIGHT_ALT);
        forcedKeys_.clear();
        wake();  // one more frame sees the release
    }
    leftPressed_ = false;
}

bool AppWindow::acquire() {
    if (target_->acquire()) return true;
    swapchainDirty_ = true;
    return false;
}

void AppWindow::present(std::span<const std::array<float, 4>> fills) {
    const ImVec4 panel = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    if (!target_->submitAndPresent(imgui_->record(fills, {panel.x, panel.y, panel.z, 1.0f}))) swapchainDirty_ = true;
}

void AppWindow::presentEmpty() {
    swapchainDirty_ = false;
    imgui_->newFrame();
    ImGui::Render();
    target_->submitAndPresent(imgui_->record({}, {}));
}

void AppWindow::writeScreenshot(const std::string& path, float cropLeft, float cropRight) {
    checkOutputPath(path);
    const std::vector<uint8_t> px = target_->readCurrentImage();
    if (px.empty()) throw OutputError(path, "the swapchain images cannot be read back on this device");
    // The crop is in window units; the image is in framebuffer pixels (HiDPI scales them).
    const uint32_t w = target_->extent().width, h = target_->extent().height;
    const double scale = double(w) / std::max(1, windowSize()[0]);
    const uint32_t x0 = std::min(w - 1, uint32_t(std::max(0.0, cropLeft * scale)));
    const uint32_t x1 = std::max(x0 + 1, w - std::min(w - x0 - 1, uint32_t(std::max(0.0, cropRight * scale))));
    std::vector<uint8_t> out;
    out.reserve(size_t(x1 - x0) * h * 4);
    for (uint32_t y = 0; y < h; ++y) out.insert(out.end(), px.begin() + (size_t(y) * w + x0) * 4, px.begin() + (size_t(y) * w + x1) * 4);
    render::writePng(path, x1 - x0, h, out);
}

}  // namespace platform
}  // namespace pw::ui

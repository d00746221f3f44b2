// The editor's window and presentation layer: the GLFW window, the Vulkan device with its surface
// and swapchain target (ui/platform/swapchain_target.*), host presentation on CPU devices under X11
// (ui/platform/x11_present.*), the ImGui layer (ui/platform/imgui_layer.*), the input callbacks, and the frame loop
// (own 60 fps pacing, idle in glfwWaitEventsTimeout when nothing changes, resize / minimise /
// out-of-date swapchains). What is drawn is the client's (ui/editor/editor.hpp); this layer knows no
// document.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

struct GLFWwindow;

namespace pw::render {
inline namespace vk {
class Device;
}  // namespace vk
}  // namespace pw::render

namespace pw::ui {
inline namespace platform {

class SwapchainTarget;  // ui/platform/swapchain_target.hpp

class ImGuiLayer;
class X11Presenter;

// What the frame loop asks of the program drawing into the window.
class WindowClient {
public:
    virtual ~WindowClient() = default;
    virtual bool quitRequested() const = 0;  // the loop ends
    virtual void idleTick() = 0;             // after every wait for events (autosave)
    virtual void closeRequested() = 0;       // the window's close button (may set quitRequested)
    virtual bool frameWanted() const = 0;    // draw a frame even when nothing woke the loop
    virtual void drawFrame() = 0;            // one frame: beginUi ... endUi, acquire, present
};

class AppWindow {
public:
    // Opens the window and runs `body` on it, then closes GLFW. The size is `fixed` (pixels at
    // content scale 1) or 1600x900 scaled to the monitor (PATCHWORK_WINDOW_SIZE overrides). Exit 2
    // with a message when there is no display.
    static int open(const std::optional<std::array<int, 2>>& fixed, const std::function<int(AppWindow&)>& body);
    ~AppWindow();
    AppWindow(const AppWindow&) = delete;
    AppWindow& operator=(const AppWindow&) = delete;

    render::Device& device() { return *dev_; }
    SwapchainTarget& target() { return *target_; }
    ImGuiLayer& imgui() { return *imgui_; }
    float uiScale() const { return uiScale_; }  // monitor content scale (HiDPI), at least 1
    std::array<int, 2> windowSize() const;
    std::array<int, 2> framebufferSize() const;
    void setTitle(const std::string& title);

    // Input, from the GLFW callbacks. ImGui popups and hover states settle over a few frames.
    void wake() { wakeFrames_ = 8; }
    // Key presses since the last frame with their modifiers (ImGui 1.86 keeps only key state, so a
    // press and release between two frames would be lost); the benchmark injects keys here too.
    void keyEvent(int key, int mods) { keyQueue_.emplace_back(key, mods); }
    bool keyPressed(int key, int mods) const;                                         // `key` with exactly `mods` queued this frame
    const std::vector<std::pair<int, int>>& queuedKeys() const { return keyQueue_; }  // in the order pressed
    // Where the left button went down this frame (a press and a move can arrive in one frame).
    std::optional<std::array<double, 2>> leftPress() const;
    void leftPressAt(double x, double y) { leftPress_ = {x, y}, leftPressed_ = true; }
    // The benchmark's mouse position (window pixels) instead of the real one; nullopt: the real one.
    void overrideMouse(std::optional<std::array<double, 2>> at) { mouseOverride_ = at; }

    // The loop: events, size changes, pacing, client.drawFrame(); until client.quitRequested().
    void run(WindowClient& client);
    double frameMs() const { return frameMs_; }  // time between the last two frames

    // One frame, in this order. beginUi: ImGui's new frame with this frame's queued keys held down.
    void beginUi();
    void endUi();    // ImGui::Render; the held keys released, the queue cleared
    bool acquire();  // a swapchain image to draw into; false: the frame is skipped
    // ImGui's draw data over the image, after clearing `fills` (window pixels) to the panels'
    // colour (ImGui's textured background quads cost ~1.5 ms a frame on CPU devices), and present.
    void present(std::span<const std::array<float, 4>> fills);
    void presentEmpty();  // an acquired image with nothing more drawn (the first frame)
    // The image drawn so far this frame (the 3D view, before the panels) as a PNG, without
    // `cropLeft` and `cropRight` window units at the sides (where the panels go). Throws
    // OutputError where it cannot be read back.
    void writeScreenshot(const std::string& path, float cropLeft = 0.0f, float cropRight = 0.0f);
    // Keeps the window's size for the next start (the state directory's window.txt).
    void rememberSize() const;

private:
    explicit AppWindow(GLFWwindow* window);
    GLFWwindow* window_;
    std::unique_ptr<render::Device> dev_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    std::unique_ptr<X11Presenter> hostPresenter_;  // CPU devices on X11: frames go to the window by XPutImage
    std::unique_ptr<SwapchainTarget> target_;
    std::unique_ptr<ImGuiLayer> imgui_;
    float uiScale_ = 1.0f;
    bool swapchainDirty_ = false;

    int wakeFrames_ = 3;
    std::chrono::steady_clock::time_point lastFrame_{};
    double frameMs_ = 0.0;
    std::vector<std::pair<int, int>> keyQueue_;
    std::vector<int> forcedKeys_;  // keys beginUi() holds down for this frame
    std::array<double, 2> leftPress_{0.0, 0.0};
    bool leftPressed_ = false;
    std::optional<std::array<double, 2>> mouseOverride_;
};

}  // namespace platform
}  // namespace pw::ui

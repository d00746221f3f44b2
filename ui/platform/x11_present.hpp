// Host presentation into the editor's X11 window (SwapchainTarget::HostPresent): the
// finished frame is copied into a MIT-SHM segment and put with XShmPutImage (0.5 ms at 720p under
// Xvfb), or, where the server cannot attach the segment (a remote display), sent with XPutImage,
// which Xlib splits into requests the server takes at once (1.1 ms). Used on CPU Vulkan devices
// (lavapipe), whose software swapchain sends a frame as one request that an X server without DRI3
// reads in small pieces: 11-16 ms (docs/PERFORMANCE.md).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>

struct GLFWwindow;

namespace pw::ui {
inline namespace platform {

class X11Presenter {
public:
    // Null when the window is not an X11 window or its visual is not 24/32-bit TrueColor in the
    // B8G8R8A8 byte layout; PATCHWORK_PRESENT=swapchain also gives null (the Vulkan swapchain).
    static std::unique_ptr<X11Presenter> create(GLFWwindow* window);
    ~X11Presenter();
    X11Presenter(const X11Presenter&) = delete;
    X11Presenter& operator=(const X11Presenter&) = delete;

    // Puts the frame into the window and waits until the X server has taken it (XSync).
    void present(const uint8_t* bgra, VkExtent2D extent, uint32_t rowBytes);

private:
    struct Impl;
    explicit X11Presenter(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace platform
}  // namespace pw::ui

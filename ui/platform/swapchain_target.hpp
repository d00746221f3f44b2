// Swapchain render target for the editor window: the renderer draws the 3D view straight into the
// acquired swapchain image (dynamic rendering, single sample, own depth buffer); an overlay render
// pass (for Dear ImGui 1.86, which needs a VkRenderPass) then draws on top and leaves the image
// ready to present. Handles resize, zero-size (minimised) windows and out-of-date/suboptimal
// swapchains: acquire()/present() return false and the caller calls recreate() with the new size.
//
// Host presentation (CPU devices): with a HostPresent function there is no VkSwapchainKHR. One
// B8G8R8A8 image is drawn the same way, copied into mapped host memory after the overlay pass, and
// handed to the function (the editor puts it into its X11 window). Mesa's software swapchain sends
// each frame as one multi-megabyte X request, which an X server without DRI3 (Xvfb, remote X)
// takes in socket-buffer-sized pieces: 11-16 ms a 720p frame, against ~1 ms for Xlib's split
// XPutImage (measured under Xvfb; docs/PERFORMANCE.md).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <vector>

#include "render/targets/render_target.hpp"
#include "render/vk/buffers.hpp"
#include "render/vk/vk_owned.hpp"

namespace pw::ui {
inline namespace platform {

class SwapchainTarget final : public render::RenderTarget {
public:
    // Shows a finished frame: B8G8R8A8 pixels, rows top first, `rowBytes` apart.
    using HostPresent = std::function<void(const uint8_t* bgra, VkExtent2D extent, uint32_t rowBytes)>;
    // `surface` stays owned by the caller (destroy it after this target). With `hostPresent`,
    // `surface` is not used (it may be VK_NULL_HANDLE) and frames go to that function instead.
    SwapchainTarget(render::Device& dev, VkSurfaceKHR surface, VkExtent2D framebufferSize, HostPresent hostPresent = {});
    ~SwapchainTarget() override;

    VkExtent2D extent() const override { return extent_; }
    VkFormat colorFormat() const override { return format_; }
    VkSampleCountFlagBits samples() const override { return VK_SAMPLE_COUNT_1_BIT; }
    void beginRendering(VkCommandBuffer cmd, const std::array<float, 4>& clear) override;
    void pauseRendering(VkCommandBuffer cmd) override;
    void resumeRendering(VkCommandBuffer cmd) override;
    void endRendering(VkCommandBuffer cmd) override;

    // Rebuilds the swapchain for a new framebuffer size (no-op for a zero size: the caller waits).
    void recreate(VkExtent2D framebufferSize);
    // Acquires the next image (waits on a fence). False: out of date, call recreate() first.
    bool acquire();
    // Submits `cmd` (recorded with the overlay pass) and presents the acquired image. False: the
    // swapchain is out of date or suboptimal and should be recreated.
    bool submitAndPresent(VkCommandBuffer cmd);

    // Overlay pass: loads the colour written by the renderer and ends in PRESENT_SRC.
    VkRenderPass overlayRenderPass() const { return overlayPass_; }
    VkFramebuffer overlayFramebuffer() const { return framebuffers_[current_]; }
    uint32_t minImageCount() const { return minImageCount_; }
    uint32_t imageCount() const { return uint32_t(images_.size()); }
    bool valid() const { return hostPresent_ ? hostImage_.image != VK_NULL_HANDLE : swapchain_ != VK_NULL_HANDLE; }
    bool hostPresented() const { return bool(hostPresent_); }

    // RGBA8 copy of the acquired image as the renderer left it (call after Renderer::render, before
    // the overlay pass); rows top first.
    std::vector<uint8_t> readCurrentImage();

private:
    void chooseSurfaceFormat();
    void createSwapchain(VkExtent2D size);
    void createHostImage(VkExtent2D size);  // host presentation: the one image, its copy and buffer
    void addImage(VkImage image);           // view, overlay framebuffer and semaphore of one image
    void destroySwapchainResources();
    render::Device& dev_;
    VkSurfaceKHR surface_;
    render::OwnedSwapchain swapchain_;
    VkFormat format_ = VK_FORMAT_B8G8R8A8_UNORM;
    VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkExtent2D extent_{0, 0};
    uint32_t minImageCount_ = 2;
    std::vector<VkImage> images_;
    std::vector<render::OwnedImageView> views_;
    std::vector<render::OwnedFramebuffer> framebuffers_;
    std::vector<render::OwnedSemaphore> renderDone_;  // per image: overlay submit -> present
    render::Image depth_;
    render::OwnedRenderPass overlayPass_;
    render::OwnedFence acquireFence_, submitFence_;
    uint32_t current_ = 0;
    bool transferSrc_ = false;
    // Host presentation.
    HostPresent hostPresent_;
    render::Image hostImage_;
    render::Buffer hostPixels_;           // mapped copy of the finished frame
    render::OwnedCommandBuffer copyCmd_;  // image -> hostPixels_, recorded per size
};

}  // namespace platform
}  // namespace pw::ui

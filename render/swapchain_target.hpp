// Swapchain render target for the editor window: the renderer draws the 3D view straight into the
// acquired swapchain image (dynamic rendering, single sample, own depth buffer); an overlay render
// pass (for Dear ImGui 1.86, which needs a VkRenderPass) then draws on top and leaves the image
// ready to present. Handles resize, zero-size (minimised) windows and out-of-date/suboptimal
// swapchains: acquire()/present() return false and the caller calls recreate() with the new size.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "buffers.hpp"
#include "render_target.hpp"

namespace pw::render {

class SwapchainTarget final : public RenderTarget {
public:
    // `surface` stays owned by the caller (destroy it after this target).
    SwapchainTarget(Device& dev, VkSurfaceKHR surface, VkExtent2D framebufferSize);
    ~SwapchainTarget() override;
    SwapchainTarget(const SwapchainTarget&) = delete;
    SwapchainTarget& operator=(const SwapchainTarget&) = delete;

    VkExtent2D extent() const override { return extent_; }
    VkFormat colorFormat() const override { return format_; }
    VkFormat depthFormat() const override { return VK_FORMAT_D32_SFLOAT; }
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
    bool valid() const { return swapchain_ != VK_NULL_HANDLE; }

    // RGBA8 copy of the acquired image as the renderer left it (call after Renderer::render, before
    // the overlay pass); rows top first.
    std::vector<uint8_t> readCurrentImage();

private:
    void createSwapchain(VkExtent2D size);
    void destroySwapchainResources();
    Device& dev_;
    VkSurfaceKHR surface_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_B8G8R8A8_UNORM;
    VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkExtent2D extent_{0, 0};
    uint32_t minImageCount_ = 2;
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkFramebuffer> framebuffers_;
    std::vector<VkSemaphore> renderDone_;  // per image: overlay submit -> present
    Image depth_;
    VkRenderPass overlayPass_ = VK_NULL_HANDLE;
    VkFence acquireFence_ = VK_NULL_HANDLE, submitFence_ = VK_NULL_HANDLE;
    uint32_t current_ = 0;
    bool transferSrc_ = false;
};

}  // namespace pw::render

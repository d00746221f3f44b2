// What the renderer draws into: an offscreen image (headless render, tests, bench) or, in the
// editor, a swapchain image. The renderer only needs the formats, the sample count and a
// begin/end of dynamic rendering around its draws.
#pragma once

#include <vulkan/vulkan.h>

#include <array>

namespace pw::render {
inline namespace targets {

class RenderTarget {
public:
    RenderTarget() = default;
    RenderTarget(const RenderTarget&) = delete;  // targets own their images
    RenderTarget& operator=(const RenderTarget&) = delete;
    virtual ~RenderTarget() = default;
    virtual VkExtent2D extent() const = 0;
    virtual VkFormat colorFormat() const = 0;
    // Every target's depth attachment: 32-bit float.
    VkFormat depthFormat() const { return VK_FORMAT_D32_SFLOAT; }
    virtual VkSampleCountFlagBits samples() const = 0;
    // Transitions the attachments and starts dynamic rendering with a clear to `clear` (RGBA) and depth 1.
    virtual void beginRendering(VkCommandBuffer cmd, const std::array<float, 4>& clear) = 0;
    // Ends rendering but keeps the contents for resumeRendering (e.g. to end a query in between).
    virtual void pauseRendering(VkCommandBuffer cmd) = 0;
    // Continues rendering on top of what was drawn before pauseRendering.
    virtual void resumeRendering(VkCommandBuffer cmd) = 0;
    // Ends rendering and leaves the image ready for its consumer (readback copy, or present).
    virtual void endRendering(VkCommandBuffer cmd) = 0;
};

}  // namespace targets
}  // namespace pw::render

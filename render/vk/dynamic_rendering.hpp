// Dynamic rendering into one colour and one depth attachment, shared by the offscreen and the
// swapchain targets: begin (clearing, or loading what a paused pass left) and pause.
#pragma once

#include <vulkan/vulkan.h>

#include <array>

namespace pw::render {
inline namespace vk {

struct ColorDepthAttachments {
    VkExtent2D extent{};
    VkImageView color = VK_NULL_HANDLE;    // in COLOR_ATTACHMENT_OPTIMAL
    VkImageView depth = VK_NULL_HANDLE;    // in DEPTH_ATTACHMENT_OPTIMAL
    VkImageView resolve = VK_NULL_HANDLE;  // multisampled colour resolves (averaged) into this, if set
};

// Moves a depth image to DEPTH_ATTACHMENT_OPTIMAL, discarding its contents (every frame clears),
// after the previous frame's depth tests.
void discardDepthToAttachment(VkCommandBuffer cmd, VkImage depth);

// vkCmdBeginRendering with both attachments cleared (`load` false) or loaded (`load` true).
void beginColorDepthRendering(VkCommandBuffer cmd, const ColorDepthAttachments& at, bool load, const std::array<float, 4>& clear);

// vkCmdEndRendering, then a barrier ordering the attachment writes before the next pass's loads.
void pauseColorDepthRendering(VkCommandBuffer cmd);

}  // namespace vk
}  // namespace pw::render

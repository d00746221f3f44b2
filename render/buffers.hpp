// Buffers and images with their own memory (the renderer allocates few, large resources).
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstring>
#include <vector>

#include "render/device.hpp"

namespace pw::render {

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // host-visible buffers stay mapped
};

// Host-visible, coherent buffer (lavapipe: all memory is host memory; on GPUs fine for our sizes).
Buffer createBuffer(Device& dev, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible = true);
void destroyBuffer(Device& dev, Buffer& b);

// A host-visible buffer holding `data` (at least 16 bytes so empty scenes stay valid).
template <class T>
Buffer uploadBuffer(Device& dev, const std::vector<T>& data, VkBufferUsageFlags usage) {
    const VkDeviceSize bytes = std::max<VkDeviceSize>(16, sizeof(T) * data.size());
    Buffer b = createBuffer(dev, bytes, usage, true);
    if (!data.empty()) std::memcpy(b.mapped, data.data(), sizeof(T) * data.size());
    return b;
}

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
};

Image createImage(Device& dev, VkExtent2D extent, VkFormat format, VkSampleCountFlagBits samples, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect);
void destroyImage(Device& dev, Image& img);

// Image layout transition with a full (conservative) barrier.
// Records the copy of a colour attachment (COLOR_ATTACHMENT_OPTIMAL, left in TRANSFER_SRC_OPTIMAL)
// into a host-visible buffer as tightly packed 4-byte pixels, with the barrier that makes the
// bytes visible to the host after the submission completes.
void copyColorAttachmentToHost(VkCommandBuffer cmd, VkImage image, VkExtent2D extent, VkBuffer dst);

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

}  // namespace pw::render

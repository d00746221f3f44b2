// Buffers and images with their own memory (the renderer allocates few, large resources), owned
// like render/vk/vk_owned.hpp's handles, each in the memory class its use calls for.
#pragma once

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <utility>
#include <vector>

#include "render/vk/device.hpp"
#include "render/vk/vk_owned.hpp"

namespace pw::render {
inline namespace vk {

// What a buffer's memory is for (DESIGN: static data device-local on discrete GPUs).
enum class MemoryUse {
    Static,       // written once at upload: device-local, filled through a staging copy unless that
                  // memory is host-visible too (lavapipe, resizable BAR), then mapped and copied
    HostWritten,  // the CPU rewrites it (frame uniforms, points being dragged): host-visible and
                  // coherent, stays mapped; device-local as well where the driver offers it
    Readback,     // the GPU writes, the CPU reads (pixels, counters): host-visible, cached if offered
};

// A buffer and its memory, owned: freed when it dies or is reset; move-only. `mapped` is set when
// the memory is host-visible (always for HostWritten and Readback).
struct Buffer {
    OwnedMemory memory;
    OwnedBufferHandle buffer;  // declared after the memory, so destroyed before it
    VkDeviceSize size = 0;
    void* mapped = nullptr;
    void reset() { *this = Buffer{}; }
};

Buffer createBuffer(Device& dev, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use);

// A Static buffer holding `bytes` bytes from `data` (at least 16 bytes so empty scenes stay valid).
Buffer uploadStatic(Device& dev, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage);
template <class T>
Buffer uploadStatic(Device& dev, const std::vector<T>& data, VkBufferUsageFlags usage) {
    return uploadStatic(dev, data.data(), sizeof(T) * data.size(), usage);
}

// A HostWritten buffer holding `data` (at least 16 bytes).
template <class T>
Buffer uploadHostWritten(Device& dev, const std::vector<T>& data, VkBufferUsageFlags usage) {
    Buffer b = createBuffer(dev, std::max<VkDeviceSize>(16, sizeof(T) * data.size()), usage, MemoryUse::HostWritten);
    if (!data.empty()) std::memcpy(b.mapped, data.data(), sizeof(T) * data.size());
    return b;
}

// A device-local image with one view, owned like Buffer.
struct Image {
    OwnedMemory memory;
    OwnedImageHandle image;
    OwnedImageView view;
    VkFormat format = VK_FORMAT_UNDEFINED;
    void reset() { *this = Image{}; }
};

// A 2D image with `mipLevels` levels, its memory and a view of them all.
Image createImage(Device& dev, VkExtent2D extent, VkFormat format, VkSampleCountFlagBits samples, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect, uint32_t mipLevels = 1);

// Records the copy of a colour attachment (COLOR_ATTACHMENT_OPTIMAL, left in TRANSFER_SRC_OPTIMAL)
// into a host-visible buffer as tightly packed 4-byte pixels, with the barrier that makes the
// bytes visible to the host after the submission completes.
void copyColorAttachmentToHost(VkCommandBuffer cmd, VkImage image, VkExtent2D extent, VkBuffer dst);

// Image layout transition of the first `mipLevels` levels with a full (conservative) barrier.
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess,
                  uint32_t mipLevels = 1);

}  // namespace vk
}  // namespace pw::render

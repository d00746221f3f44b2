#include "render/vk/buffers.hpp"

namespace pw::render {
inline namespace vk {

namespace {

// The first memory type with all of `want` (and then as many of `prefer` as possible).
uint32_t pickMemoryType(const VkPhysicalDeviceMemoryProperties& props, uint32_t typeBits, VkMemoryPropertyFlags want,
                        VkMemoryPropertyFlags prefer) {
    int best = -1, bestScore = -1;
    for (uint32_t i = 0; i < props.memoryTypeCount; ++i) {
        const VkMemoryPropertyFlags f = props.memoryTypes[i].propertyFlags;
        if (!(typeBits & (1u << i)) || (f & want) != want) continue;
        const int score = __builtin_popcount(f & prefer);
        if (score > bestScore) best = int(i), bestScore = score;
    }
    if (best < 0) throw VulkanError("no suitable Vulkan memory type");
    return uint32_t(best);
}

// HostWritten buffers up to this size may take device-local host-visible memory (a BAR heap can be
// as small as 256 MiB; large ones stay in system memory).
constexpr VkDeviceSize kSmallHostWritten = VkDeviceSize(16) << 20;

}  // namespace

Buffer createBuffer(Device& dev, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use) {
    Buffer b;
    b.size = size;
    const VkBufferCreateInfo ci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, nullptr, 0, size, usage, VK_SHARING_MODE_EXCLUSIVE, 0, nullptr};
    VK_CHECK(vkCreateBuffer(dev.device(), &ci, nullptr, b.buffer.replace(dev.device())));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(dev.device(), b.buffer, &req);
    VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, prefer = 0;
    if (use == MemoryUse::Static) want = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    if (use == MemoryUse::HostWritten && size <= kSmallHostWritten) prefer = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    if (use == MemoryUse::Readback) prefer = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = pickMemoryType(dev.memoryProperties(), req.memoryTypeBits, want, prefer);
    VK_CHECK(vkAllocateMemory(dev.device(), &ai, nullptr, b.memory.replace(dev.device())));
    VK_CHECK(vkBindBufferMemory(dev.device(), b.buffer, b.memory, 0));
    const bool hostVisible = dev.memoryProperties().memoryTypes[ai.memoryTypeIndex].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
    if (hostVisible) VK_CHECK(vkMapMemory(dev.device(), b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    return b;
}

Buffer uploadStatic(Device& dev, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage) {
    const VkDeviceSize size = std::max<VkDeviceSize>(16, bytes);
    Buffer b = createBuffer(dev, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Static);
    if (bytes == 0) return b;
    if (b.mapped) {  // device-local memory the host sees (lavapipe, resizable BAR): no copy needed
        const VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, b.memory.get(), 0, VK_WHOLE_SIZE};
        std::memcpy(b.mapped, data, bytes);
        VK_CHECK(vkFlushMappedMemoryRanges(dev.device(), 1, &range));
        return b;
    }
    Buffer staging = createBuffer(dev, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostWritten);
    std::memcpy(staging.mapped, data, bytes);
    dev.submitAndWait([&](VkCommandBuffer cmd) {
        const VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, staging.buffer, b.buffer, 1, &region);
        VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        mb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        mb.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &mb, 0, nullptr, 0, nullptr);
    });
    return b;
}

Image createImage(Device& dev, VkExtent2D extent, VkFormat format, VkSampleCountFlagBits samples, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect, uint32_t mipLevels) {
    Image img;
    img.format = format;
    VkImageCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ci.imageType = VK_IMAGE_TYPE_2D;
    ci.format = format;
    ci.extent = {extent.width, extent.height, 1};
    ci.mipLevels = mipLevels;
    ci.arrayLayers = 1;
    ci.samples = samples;
    ci.tiling = VK_IMAGE_TILING_OPTIMAL;
    ci.usage = usage;
    ci.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(dev.device(), &ci, nullptr, img.image.replace(dev.device())));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(dev.device(), img.image, &req);
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = dev.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vkAllocateMemory(dev.device(), &ai, nullptr, img.memory.replace(dev.device())));
    VK_CHECK(vkBindImageMemory(dev.device(), img.image, img.memory, 0));
    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = img.image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format;
    vi.subresourceRange = {aspect, 0, mipLevels, 0, 1};
    VK_CHECK(vkCreateImageView(dev.device(), &vi, nullptr, img.view.replace(dev.device())));
    return img;
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess,
                  uint32_t mipLevels) {
    const VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                                 nullptr,
                                 srcAccess,
                                 dstAccess,
                                 from,
                                 to,
                                 VK_QUEUE_FAMILY_IGNORED,
                                 VK_QUEUE_FAMILY_IGNORED,
                                 image,
                                 {aspect, 0, mipLevels, 0, 1}};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

void copyColorAttachmentToHost(VkCommandBuffer cmd, VkImage image, VkExtent2D extent, VkBuffer dst) {
    imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, 1, &region);
    VkBufferMemoryBarrier bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    bb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    bb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    bb.buffer = dst;
    bb.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &bb, 0, nullptr);
}

}  // namespace vk
}  // namespace pw::render

#include "render/vk/vk_owned.hpp"

#include "render/vk/vk_check.hpp"

namespace pw::render {
inline namespace vk {

OwnedCommandBuffer::OwnedCommandBuffer(VkDevice device, VkCommandPool pool) : device_(device), pool_(pool) {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(device, &ai, &cmd_));
}

void OwnedCommandBuffer::reset() {
    if (cmd_) vkFreeCommandBuffers(device_, pool_, 1, &cmd_);
    cmd_ = VK_NULL_HANDLE;
}

}  // namespace vk
}  // namespace pw::render

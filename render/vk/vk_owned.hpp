// Move-only owners of Vulkan handles: each destroys its handle (with the device that made it)
// when it dies or is reset, so no class keeps a hand-written destroy list. Owned<H, Destroy> fits
// every vkDestroy*(VkDevice, H, const VkAllocationCallbacks*) handle; Buffer and Image
// (render/vk/buffers.hpp) own their memory too.
#pragma once

#include <vulkan/vulkan.h>

#include <utility>

namespace pw::render {
inline namespace vk {

template <class H, void (*Destroy)(VkDevice, H, const VkAllocationCallbacks*)>
class Owned {
public:
    Owned() = default;
    Owned(VkDevice device, H handle) : device_(device), handle_(handle) {}
    ~Owned() { reset(); }
    Owned(Owned&& o) noexcept : device_(o.device_), handle_(std::exchange(o.handle_, H(VK_NULL_HANDLE))) {}
    Owned& operator=(Owned&& o) noexcept {
        if (this != &o) {
            reset();
            device_ = o.device_;
            handle_ = std::exchange(o.handle_, H(VK_NULL_HANDLE));
        }
        return *this;
    }
    Owned(const Owned&) = delete;
    Owned& operator=(const Owned&) = delete;

    void reset() {
        if (handle_ != H(VK_NULL_HANDLE)) Destroy(device_, handle_, nullptr);
        handle_ = H(VK_NULL_HANDLE);
    }
    // For vkCreate*: destroys what is held and hands out the slot the new handle is written to.
    H* replace(VkDevice device) {
        reset();
        device_ = device;
        return &handle_;
    }
    H get() const { return handle_; }
    const H* ptr() const { return &handle_; }  // for Vulkan calls that take an array of one
    operator H() const { return handle_; }     // NOLINT: passes straight into Vulkan calls
    explicit operator bool() const { return handle_ != H(VK_NULL_HANDLE); }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    H handle_ = H(VK_NULL_HANDLE);
};

using OwnedPipeline = Owned<VkPipeline, vkDestroyPipeline>;
using OwnedPipelineLayout = Owned<VkPipelineLayout, vkDestroyPipelineLayout>;
using OwnedPipelineCache = Owned<VkPipelineCache, vkDestroyPipelineCache>;
using OwnedDescriptorSetLayout = Owned<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using OwnedDescriptorPool = Owned<VkDescriptorPool, vkDestroyDescriptorPool>;
using OwnedShaderModule = Owned<VkShaderModule, vkDestroyShaderModule>;
using OwnedQueryPool = Owned<VkQueryPool, vkDestroyQueryPool>;
using OwnedFence = Owned<VkFence, vkDestroyFence>;
using OwnedSemaphore = Owned<VkSemaphore, vkDestroySemaphore>;
using OwnedImageView = Owned<VkImageView, vkDestroyImageView>;
using OwnedSampler = Owned<VkSampler, vkDestroySampler>;
using OwnedFramebuffer = Owned<VkFramebuffer, vkDestroyFramebuffer>;
using OwnedRenderPass = Owned<VkRenderPass, vkDestroyRenderPass>;
using OwnedSwapchain = Owned<VkSwapchainKHR, vkDestroySwapchainKHR>;
using OwnedBufferHandle = Owned<VkBuffer, vkDestroyBuffer>;
using OwnedImageHandle = Owned<VkImage, vkDestroyImage>;
using OwnedMemory = Owned<VkDeviceMemory, vkFreeMemory>;

// A primary command buffer from a pool, freed back to it.
class OwnedCommandBuffer {
public:
    OwnedCommandBuffer() = default;
    OwnedCommandBuffer(VkDevice device, VkCommandPool pool);  // allocates one
    ~OwnedCommandBuffer() { reset(); }
    OwnedCommandBuffer(OwnedCommandBuffer&& o) noexcept : device_(o.device_), pool_(o.pool_), cmd_(std::exchange(o.cmd_, VK_NULL_HANDLE)) {}
    OwnedCommandBuffer& operator=(OwnedCommandBuffer&& o) noexcept {
        if (this != &o) {
            reset();
            device_ = o.device_, pool_ = o.pool_, cmd_ = std::exchange(o.cmd_, VK_NULL_HANDLE);
        }
        return *this;
    }
    void reset();
    operator VkCommandBuffer() const { return cmd_; }  // NOLINT
    const VkCommandBuffer* ptr() const { return &cmd_; }
    explicit operator bool() const { return cmd_ != VK_NULL_HANDLE; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
};

}  // namespace vk
}  // namespace pw::render

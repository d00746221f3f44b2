#include "ui/platform/swapchain_target.hpp"

#include "render/vk/dynamic_rendering.hpp"

#include <algorithm>
#include <cstring>

namespace pw::ui {
inline namespace platform {

using namespace render;  // the Vulkan objects of render/vk and render/targets

SwapchainTarget::SwapchainTarget(Device& dev, VkSurfaceKHR surface, VkExtent2D framebufferSize, HostPresent hostPresent)
    : dev_(dev), surface_(surface), hostPresent_(std::move(hostPresent)) {
    // Step 1: the surface's format (host presentation draws B8G8R8A8, the X11 TrueColor layout).
    if (!hostPresent_) chooseSurfaceFormat();

    // Step 2: overlay render pass (ImGui): load what the renderer drew, end ready to present (or,
    // presenting from host memory, ready for the copy into it).
    // flags, format, samples, load/store, stencil load/store, initial and final layout
    const VkAttachmentDescription att{0,
                                      format_,
                                      VK_SAMPLE_COUNT_1_BIT,
                                      VK_ATTACHMENT_LOAD_OP_LOAD,
                                      VK_ATTACHMENT_STORE_OP_STORE,
                                      VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                      VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                      hostPresent_ ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription sub{};
    sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    sub.colorAttachmentCount = 1;
    sub.pColorAttachments = &ref;
    VkSubpassDependency deps[2]{};
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].srcSubpass = 0;  // host presentation: the overlay's writes before the copy reads them
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rp.attachmentCount = 1;
    rp.pAttachments = &att;
    rp.subpassCount = 1;
    rp.pSubpasses = &sub;
    rp.dependencyCount = hostPresent_ ? 2 : 1;
    rp.pDependencies = deps;
    VK_CHECK(vkCreateRenderPass(dev.device(), &rp, nullptr, overlayPass_.replace(dev.device())));

    // Step 3: fences (acquire waits on the host; the renderer's own submit then owns the image).
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(dev.device(), &fci, nullptr, acquireFence_.replace(dev.device())));
    VK_CHECK(vkCreateFence(dev.device(), &fci, nullptr, submitFence_.replace(dev.device())));

    createSwapchain(framebufferSize);
}

void SwapchainTarget::chooseSurfaceFormat() {
    // The queue must be able to present to this surface.
    VkBool32 present = VK_FALSE;
    VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(dev_.physical(), dev_.queueFamily(), surface_, &present));
    if (!present) throw VulkanError("the Vulkan device's graphics queue cannot present to the window surface");

    // UNORM like the offscreen target, so colours match `patchwork render`.
    uint32_t n = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(dev_.physical(), surface_, &n, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(n);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(dev_.physical(), surface_, &n, formats.data()));
    if (formats.empty()) throw VulkanError("the window surface reports no formats");
    format_ = formats[0].format;
    colorSpace_ = formats[0].colorSpace;
    for (const VkSurfaceFormatKHR& f : formats)
        if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) {
            format_ = f.format;
            colorSpace_ = f.colorSpace;
            break;
        }
}

SwapchainTarget::~SwapchainTarget() {
    vkDeviceWaitIdle(dev_.device());
    destroySwapchainResources();  // before the swapchain; the members go by themselves
}

void SwapchainTarget::destroySwapchainResources() {
    framebuffers_.clear();
    views_.clear();
    renderDone_.clear();
    images_.clear();
    depth_.reset();
    hostImage_.reset();
    hostPixels_.reset();
}

void SwapchainTarget::recreate(VkExtent2D size) {
    if (size.width == 0 || size.height == 0) return;
    vkDeviceWaitIdle(dev_.device());
    createSwapchain(size);
}

void SwapchainTarget::createSwapchain(VkExtent2D size) {
    if (hostPresent_) {
        createHostImage(size);
        return;
    }
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(dev_.physical(), surface_, &caps));
    VkExtent2D ext = caps.currentExtent;
    if (ext.width == 0xFFFFFFFFu) {
        ext.width = std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width);
        ext.height = std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (ext.width == 0 || ext.height == 0) return;  // minimised: keep the old one until a real size

    // Step 1: the swapchain (FIFO is always available; the editor paces frames itself).
    minImageCount_ = std::max(2u, caps.minImageCount);
    uint32_t count = minImageCount_ + 1;
    if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);
    transferSrc_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
    VkSwapchainCreateInfoKHR ci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    ci.surface = surface_;
    ci.minImageCount = count;
    ci.imageFormat = format_;
    ci.imageColorSpace = colorSpace_;
    ci.imageExtent = ext;
    ci.imageArrayLayers = 1;
    ci.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (transferSrc_ ? uint32_t(VK_IMAGE_USAGE_TRANSFER_SRC_BIT) : 0u);
    ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.preTransform = caps.currentTransform;
    ci.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR) ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                                                                                           : VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
    ci.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    ci.clipped = VK_TRUE;
    ci.oldSwapchain = swapchain_;
    VkSwapchainKHR fresh = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSwapchainKHR(dev_.device(), &ci, nullptr, &fresh));
    destroySwapchainResources();
    swapchain_ = OwnedSwapchain(dev_.device(), fresh);
    extent_ = ext;

    // Step 2: images, views, overlay framebuffers and per-image semaphores.
    uint32_t n = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(dev_.device(), swapchain_, &n, nullptr));
    images_.resize(n);
    VK_CHECK(vkGetSwapchainImagesKHR(dev_.device(), swapchain_, &n, images_.data()));
    for (VkImage img : images_) addImage(img);
    // Step 3: depth buffer of the new size.
    depth_ = createImage(dev_, ext, depthFormat(), VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                         VK_IMAGE_ASPECT_DEPTH_BIT);
    current_ = 0;
}

void SwapchainTarget::addImage(VkImage img) {
    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = img;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format_;
    vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(dev_.device(), &vi, nullptr, &view));
    views_.emplace_back(dev_.device(), view);
    VkFramebufferCreateInfo fi{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fi.renderPass = overlayPass_;
    fi.attachmentCount = 1;
    fi.pAttachments = &view;
    fi.width = extent_.width;
    fi.height = extent_.height;
    fi.layers = 1;
    VkFramebuffer fb = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(dev_.device(), &fi, nullptr, &fb));
    framebuffers_.emplace_back(dev_.device(), fb);
    VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore s = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(dev_.device(), &si, nullptr, &s));
    renderDone_.emplace_back(dev_.device(), s);
}

void SwapchainTarget::createHostImage(VkExtent2D size) {
    if (size.width == 0 || size.height == 0) return;  // minimised: keep the old image until a real size
    destroySwapchainResources();
    extent_ = size;
    transferSrc_ = true;
    hostImage_ = createImage(dev_, size, format_, VK_SAMPLE_COUNT_1_BIT,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    images_ = {hostImage_.image};
    addImage(hostImage_.image);
    depth_ = createImage(dev_, size, depthFormat(), VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                         VK_IMAGE_ASPECT_DEPTH_BIT);
    hostPixels_ = createBuffer(dev_, VkDeviceSize(size.width) * size.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
    // The copy that follows the overlay pass every frame (which leaves the image TRANSFER_SRC).
    if (!copyCmd_) copyCmd_ = OwnedCommandBuffer(dev_.device(), dev_.commandPool());
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(copyCmd_, &bi));
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {size.width, size.height, 1};
    vkCmdCopyImageToBuffer(copyCmd_, hostImage_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, hostPixels_.buffer, 1, &region);
    VkBufferMemoryBarrier bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    bb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    bb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    bb.buffer = hostPixels_.buffer;
    bb.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(copyCmd_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &bb, 0, nullptr);
    VK_CHECK(vkEndCommandBuffer(copyCmd_));
    current_ = 0;
}

bool SwapchainTarget::acquire() {
    if (hostPresent_) {  // one image, free again once the last submitAndPresent returned
        current_ = 0;
        return hostImage_.image != VK_NULL_HANDLE;
    }
    if (!swapchain_) return false;
    VK_CHECK(vkResetFences(dev_.device(), 1, acquireFence_.ptr()));
    const VkResult r = vkAcquireNextImageKHR(dev_.device(), swapchain_, UINT64_MAX, VK_NULL_HANDLE, acquireFence_, &current_);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) return false;
    if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR) VK_CHECK(r);
    // A suboptimal image was still acquired (and signals the fence): use it, recreate after present.
    VK_CHECK(vkWaitForFences(dev_.device(), 1, acquireFence_.ptr(), VK_TRUE, UINT64_MAX));
    return true;
}

bool SwapchainTarget::submitAndPresent(VkCommandBuffer cmd) {
    if (hostPresent_) {  // the overlay pass, the copy into host memory, then the window
        const VkCommandBuffer cmds[2] = {cmd, copyCmd_};
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        si.commandBufferCount = 2;
        si.pCommandBuffers = cmds;
        VK_CHECK(vkResetFences(dev_.device(), 1, submitFence_.ptr()));
        VK_CHECK(vkQueueSubmit(dev_.queue(), 1, &si, submitFence_));
        VK_CHECK(vkWaitForFences(dev_.device(), 1, submitFence_.ptr(), VK_TRUE, UINT64_MAX));
        hostPresent_(static_cast<const uint8_t*>(hostPixels_.mapped), extent_, extent_.width * 4);
        return true;
    }
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    si.signalSemaphoreCount = 1;
    si.pSignalSemaphores = renderDone_[current_].ptr();
    VK_CHECK(vkResetFences(dev_.device(), 1, submitFence_.ptr()));
    VK_CHECK(vkQueueSubmit(dev_.queue(), 1, &si, submitFence_));
    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.waitSemaphoreCount = 1;
    pi.pWaitSemaphores = renderDone_[current_].ptr();
    pi.swapchainCount = 1;
    pi.pSwapchains = swapchain_.ptr();
    pi.pImageIndices = &current_;
    const VkResult r = vkQueuePresentKHR(dev_.queue(), &pi);
    VK_CHECK(vkWaitForFences(dev_.device(), 1, submitFence_.ptr(), VK_TRUE, UINT64_MAX));
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) return false;
    VK_CHECK(r);
    return true;
}

void SwapchainTarget::beginRendering(VkCommandBuffer cmd, const std::array<float, 4>& clear) {
    // Previous contents are discarded (UNDEFINED): every frame clears.
    imageBarrier(cmd, images_[current_], VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT);
    discardDepthToAttachment(cmd, depth_.image);
    beginColorDepthRendering(cmd, {extent_, views_[current_], depth_.view}, false, clear);
}

void SwapchainTarget::pauseRendering(VkCommandBuffer cmd) { pauseColorDepthRendering(cmd); }

void SwapchainTarget::resumeRendering(VkCommandBuffer cmd) {
    beginColorDepthRendering(cmd, {extent_, views_[current_], depth_.view}, true, {0, 0, 0, 0});
}

void SwapchainTarget::endRendering(VkCommandBuffer cmd) {
    // The image stays in COLOR_ATTACHMENT_OPTIMAL for the overlay pass, which ends in PRESENT_SRC.
    vkCmdEndRendering(cmd);
}

std::vector<uint8_t> SwapchainTarget::readCurrentImage() {
    // Host presentation draws into one image of its own (always TRANSFER_SRC); a swapchain's images
    // only where the surface allows it.
    if (!transferSrc_ || (!swapchain_ && !hostPresent_) || images_.empty()) return {};
    const VkDeviceSize bytes = VkDeviceSize(extent_.width) * extent_.height * 4;
    Buffer buf = createBuffer(dev_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
    VkImage img = images_[current_];
    dev_.submitAndWait([&](VkCommandBuffer cmd) {
        copyColorAttachmentToHost(cmd, img, extent_, buf.buffer);
        // back to an attachment for the overlay pass
        imageBarrier(cmd, img, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT);
    });
    std::vector<uint8_t> out(bytes);
    std::memcpy(out.data(), buf.mapped, bytes);
    const bool bgra = format_ == VK_FORMAT_B8G8R8A8_UNORM || format_ == VK_FORMAT_B8G8R8A8_SRGB;
    for (size_t i = 0; i < out.size(); i += 4) {
        if (bgra) std::swap(out[i], out[i + 2]);
        out[i + 3] = 255;
    }
    return out;
}

}  // namespace platform
}  // namespace pw::ui

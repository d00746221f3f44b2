#include "render/targets/offscreen_target.hpp"

#include "render/vk/dynamic_rendering.hpp"

namespace pw::render {
inline namespace targets {

OffscreenTarget::OffscreenTarget(Device& dev, uint32_t width, uint32_t height, bool msaa)
    : dev_(dev), extent_{width, height}, samples_(msaa ? dev.caps().maxSamples : VkSampleCountFlagBits(VK_SAMPLE_COUNT_1_BIT)) {
    const bool ms = samples_ != VK_SAMPLE_COUNT_1_BIT;
    color_ =
        createImage(dev, extent_, colorFormat(), samples_,
                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (ms ? 0u : uint32_t(VK_IMAGE_USAGE_TRANSFER_SRC_BIT)), VK_IMAGE_ASPECT_COLOR_BIT);
    if (ms)
        resolve_ = createImage(dev, extent_, colorFormat(), VK_SAMPLE_COUNT_1_BIT,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    depth_ = createImage(dev, extent_, depthFormat(), samples_, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
    readbackBuf_ = createBuffer(dev, VkDeviceSize(width) * height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
}

OffscreenTarget::~OffscreenTarget() {
    vkDeviceWaitIdle(dev_.device());  // then the images and the buffer free themselves
}

void OffscreenTarget::beginRendering(VkCommandBuffer cmd, const std::array<float, 4>& clear) { begin(cmd, false, clear); }

void OffscreenTarget::pauseRendering(VkCommandBuffer cmd) { pauseColorDepthRendering(cmd); }

void OffscreenTarget::resumeRendering(VkCommandBuffer cmd) {
    if (readImageInTransferSrc_) {  // a later submission draws on top of a finished frame (comparison panes)
        imageBarrier(cmd, resolve_.image ? resolve_.image : color_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT);
        readImageInTransferSrc_ = false;
    }
    begin(cmd, true, {0, 0, 0, 0});
}

void OffscreenTarget::begin(VkCommandBuffer cmd, bool load, const std::array<float, 4>& clear) {
    const bool ms = resolve_.image != VK_NULL_HANDLE;
    if (!load) {
        readImageInTransferSrc_ = false;  // the barriers below start from UNDEFINED
        // Previous contents are discarded (UNDEFINED): every frame clears.
        imageBarrier(cmd, color_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT);
        if (ms)
            imageBarrier(cmd, resolve_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                         VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        discardDepthToAttachment(cmd, depth_.image);
    }

    beginColorDepthRendering(cmd, {extent_, color_.view, depth_.view, ms ? resolve_.view.get() : VK_NULL_HANDLE}, load, clear);
}

void OffscreenTarget::endRendering(VkCommandBuffer cmd) {
    vkCmdEndRendering(cmd);
    if (!readback_) return;
    readImageInTransferSrc_ = true;
    copyColorAttachmentToHost(cmd, resolve_.image ? resolve_.image : color_.image, extent_, readbackBuf_.buffer);
}

std::vector<uint8_t> OffscreenTarget::pixels() const {
    const size_t n = size_t(extent_.width) * extent_.height * 4;
    std::vector<uint8_t> out(n);
    std::memcpy(out.data(), readbackBuf_.mapped, n);
    return out;
}

}  // namespace targets
}  // namespace pw::render

// Offscreen render target: RGBA8 colour + D32 depth, 4x MSAA where supported (resolved into a
// single-sample image), optional readback of the resolved image into host memory.
#pragma once

#include <cstdint>
#include <vector>

#include "render/targets/render_target.hpp"
#include "render/vk/buffers.hpp"

namespace pw::render {
inline namespace targets {

class OffscreenTarget final : public RenderTarget {
public:
    OffscreenTarget(Device& dev, uint32_t width, uint32_t height, bool msaa = true);
    ~OffscreenTarget() override;

    VkExtent2D extent() const override { return extent_; }
    VkFormat colorFormat() const override { return VK_FORMAT_R8G8B8A8_UNORM; }
    VkSampleCountFlagBits samples() const override { return samples_; }
    void beginRendering(VkCommandBuffer cmd, const std::array<float, 4>& clear) override;
    void pauseRendering(VkCommandBuffer cmd) override;
    void resumeRendering(VkCommandBuffer cmd) override;
    void endRendering(VkCommandBuffer cmd) override;

    // When on, endRendering copies the image into a host buffer (read with pixels()).
    void setReadback(bool on) { readback_ = on; }
    // RGBA8 rows, top row first; valid after the frame's submission completed.
    std::vector<uint8_t> pixels() const;

private:
    void begin(VkCommandBuffer cmd, bool load, const std::array<float, 4>& clear);
    Device& dev_;
    VkExtent2D extent_;
    VkSampleCountFlagBits samples_;
    Image color_, resolve_, depth_;
    Buffer readbackBuf_;
    bool readback_ = true;
    bool readImageInTransferSrc_ = false;  // the last recorded endRendering copied it out, leaving it in TRANSFER_SRC
};

}  // namespace targets
}  // namespace pw::render

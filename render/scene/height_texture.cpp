#include "render/scene/height_texture.hpp"

#include "render/vk/vk_check.hpp"

namespace pw::render {
inline namespace scene {

HeightTexture uploadHeightTexture(Device& dev, const HeightMap* map) {
    HeightTexture t;
    const bool real = map && !map->empty();
    t.width = real ? map->width : 1;
    t.height = real ? map->height : 1;
    const std::vector<uint16_t> zero(1, 0);
    const std::vector<uint16_t>& texels = real ? map->texels : zero;
    t.image = createImage(dev, {t.width, t.height}, VK_FORMAT_R16_UNORM, VK_SAMPLE_COUNT_1_BIT,
                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    Buffer staging = createBuffer(dev, texels.size() * sizeof(uint16_t), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostWritten);
    std::memcpy(staging.mapped, texels.data(), texels.size() * sizeof(uint16_t));
    dev.submitAndWait([&](VkCommandBuffer cmd) {
        imageBarrier(cmd, t.image.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {t.width, t.height, 1};
        vkCmdCopyBufferToImage(cmd, staging.buffer, t.image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        imageBarrier(cmd, t.image.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT, VK_ACCESS_SHADER_READ_BIT);
    });
    VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    si.magFilter = si.minFilter = VK_FILTER_LINEAR;
    si.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    si.maxLod = 0.0f;
    VK_CHECK(vkCreateSampler(dev.device(), &si, nullptr, t.sampler.replace(dev.device())));
    return t;
}

}  // namespace scene
}  // namespace pw::render

#include "render/scene/height_texture.hpp"

#include <cstring>
#include <vector>

#include "render/vk/vk_check.hpp"

namespace pw::render {
inline namespace scene {

HeightTexture uploadHeightTexture(Device& dev, const HeightMap* map, const std::vector<HeightMap>& mips) {
    HeightTexture t;
    const bool real = map && !map->empty();
    HeightMap zero;
    zero.width = zero.height = 1;
    zero.texels = {0};
    const HeightMap& base = real ? *map : zero;
    t.width = base.width;
    t.height = base.height;
    // Level 0 and the CPU's own mip levels (core/model/height_map.hpp heightMipChain), all of them
    // down to 1 x 1, one after the other in the staging buffer.
    std::vector<const HeightMap*> levels{&base};
    if (real)
        for (const HeightMap& m : mips) levels.push_back(&m);
    t.levels = uint32_t(levels.size());
    size_t bytes = 0;
    for (const HeightMap* m : levels) bytes += m->texels.size() * sizeof(uint16_t);
    t.image = createImage(dev, {t.width, t.height}, VK_FORMAT_R16_UNORM, VK_SAMPLE_COUNT_1_BIT,
                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT, t.levels);
    Buffer staging = createBuffer(dev, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostWritten);
    std::vector<VkBufferImageCopy> regions;
    size_t offset = 0;
    for (uint32_t l = 0; l < t.levels; ++l) {
        const HeightMap& m = *levels[l];
        std::memcpy(static_cast<char*>(staging.mapped) + offset, m.texels.data(), m.texels.size() * sizeof(uint16_t));
        VkBufferImageCopy region{};
        region.bufferOffset = offset;
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, 1};
        region.imageExtent = {m.width, m.height, 1};
        regions.push_back(region);
        offset += m.texels.size() * sizeof(uint16_t);
    }
    dev.submitAndWait([&](VkCommandBuffer cmd) {
        imageBarrier(cmd, t.image.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, t.levels);
        vkCmdCopyBufferToImage(cmd, staging.buffer, t.image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(regions.size()),
                               regions.data());
        imageBarrier(cmd, t.image.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT, VK_ACCESS_SHADER_READ_BIT, t.levels);
    });
    VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    si.magFilter = si.minFilter = VK_FILTER_LINEAR;
    si.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;  // band-limited displacement blends two levels
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    si.maxLod = float(t.levels - 1);
    VK_CHECK(vkCreateSampler(dev.device(), &si, nullptr, t.sampler.replace(dev.device())));
    return t;
}

}  // namespace scene
}  // namespace pw::render

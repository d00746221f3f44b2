// The height map on the GPU (DESIGN §11): one R16_UNORM image with the CPU's mip levels
// (core/model/height_map.hpp heightMipChain), sampled with linear filtering between texels and levels
// and clamp-to-edge (core/model/height_map.hpp samples a level the same way on the CPU), bound at
// binding 3. A 1 x 1 zero texture stands in when there is no map, so the descriptor is always valid.
#pragma once

#include "core/model/height_map.hpp"
#include "render/vk/buffers.hpp"

namespace pw::render {
inline namespace scene {

struct HeightTexture {
    Image image;
    OwnedSampler sampler;
    uint32_t width = 0, height = 0;
    uint32_t levels = 1;  // mip levels, down to 1 x 1
};

// `mips`: heightMipChain(*map, …) down to 1 x 1 (empty without a map).
HeightTexture uploadHeightTexture(Device& dev, const HeightMap* map, const std::vector<HeightMap>& mips);

}  // namespace scene
}  // namespace pw::render

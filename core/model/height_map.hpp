// Height maps for displacement (DESIGN §11): an 8- or 16-bit PNG read through stb_image as one
// 16-bit channel (grey, or the luminance of colour; 8-bit values v become v * 257, so 0..1 is kept
// exactly), sampled like the GPU's linear filter with clamp-to-edge. core/eval/displacement.hpp maps
// them onto the model.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pw {
inline namespace model {

struct HeightMap {
    uint32_t width = 0, height = 0;
    int bits = 8;                  // of the file
    std::vector<uint16_t> texels;  // row-major, row 0 = the image's top row = v 0
    std::string source;            // the file it came from (messages)
    bool empty() const { return texels.empty(); }
    double texel(int64_t x, int64_t y) const;  // 0..1, coordinates clamped to the image
    // Bilinear at (u, v) in [0, 1]^2 with texel centres at (i + 0.5) / size and clamp-to-edge, as a
    // VK_FILTER_LINEAR sampler reads it.
    double sample(double u, double v) const;
};

// Reads a PNG height map; InputError naming the file when it is missing, not a PNG, or larger than
// 8192 x 8192.
HeightMap loadHeightMap(const std::filesystem::path& path);
// An in-memory map (tests, generated terrain): width x height values in 0..1, row-major.
HeightMap heightMapFromValues(uint32_t width, uint32_t height, const std::vector<double>& values, std::string source = "(generated)");

// The map's mip levels 1, 2, … (each half the size of the one before, at least 1 texel, the mean of
// the 2 x 2 texels above it), at most `levels` of them, stopping at 1 x 1. The GPU's texture holds
// the same levels (render/scene/height_texture), so both sides band-limit the map alike.
std::vector<HeightMap> heightMipChain(const HeightMap& map, int levels);

}  // namespace model
}  // namespace pw

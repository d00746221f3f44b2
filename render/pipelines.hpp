// Every graphics pipeline of the renderer, created up front from the embedded SPIR-V with a
// VkPipelineCache kept on disk ($XDG_CACHE_HOME/patchwork or ~/.cache/patchwork), so switching
// spacing, shading or overlays never compiles anything.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <filesystem>
#include <string>

#include "device.hpp"

namespace pw::render {

// Tessellation-evaluation variants: one per partitioning (pow2 uses equal spacing).
enum class SpacingVariant { Equal = 0, FractionalOdd = 1, FractionalEven = 2 };
constexpr int kSpacingVariants = 3;

struct PipelineSet {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;  // 0: frame UBO, 1: patch data, 2: counters
    VkPipelineLayout layout = VK_NULL_HANDLE;          // + DrawPush push constants
    std::array<VkPipeline, kSpacingVariants> surface{};   // shaded tessellated surface
    std::array<VkPipeline, kSpacingVariants> wire{};      // same, polygonMode LINE + depth bias
    std::array<VkPipeline, kSpacingVariants> normals{};   // point-mode TES + geometry shader (if supported)
    VkPipeline mesh = VK_NULL_HANDLE;        // plain pre-tessellated triangles
    VkPipeline gridLines = VK_NULL_HANDLE;   // control net lines (over everything)
    VkPipeline gridPoints = VK_NULL_HANDLE;  // control points
    VkPipeline colorLines = VK_NULL_HANDLE;  // coloured lines, depth-tested (boundaries)
    VkPipelineCache cache = VK_NULL_HANDLE;
    std::filesystem::path cacheFile;
    double createMs = 0.0;  // time spent creating all pipelines
};

// The directory for the pipeline cache: $XDG_CACHE_HOME/patchwork, else ~/.cache/patchwork.
std::filesystem::path pipelineCacheDir();

PipelineSet createPipelines(Device& dev, VkFormat color, VkFormat depth, VkSampleCountFlagBits samples);
// Saves the cache (best effort) and destroys everything.
void destroyPipelines(Device& dev, PipelineSet& set);

}  // namespace pw::render

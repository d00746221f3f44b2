// Every graphics pipeline of the renderer, described up front and made the first time a frame binds
// it (issue 43: lavapipe compiles a pipeline in 50-100 ms and a first frame needs about 3 of the 60),
// from the embedded SPIR-V with a VkPipelineCache kept on disk ($XDG_CACHE_HOME/patchwork or
// ~/.cache/patchwork), so a variant used before compiles nothing.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/vk/device.hpp"
#include "render/vk/pipeline_builder.hpp"

namespace pw::render {
inline namespace scene {

// Tessellation-evaluation variants: one per partitioning (pow2 uses equal spacing).
enum class SpacingVariant { Equal = 0, FractionalOdd = 1, FractionalEven = 2 };
constexpr int kSpacingVariants = 3;
// Control-shader variants: Fixed computes uniform levels and per-patch overrides only; Full adds
// adaptive levels and culling. lavapipe executes both sides of every branch, so code that is
// switched off still costs (1 024 patches at 16: ~25 ms a frame); GPUs lose nothing either way.
enum class LevelsVariant { Fixed = 0, Full = 1 };
constexpr int kLevelsVariants = 2;
// Varying sets: Lean passes position and normal (lit, normal, zebra, wireframe); Full adds UV,
// patch id and curvatures (patch, uv, curvature shading). Each varying costs per-vertex work in
// lavapipe's draw module and attribute bandwidth on GPUs.
enum class VaryingsVariant { Lean = 0, Full = 1 };
constexpr int kVaryingsVariants = 2;

// Index of the shaded surface pipeline for a spacing, levels and varyings variant.
constexpr size_t surfaceIndex(int spacing, LevelsVariant l, VaryingsVariant v) {
    return (size_t(spacing) * kLevelsVariants + size_t(l)) * kVaryingsVariants + size_t(v);
}
// Index of the wireframe or normal-overlay pipeline (lean varyings) for a spacing and levels variant.
constexpr size_t overlayIndex(int spacing, LevelsVariant l) { return size_t(spacing) * kLevelsVariants + size_t(l); }

// What making the pipelines has cost so far (shared by the makers, which outlive moves of the set).
struct PipelineCost {
    double createMs = 0.0;  // set-up plus every pipeline made
    int made = 0, described = 0;
};

// The pipelines of the tessellated surfaces, for one evaluation-shader family (plain or displaced).
struct SurfacePipelines {
    // shaded tessellated surface, by surfaceIndex
    std::array<LazyPipeline, kSpacingVariants * kLevelsVariants * kVaryingsVariants> surface{};
    // by overlayIndex: the surface as polygonMode LINE + depth bias; point-mode evaluation +
    // geometry shader for normal vectors (if supported)
    std::array<LazyPipeline, kSpacingVariants * kLevelsVariants> wire{}, normals{};
    // Bézier triangles (10 control points, triangle domain): shaded by surfaceIndex, wireframe and
    // normal vectors (if supported) by overlayIndex.
    std::array<LazyPipeline, kSpacingVariants * kLevelsVariants * kVaryingsVariants> triSurface{};
    std::array<LazyPipeline, kSpacingVariants * kLevelsVariants> triWire{}, triNormals{};
};

// The handles of every pipeline of the renderer (PipelineSet owns them).
struct PipelineHandles {
    // 0: frame UBO, 1: patch data, 2: counters, 3: height map, 4: pool, 5: window indices, 6: merged blocks
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;  // + gpu::DrawPush push constants
    // The tessellated surfaces, plain (tess[0]) and displaced by the height map (tess[1], described
    // on first use: ensureDisplacedPipelines).
    std::array<SurfacePipelines, 2> tess{};
    // The isoline domain, by spacing variant: Bézier curves (4 points) and the isocurve overlay of
    // every window (16 points).
    std::array<LazyPipeline, kSpacingVariants> curves{}, isocurves{};
    // Curvature combs (shaders/comb.*): on Bézier curves and on windows' isocurves; equal spacing.
    LazyPipeline combs, isoCombs;
    std::array<LazyPipeline, kVaryingsVariants> mesh{};  // plain pre-tessellated triangles
    // Blocks of Bu x Bv net windows at one level, one patch each (render/scene/merged_blocks.hpp); lean varyings.
    LazyPipeline merged;
    // The raw tessellator's reference for `patchwork bench`: windows at uniform levels through trivial shaders.
    LazyPipeline raw;
    LazyPipeline gridLines;    // control net lines (over everything)
    LazyPipeline gridPoints;   // control points
    LazyPipeline colorLines;   // coloured lines, depth-tested (boundaries)
    LazyPipeline groundLines;  // coloured translucent lines, depth-tested (the editor's ground grid)
    VkPipelineCache cache = VK_NULL_HANDLE;
    std::filesystem::path cacheFile;
    VkFormat colorFormat = VK_FORMAT_UNDEFINED, depthFormat = VK_FORMAT_UNDEFINED;  // what the pipelines draw into
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    std::shared_ptr<PipelineCost> cost = std::make_shared<PipelineCost>();
    // The shader modules the makers use, kept until the set is released.
    std::shared_ptr<std::vector<VkShaderModule>> modules = std::make_shared<std::vector<VkShaderModule>>();
};

// Every pipeline, their layouts and the pipeline cache, owned: when the set dies or is replaced it
// saves the cache (best effort) and destroys every handle. Move-only.
struct PipelineSet : PipelineHandles {
    PipelineSet() = default;
    explicit PipelineSet(VkDevice device) : device_(device) {}
    ~PipelineSet() { release(); }
    PipelineSet(PipelineSet&& o) noexcept
        : PipelineHandles(std::exchange(static_cast<PipelineHandles&>(o), PipelineHandles{})), device_(o.device_) {}
    PipelineSet& operator=(PipelineSet&& o) noexcept;
    PipelineSet(const PipelineSet&) = delete;
    PipelineSet& operator=(const PipelineSet&) = delete;

private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
};

// The directory for the pipeline cache: $XDG_CACHE_HOME/patchwork, else ~/.cache/patchwork.
std::filesystem::path pipelineCacheDir();

PipelineSet createPipelines(Device& dev, VkFormat color, VkFormat depth, VkSampleCountFlagBits samples);
// Builds set.tess[1], the displaced surfaces, unless they exist (the first frame with a height map).
void ensureDisplacedPipelines(Device& dev, PipelineSet& set);

}  // namespace scene
}  // namespace pw::render

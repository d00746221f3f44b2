// Building blocks of the graphics pipelines (render/scene/pipelines.cpp, render/domain/domain_view.cpp): shader
// modules from embedded SPIR-V and one pipeline for dynamic rendering from a short description.
#pragma once

#include <vulkan/vulkan.h>

#include <utility>
#include <vector>

#include "render/vk/device.hpp"
#include "shaders/spirv.hpp"

namespace pw::render {

struct PipelineDesc {
    std::vector<std::pair<VkShaderStageFlagBits, VkShaderModule>> stages;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    bool tess = false;
    uint32_t patchControlPoints = 16;
    VkPolygonMode polygon = VK_POLYGON_MODE_FILL;
    bool depthTest = true, depthWrite = true, depthBias = false;
    bool blend = false;              // source-alpha blending (translucent lines)
    bool rasterizerDiscard = false;  // nothing rasterised (transform feedback capture)
    int vertexLayout = 0;  // -1: none; 0: the pool (vec4: position, weight); 1: position, normal, uv (mesh); 2: position + rgba colour;
                           // 3: position, normal (mesh, lean varyings)
};

VkShaderModule makeModule(Device& dev, const spirv::Blob& blob);

// A pipeline for dynamic rendering into one colour attachment of `color` and a `depth` attachment
// (VK_FORMAT_UNDEFINED for both: no attachments), with dynamic viewport and scissor.
VkPipeline buildPipeline(Device& dev, VkPipelineLayout layout, VkPipelineCache cache, const PipelineDesc& d, VkFormat color, VkFormat depth,
                         VkSampleCountFlagBits samples);

}  // namespace pw::render

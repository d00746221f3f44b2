#include "render/vk/pipeline_builder.hpp"

namespace pw::render {
inline namespace vk {

VkShaderModule makeModule(Device& dev, const spirv::Blob& blob) {
    VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = blob.words * sizeof(uint32_t);
    ci.pCode = blob.code;
    VkShaderModule m;
    VK_CHECK(vkCreateShaderModule(dev.device(), &ci, nullptr, &m));
    return m;
}

VkPipeline buildPipeline(Device& dev, VkPipelineLayout layout, VkPipelineCache cache, const PipelineDesc& d, VkFormat color, VkFormat depth,
                         VkSampleCountFlagBits samples) {
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (auto& [stage, module] : d.stages) {
        VkPipelineShaderStageCreateInfo s{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        s.stage = stage;
        s.module = module;
        s.pName = "main";
        stages.push_back(s);
    }
    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attrs;
    if (d.vertexLayout < 0) {
        // no vertex input
    } else if (d.vertexLayout == 0) {  // the pool: position and weight
        bindings.push_back({0, 16, VK_VERTEX_INPUT_RATE_VERTEX});
        attrs.push_back({0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0});
    } else if (d.vertexLayout == 1 || d.vertexLayout == 3) {
        bindings.push_back({0, 12, VK_VERTEX_INPUT_RATE_VERTEX});
        bindings.push_back({1, 12, VK_VERTEX_INPUT_RATE_VERTEX});
        attrs.push_back({0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0});
        attrs.push_back({1, 1, VK_FORMAT_R32G32B32_SFLOAT, 0});
        if (d.vertexLayout == 1) {
            bindings.push_back({2, 8, VK_VERTEX_INPUT_RATE_VERTEX});
            attrs.push_back({2, 2, VK_FORMAT_R32G32_SFLOAT, 0});
        }
    } else {
        bindings.push_back({0, 28, VK_VERTEX_INPUT_RATE_VERTEX});
        attrs.push_back({0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0});
        attrs.push_back({1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 12});
    }
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vi.vertexBindingDescriptionCount = uint32_t(bindings.size());
    vi.pVertexBindingDescriptions = bindings.data();
    vi.vertexAttributeDescriptionCount = uint32_t(attrs.size());
    vi.pVertexAttributeDescriptions = attrs.data();
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = d.topology;
    VkPipelineTessellationStateCreateInfo ts{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
    ts.patchControlPoints = d.patchControlPoints;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.rasterizerDiscardEnable = d.rasterizerDiscard;
    rs.polygonMode = d.polygon;
    rs.cullMode = VK_CULL_MODE_NONE;
    rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    rs.lineWidth = 1.0f;
    rs.depthBiasEnable = d.depthBias;
    rs.depthBiasConstantFactor = -2.0f;
    rs.depthBiasSlopeFactor = -1.5f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = samples;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = d.depthTest;
    ds.depthWriteEnable = d.depthWrite;
    ds.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    // Blending "over" (colour by source alpha, alpha accumulated), or none; all four channels written.
    const VkPipelineColorBlendAttachmentState cb{VkBool32(d.blend),
                                                 VK_BLEND_FACTOR_SRC_ALPHA,
                                                 VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
                                                 VK_BLEND_OP_ADD,
                                                 VK_BLEND_FACTOR_ONE,
                                                 VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
                                                 VK_BLEND_OP_ADD,
                                                 0xf};
    VkPipelineColorBlendStateCreateInfo cbs{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cbs.attachmentCount = 1;
    cbs.pAttachments = &cb;
    const VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dy.dynamicStateCount = 2;
    dy.pDynamicStates = dyn;
    VkPipelineRenderingCreateInfo rci{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rci.colorAttachmentCount = color == VK_FORMAT_UNDEFINED ? 0 : 1;  // none: rendering without attachments
    rci.pColorAttachmentFormats = &color;
    rci.depthAttachmentFormat = depth;

    VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    ci.pNext = &rci;
    ci.stageCount = uint32_t(stages.size());
    ci.pStages = stages.data();
    ci.pVertexInputState = &vi;
    ci.pInputAssemblyState = &ia;
    ci.pTessellationState = d.tess ? &ts : nullptr;
    ci.pViewportState = &vp;
    ci.pRasterizationState = &rs;
    ci.pMultisampleState = &ms;
    ci.pDepthStencilState = &ds;
    ci.pColorBlendState = &cbs;
    ci.pDynamicState = &dy;
    ci.layout = layout;
    VkPipeline p;
    VK_CHECK(vkCreateGraphicsPipelines(dev.device(), cache, 1, &ci, nullptr, &p));
    return p;
}

}  // namespace vk
}  // namespace pw::render

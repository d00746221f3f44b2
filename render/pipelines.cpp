#include "pipelines.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <vector>

#include "gpu_types.hpp"
#include "spirv.hpp"

namespace pw::render {
namespace {

VkShaderModule makeModule(Device& dev, const spirv::Blob& blob) {
    VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = blob.words * sizeof(uint32_t);
    ci.pCode = blob.code;
    VkShaderModule m;
    VK_CHECK(vkCreateShaderModule(dev.device(), &ci, nullptr, &m));
    return m;
}

struct PipelineDesc {
    std::vector<std::pair<VkShaderStageFlagBits, VkShaderModule>> stages;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    bool tess = false;
    VkPolygonMode polygon = VK_POLYGON_MODE_FILL;
    bool depthTest = true, depthWrite = true, depthBias = false;
    int vertexLayout = 0;  // 0: vec3 position; 1: position, normal, uv (mesh); 2: position + rgba colour;
                           // 3: position, normal (mesh, lean varyings)
};

VkPipeline buildPipeline(Device& dev, const PipelineSet& set, const PipelineDesc& d, VkFormat color, VkFormat depth,
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
    if (d.vertexLayout == 0) {
        bindings.push_back({0, 12, VK_VERTEX_INPUT_RATE_VERTEX});
        attrs.push_back({0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0});
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
    ts.patchControlPoints = 16;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
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
    VkPipelineColorBlendAttachmentState cb{};
    cb.colorWriteMask = 0xf;
    VkPipelineColorBlendStateCreateInfo cbs{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cbs.attachmentCount = 1;
    cbs.pAttachments = &cb;
    const VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dy.dynamicStateCount = 2;
    dy.pDynamicStates = dyn;
    VkPipelineRenderingCreateInfo rci{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rci.colorAttachmentCount = 1;
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
    ci.layout = set.layout;
    VkPipeline p;
    VK_CHECK(vkCreateGraphicsPipelines(dev.device(), set.cache, 1, &ci, nullptr, &p));
    return p;
}

std::vector<char> readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) return {};
    return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

std::filesystem::path pipelineCacheDir() {
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::filesystem::path(x) / "patchwork";
    if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".cache" / "patchwork";
    return std::filesystem::temp_directory_path() / "patchwork-cache";
}

PipelineSet createPipelines(Device& dev, VkFormat color, VkFormat depth, VkSampleCountFlagBits samples) {
    const auto t0 = std::chrono::steady_clock::now();
    PipelineSet set;
    VkDevice d = dev.device();

    // Pipeline cache from disk (the driver rejects a blob from another device or driver version).
    const auto& props = dev.properties();
    set.cacheFile = pipelineCacheDir() / ("pipelines-" + std::to_string(props.vendorID) + "-" +
                                          std::to_string(props.deviceID) + "-" + std::to_string(props.driverVersion) + ".bin");
    std::vector<char> blob = readFile(set.cacheFile);
    VkPipelineCacheCreateInfo pc{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    pc.initialDataSize = blob.size();
    pc.pInitialData = blob.empty() ? nullptr : blob.data();
    if (vkCreatePipelineCache(d, &pc, nullptr, &set.cache) != VK_SUCCESS) {
        pc.initialDataSize = 0;
        pc.pInitialData = nullptr;
        VK_CHECK(vkCreatePipelineCache(d, &pc, nullptr, &set.cache));
    }

    // Descriptor set layout: 0 frame uniforms, 1 per-patch levels, 2 counters.
    const VkShaderStageFlags all = VK_SHADER_STAGE_ALL_GRAPHICS;
    VkDescriptorSetLayoutBinding b[3] = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, all, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, all, nullptr},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, all, nullptr},
    };
    VkDescriptorSetLayoutCreateInfo dl{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    dl.bindingCount = 3;
    dl.pBindings = b;
    VK_CHECK(vkCreateDescriptorSetLayout(d, &dl, nullptr, &set.setLayout));
    VkPushConstantRange pr{all, 0, sizeof(DrawPush)};
    VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &set.setLayout;
    pl.pushConstantRangeCount = 1;
    pl.pPushConstantRanges = &pr;
    VK_CHECK(vkCreatePipelineLayout(d, &pl, nullptr, &set.layout));

    // Shader modules (destroyed once the pipelines exist).
    std::vector<VkShaderModule> modules;
    auto mod = [&](const spirv::Blob& blob) {
        modules.push_back(makeModule(dev, blob));
        return modules.back();
    };
    VkShaderModule vert = mod(spirv::surface_vert);
    const VkShaderModule tesc[kLevelsVariants] = {mod(spirv::surface_tesc_fixed), mod(spirv::surface_tesc_full)};
    const VkShaderModule frag[kVaryingsVariants] = {mod(spirv::surface_frag), mod(spirv::surface_frag_full)};
    const spirv::Blob* tese[kSpacingVariants][kVaryingsVariants] = {
        {&spirv::surface_tese_equal, &spirv::surface_tese_equal_full},
        {&spirv::surface_tese_odd, &spirv::surface_tese_odd_full},
        {&spirv::surface_tese_even, &spirv::surface_tese_even_full}};
    const spirv::Blob* ptese[kSpacingVariants] = {&spirv::points_tese_equal, &spirv::points_tese_odd, &spirv::points_tese_even};
    VkShaderModule lineFrag = mod(spirv::line_frag);
    VkShaderModule geom = dev.caps().geometryShader ? mod(spirv::normals_geom) : VK_NULL_HANDLE;

    for (int s = 0; s < kSpacingVariants; ++s) {
        const VkShaderModule te[kVaryingsVariants] = {mod(*tese[s][0]), mod(*tese[s][1])};
        const VkShaderModule pte = geom ? mod(*ptese[s]) : VK_NULL_HANDLE;
        for (int l = 0; l < kLevelsVariants; ++l) {
            const auto lv = LevelsVariant(l);
            for (int v = 0; v < kVaryingsVariants; ++v) {
                PipelineDesc pd;
                pd.tess = true;
                pd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert}, {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tesc[l]},
                             {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, te[v]}, {VK_SHADER_STAGE_FRAGMENT_BIT, frag[v]}};
                set.surface[surfaceIndex(s, lv, VaryingsVariant(v))] = buildPipeline(dev, set, pd, color, depth, samples);
                if (v != int(VaryingsVariant::Lean)) continue;
                pd.polygon = VK_POLYGON_MODE_LINE;
                pd.depthWrite = false;
                pd.depthBias = true;
                set.wire[overlayIndex(s, lv)] = buildPipeline(dev, set, pd, color, depth, samples);
            }
            if (geom) {
                PipelineDesc nd;
                nd.tess = true;
                nd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert}, {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tesc[l]},
                             {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, pte},
                             {VK_SHADER_STAGE_GEOMETRY_BIT, geom}, {VK_SHADER_STAGE_FRAGMENT_BIT, lineFrag}};
                nd.depthWrite = false;
                set.normals[overlayIndex(s, lv)] = buildPipeline(dev, set, nd, color, depth, samples);
            }
        }
    }
    const spirv::Blob* meshVert[kVaryingsVariants] = {&spirv::mesh_vert, &spirv::mesh_vert_full};
    for (int v = 0; v < kVaryingsVariants; ++v) {
        PipelineDesc md;
        md.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        md.vertexLayout = v == int(VaryingsVariant::Full) ? 1 : 3;
        md.stages = {{VK_SHADER_STAGE_VERTEX_BIT, mod(*meshVert[v])}, {VK_SHADER_STAGE_FRAGMENT_BIT, frag[v]}};
        set.mesh[v] = buildPipeline(dev, set, md, color, depth, samples);
    }
    {
        VkShaderModule gv = mod(spirv::grid_vert);
        PipelineDesc gd;
        gd.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
        gd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, gv}, {VK_SHADER_STAGE_FRAGMENT_BIT, lineFrag}};
        gd.depthTest = false;
        gd.depthWrite = false;
        set.gridLines = buildPipeline(dev, set, gd, color, depth, samples);
        gd.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
        set.gridPoints = buildPipeline(dev, set, gd, color, depth, samples);
        PipelineDesc cd;
        cd.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
        cd.vertexLayout = 2;
        cd.depthWrite = false;
        cd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, mod(spirv::colorline_vert)}, {VK_SHADER_STAGE_FRAGMENT_BIT, lineFrag}};
        set.colorLines = buildPipeline(dev, set, cd, color, depth, samples);
    }
    for (VkShaderModule m : modules) vkDestroyShaderModule(d, m, nullptr);
    set.createMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return set;
}

void destroyPipelines(Device& dev, PipelineSet& set) {
    VkDevice d = dev.device();
    if (set.cache) {
        size_t size = 0;
        if (vkGetPipelineCacheData(d, set.cache, &size, nullptr) == VK_SUCCESS && size > 0) {
            std::vector<char> data(size);
            if (vkGetPipelineCacheData(d, set.cache, &size, data.data()) == VK_SUCCESS) {
                std::error_code ec;
                std::filesystem::create_directories(set.cacheFile.parent_path(), ec);
                const auto tmp = set.cacheFile.string() + ".tmp";
                std::ofstream out(tmp, std::ios::binary);
                if (out.write(data.data(), std::streamsize(size))) {
                    out.close();
                    std::filesystem::rename(tmp, set.cacheFile, ec);
                }
            }
        }
        vkDestroyPipelineCache(d, set.cache, nullptr);
    }
    auto kill = [&](VkPipeline& p) {
        if (p) vkDestroyPipeline(d, p, nullptr);
        p = VK_NULL_HANDLE;
    };
    for (auto& p : set.surface) kill(p);
    for (auto& p : set.wire) kill(p);
    for (auto& p : set.normals) kill(p);
    for (auto& p : set.mesh) kill(p);
    kill(set.gridLines);
    kill(set.gridPoints);
    kill(set.colorLines);
    if (set.layout) vkDestroyPipelineLayout(d, set.layout, nullptr);
    if (set.setLayout) vkDestroyDescriptorSetLayout(d, set.setLayout, nullptr);
    set = PipelineSet{};
}

}  // namespace pw::render

#include "render/scene/pipelines.hpp"

#include "render/vk/vk_owned.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <vector>

#include "core/gpu/gpu_interface.h"
#include "render/vk/pipeline_builder.hpp"
#include "shaders/spirv.hpp"

namespace pw::render {
inline namespace scene {
namespace {

using ModuleMaker = std::function<VkShaderModule(const spirv::Blob&)>;

std::vector<char> readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) return {};
    return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Where pipelines are built for: device, layout, cache and attachment formats; what making them costs.
struct Targets {
    Device& dev;
    VkPipelineLayout layout;
    VkPipelineCache cache;
    VkFormat color, depth;
    VkSampleCountFlagBits samples;
    std::shared_ptr<PipelineCost> cost;
    // The pipeline `pd` describes, made when first bound (its shader modules live as long as the set).
    LazyPipeline lazy(const PipelineDesc& pd) const {
        ++cost->described;
        return LazyPipeline(dev.device(), [t = *this, pd] {
            const auto t0 = std::chrono::steady_clock::now();
            const VkPipeline p = buildPipeline(t.dev, t.layout, t.cache, pd, t.color, t.depth, t.samples);
            t.cost->createMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            ++t.cost->made;
            return p;
        });
    }
};

// A maker of shader modules that the set keeps (its pipelines are made later, from them).
ModuleMaker keepModules(Device& dev, PipelineHandles& set) {
    return [&dev, modules = set.modules](const spirv::Blob& blob) { return modules->emplace_back(makeModule(dev, blob)); };
}

// Stages every tessellated family shares: vertex, the fragment shader per varyings set, the line
// fragment shader and the normals geometry shader (null where the device has none).
struct SharedStages {
    VkShaderModule vert;
    const VkShaderModule* frag;  // [kVaryingsVariants]
    VkShaderModule lineFrag, geom;
};

// The pipelines of one patch kind (quad patches, Bézier triangles): shaded by surfaceIndex,
// wireframe and normal overlays by overlayIndex.
struct FamilyOut {
    std::array<LazyPipeline, kSpacingVariants * kLevelsVariants * kVaryingsVariants>& surface;
    std::array<LazyPipeline, kSpacingVariants * kLevelsVariants>& wire;
    std::array<LazyPipeline, kSpacingVariants * kLevelsVariants>& normals;
};

// One patch family (quad windows or Bézier triangles) from its generated shader index
// (shaders/CMakeLists.txt): control shader by levels, evaluation shader by spacing x varyings x
// displacement, the normals' point-mode evaluation by spacing x displacement.
struct TessShaders {
    const spirv::Blob& (*tesc)(std::size_t levels);
    const spirv::Blob& (*tese)(std::size_t spacing, std::size_t varyings, std::size_t displace);
    const spirv::Blob& (*points)(std::size_t spacing, std::size_t displace);
};

template <class Mod>
void buildTessFamily(const Targets& t, const SharedStages& sh, uint32_t controlPoints, const TessShaders& shaders, size_t displaced,
                     Mod&& mod, FamilyOut out) {
    const VkShaderModule tesc[kLevelsVariants] = {mod(shaders.tesc(size_t(LevelsVariant::Fixed))),
                                                  mod(shaders.tesc(size_t(LevelsVariant::Full)))};
    for (int s = 0; s < kSpacingVariants; ++s) {
        const VkShaderModule te[kVaryingsVariants] = {mod(shaders.tese(size_t(s), size_t(VaryingsVariant::Lean), displaced)),
                                                      mod(shaders.tese(size_t(s), size_t(VaryingsVariant::Full), displaced))};
        const VkShaderModule pte = sh.geom ? mod(shaders.points(size_t(s), displaced)) : VK_NULL_HANDLE;
        for (int l = 0; l < kLevelsVariants; ++l) {
            const auto lv = LevelsVariant(l);
            for (int v = 0; v < kVaryingsVariants; ++v) {
                PipelineDesc pd;
                pd.tess = true;
                pd.patchControlPoints = controlPoints;
                pd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, sh.vert},
                             {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tesc[size_t(l)]},
                             {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, te[v]},
                             {VK_SHADER_STAGE_FRAGMENT_BIT, sh.frag[v]}};
                out.surface[surfaceIndex(s, lv, VaryingsVariant(v))] = t.lazy(pd);
                if (v != int(VaryingsVariant::Lean)) continue;
                pd.polygon = VK_POLYGON_MODE_LINE;
                pd.depthWrite = false;
                pd.depthBias = true;
                pd.blend = true;  // a dense wire fades (surface.frag, wireOpacity)
                out.wire[overlayIndex(s, lv)] = t.lazy(pd);
            }
            if (!sh.geom) continue;
            PipelineDesc nd;
            nd.tess = true;
            nd.patchControlPoints = controlPoints;
            nd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, sh.vert},
                         {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tesc[size_t(l)]},
                         {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, pte},
                         {VK_SHADER_STAGE_GEOMETRY_BIT, sh.geom},
                         {VK_SHADER_STAGE_FRAGMENT_BIT, sh.lineFrag}};
            nd.depthWrite = false;
            out.normals[overlayIndex(s, lv)] = t.lazy(nd);
        }
    }
}

// The vertex, fragment, line and normals-geometry modules every family shares; `frag` holds
// kVaryingsVariants modules and must outlive the result.
SharedStages makeSharedStages(Device& dev, const ModuleMaker& mod, VkShaderModule (&frag)[kVaryingsVariants]) {
    for (int v = 0; v < kVaryingsVariants; ++v) frag[v] = mod(spirv::surface_frag(size_t(v)));
    return {mod(spirv::surface_vert()), frag, mod(spirv::line_frag()),
            dev.caps().geometryShader ? mod(spirv::normals_geom()) : VK_NULL_HANDLE};
}

// The quad and triangle surface families, plain or displaced (-DDISPLACE evaluation shaders).
void buildSurfaceFamilies(const Targets& t, const SharedStages& shared, SurfacePipelines& out, bool displaced, const ModuleMaker& mod) {
    const size_t d = displaced ? 1 : 0;
    buildTessFamily(t, shared, 16, {spirv::surface_tesc, spirv::surface_tese, spirv::points_tese}, d, mod,
                    {out.surface, out.wire, out.normals});
    // Bézier triangles: the same vertex and fragment shaders, their own control and evaluation shaders.
    buildTessFamily(t, shared, 10, {spirv::tri_surface_tesc, spirv::tri_surface_tese, spirv::tri_points_tese}, d, mod,
                    {out.triSurface, out.triWire, out.triNormals});
}

}  // namespace

std::filesystem::path pipelineCacheDir() {
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::filesystem::path(x) / "patchwork";
    if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".cache" / "patchwork";
    return std::filesystem::temp_directory_path() / "patchwork-cache";
}

PipelineSet createPipelines(Device& dev, VkFormat color, VkFormat depth, VkSampleCountFlagBits samples) {
    const auto t0 = std::chrono::steady_clock::now();
    PipelineSet set(dev.device());
    VkDevice d = dev.device();

    // Pipeline cache from disk (the driver rejects a blob from another device or driver version).
    const auto& props = dev.properties();
    set.cacheFile = pipelineCacheDir() / ("pipelines-" + std::to_string(props.vendorID) + "-" + std::to_string(props.deviceID) + "-" +
                                          std::to_string(props.driverVersion) + ".bin");
    std::vector<char> blob = readFile(set.cacheFile);
    VkPipelineCacheCreateInfo pc{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    pc.initialDataSize = blob.size();
    pc.pInitialData = blob.empty() ? nullptr : blob.data();
    if (vkCreatePipelineCache(d, &pc, nullptr, &set.cache) != VK_SUCCESS) {
        pc.initialDataSize = 0;
        pc.pInitialData = nullptr;
        VK_CHECK(vkCreatePipelineCache(d, &pc, nullptr, &set.cache));
    }

    // Descriptor set layout: 0 frame uniforms, 1 per-patch levels, 2 counters, 3 the height map; the
    // merged blocks' 4 pool, 5 window indices, 6 blocks; 7 the trim segments.
    const VkShaderStageFlags all = VK_SHADER_STAGE_ALL_GRAPHICS;
    VkDescriptorSetLayoutBinding b[8] = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, all, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, all, nullptr},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, all, nullptr},
        {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, all, nullptr},
        // Only the stages that read them: every stage then sees at most 4 storage buffers (the
        // guaranteed maxPerStageDescriptorStorageBuffers).
        {4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, nullptr},
        {5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, nullptr},
        {6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, nullptr},
        {7, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
    };
    VkDescriptorSetLayoutCreateInfo dl{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    dl.bindingCount = 8;
    dl.pBindings = b;
    VK_CHECK(vkCreateDescriptorSetLayout(d, &dl, nullptr, &set.setLayout));
    VkPushConstantRange pr{all, 0, sizeof(gpu::DrawPush)};
    VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &set.setLayout;
    pl.pushConstantRangeCount = 1;
    pl.pPushConstantRanges = &pr;
    VK_CHECK(vkCreatePipelineLayout(d, &pl, nullptr, &set.layout));

    // Shader modules (kept with the set: the pipelines are made from them when first bound).
    const ModuleMaker mod = keepModules(dev, set);
    VkShaderModule frag[kVaryingsVariants] = {};
    const SharedStages shared = makeSharedStages(dev, mod, frag);
    const VkShaderModule vert = shared.vert, lineFrag = shared.lineFrag;
    set.colorFormat = color;
    set.depthFormat = depth;
    set.samples = samples;
    const Targets targets{dev, set.layout, set.cache, color, depth, samples, set.cost};
    buildSurfaceFamilies(targets, shared, set.tess[0], false, mod);
    // Curves and isocurves: the isoline domain; lines drawn depth-tested over the surface.
    {
        const VkShaderModule ctesc = mod(spirv::curve_tesc()), itesc = mod(spirv::isocurve_tesc());
        for (int s = 0; s < kSpacingVariants; ++s) {
            PipelineDesc cd;
            cd.tess = true;
            cd.patchControlPoints = 4;
            cd.depthWrite = false;
            cd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert},
                         {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, ctesc},
                         {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, mod(spirv::curve_tese(size_t(s)))},
                         {VK_SHADER_STAGE_FRAGMENT_BIT, lineFrag}};
            set.curves[size_t(s)] = targets.lazy(cd);
            cd.patchControlPoints = 16;
            cd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert},
                         {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, itesc},
                         {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, mod(spirv::isocurve_tese(size_t(s)))},
                         {VK_SHADER_STAGE_FRAGMENT_BIT, lineFrag}};
            set.isocurves[size_t(s)] = targets.lazy(cd);
        }
        PipelineDesc cd;
        cd.tess = true;
        cd.patchControlPoints = 4;
        cd.depthWrite = false;
        cd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert},
                     {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, mod(spirv::comb_tesc())},
                     {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, mod(spirv::comb_tese())},
                     {VK_SHADER_STAGE_FRAGMENT_BIT, lineFrag}};
        set.combs = targets.lazy(cd);
        cd.patchControlPoints = 16;
        cd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert},
                     {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, mod(spirv::isocomb_tesc())},
                     {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, mod(spirv::isocomb_tese())},
                     {VK_SHADER_STAGE_FRAGMENT_BIT, lineFrag}};
        set.isoCombs = targets.lazy(cd);
    }
    for (int v = 0; v < kVaryingsVariants; ++v) {
        PipelineDesc md;
        md.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        md.vertexLayout = v == int(VaryingsVariant::Full) ? 1 : 3;
        md.stages = {{VK_SHADER_STAGE_VERTEX_BIT, mod(spirv::mesh_vert(size_t(v)))}, {VK_SHADER_STAGE_FRAGMENT_BIT, frag[v]}};
        set.mesh[v] = targets.lazy(md);
    }
    {  // merged blocks: one control point (the block's index), no vertex buffer; lean varyings
        PipelineDesc pd;
        pd.tess = true;
        pd.patchControlPoints = 1;
        pd.vertexLayout = -1;
        pd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, mod(spirv::merged_vert())},
                     {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, mod(spirv::merged_tesc())},
                     {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, mod(spirv::merged_tese())},
                     {VK_SHADER_STAGE_FRAGMENT_BIT, frag[size_t(VaryingsVariant::Lean)]}};
        set.merged = targets.lazy(pd);
        PipelineDesc rd;
        rd.tess = true;
        rd.patchControlPoints = 16;
        rd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert},
                     {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, mod(spirv::raw_tesc())},
                     {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, mod(spirv::raw_tese())},
                     {VK_SHADER_STAGE_FRAGMENT_BIT, frag[size_t(VaryingsVariant::Lean)]}};
        set.raw = targets.lazy(rd);
    }
    {
        VkShaderModule gv = mod(spirv::grid_vert());
        PipelineDesc gd;
        gd.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
        gd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, gv}, {VK_SHADER_STAGE_FRAGMENT_BIT, lineFrag}};
        gd.depthTest = false;
        gd.depthWrite = false;
        set.gridLines = targets.lazy(gd);
        gd.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
        set.gridPoints = targets.lazy(gd);
        PipelineDesc cd;
        cd.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
        cd.vertexLayout = 2;
        cd.depthWrite = false;
        cd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, mod(spirv::colorline_vert())}, {VK_SHADER_STAGE_FRAGMENT_BIT, lineFrag}};
        set.colorLines = targets.lazy(cd);
        cd.blend = true;
        set.groundLines = targets.lazy(cd);
    }
    set.cost->createMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return set;
}

void ensureDisplacedPipelines(Device& dev, PipelineSet& set) {
    if (set.tess[1].surface[0]) return;
    const auto t0 = std::chrono::steady_clock::now();
    const ModuleMaker mod = keepModules(dev, set);
    VkShaderModule frag[kVaryingsVariants] = {};
    const SharedStages shared = makeSharedStages(dev, mod, frag);
    buildSurfaceFamilies({dev, set.layout, set.cache, set.colorFormat, set.depthFormat, set.samples, set.cost}, shared, set.tess[1], true,
                         mod);
    set.cost->createMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

PipelineSet& PipelineSet::operator=(PipelineSet&& o) noexcept {
    if (this != &o) {
        release();
        static_cast<PipelineHandles&>(*this) = std::exchange(static_cast<PipelineHandles&>(o), PipelineHandles{});
        device_ = o.device_;
    }
    return *this;
}

void PipelineSet::release() {
    VkDevice d = device_;
    PipelineHandles& set = *this;
    if (!d) return;
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
    auto kill = [&](LazyPipeline& p) { p.destroy(); };
    for (SurfacePipelines& f : set.tess) {
        for (auto& p : f.surface) kill(p);
        for (auto& p : f.wire) kill(p);
        for (auto& p : f.normals) kill(p);
        for (auto& p : f.triSurface) kill(p);
        for (auto& p : f.triWire) kill(p);
        for (auto& p : f.triNormals) kill(p);
    }
    for (auto& p : set.curves) kill(p);
    for (auto& p : set.isocurves) kill(p);
    kill(set.combs);
    kill(set.isoCombs);
    for (auto& p : set.mesh) kill(p);
    kill(set.merged);
    kill(set.raw);
    kill(set.gridLines);
    kill(set.gridPoints);
    kill(set.colorLines);
    kill(set.groundLines);
    if (set.modules)
        for (VkShaderModule m : *set.modules) vkDestroyShaderModule(d, m, nullptr);
    if (set.layout) vkDestroyPipelineLayout(d, set.layout, nullptr);
    if (set.setLayout) vkDestroyDescriptorSetLayout(d, set.setLayout, nullptr);
    set = PipelineHandles{};
}

}  // namespace scene
}  // namespace pw::render

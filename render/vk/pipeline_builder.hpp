// Building blocks of the graphics pipelines (render/scene/pipelines.cpp, render/domain/domain_view.cpp): shader
// modules from embedded SPIR-V and one pipeline for dynamic rendering from a short description.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <utility>
#include <vector>

#include "render/vk/device.hpp"
#include "shaders/spirv.hpp"

namespace pw::render {
inline namespace vk {

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

// One pipeline, made the first time it is used as a VkPipeline (bound) from the maker it was given
// (lavapipe compiles a pipeline in 50-100 ms; a first frame needs few of those a renderer can use);
// `if (p)` asks whether it exists or can be made (a normals pipeline needs geometry shaders) without
// making it. Move-only; destroys what it made (on `device`) when it dies or on destroy().
class LazyPipeline {
public:
    LazyPipeline() = default;
    LazyPipeline(VkDevice device, std::function<VkPipeline()> make) : device_(device), make_(std::move(make)) {}
    ~LazyPipeline() { destroy(); }
    LazyPipeline(LazyPipeline&& o) noexcept
        : device_(o.device_), handle_(std::exchange(o.handle_, VK_NULL_HANDLE)), make_(std::exchange(o.make_, nullptr)) {}
    LazyPipeline& operator=(LazyPipeline&& o) noexcept {
        if (this != &o) {
            destroy();
            device_ = o.device_;
            handle_ = std::exchange(o.handle_, VK_NULL_HANDLE);
            make_ = std::exchange(o.make_, nullptr);
        }
        return *this;
    }
    LazyPipeline(const LazyPipeline&) = delete;
    LazyPipeline& operator=(const LazyPipeline&) = delete;
    operator VkPipeline() const {  // NOLINT: binds like the handle it stands for
        if (!handle_ && make_) handle_ = make_();
        return handle_;
    }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE || bool(make_); }
    bool made() const { return handle_ != VK_NULL_HANDLE; }
    void destroy() {
        if (handle_) vkDestroyPipeline(device_, handle_, nullptr);
        handle_ = VK_NULL_HANDLE;
        make_ = nullptr;
    }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    mutable VkPipeline handle_ = VK_NULL_HANDLE;
    std::function<VkPipeline()> make_;
};

}  // namespace vk
}  // namespace pw::render

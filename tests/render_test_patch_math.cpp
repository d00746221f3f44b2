// core/gpu/patch_math.h on the GPU and on the CPU: tests/patch_math_check.comp runs every function of
// the shared header on the device (lavapipe here, any GPU with `--gtest` on the device machine)
// and the test runs the same header compiled as C++ on the same inputs. Integer results (edge
// slots, canonical direction, rounded levels) must be equal; float results equal to float rounding;
// and a shared boundary walked from both ends must give the same bits on the GPU (no cracks).
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "patch_math_check.h"
#include "render/vk/buffers.hpp"
#include "render/vk/vk_owned.hpp"
#include "render_support.hpp"

namespace pw::test {
namespace {

const uint32_t kCheckSpirv[] = {
#include "patch_math_check.inc"
};

// Runs the check shader once over `in`; returns its kOutSize floats.
std::vector<float> runOnGpu(render::Device& dev, const gpu::CheckInput& in) {
    VkDevice d = dev.device();
    render::Buffer inBuf = render::createBuffer(dev, sizeof in, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, render::MemoryUse::HostWritten);
    render::Buffer outBuf =
        render::createBuffer(dev, sizeof(float) * gpu::kOutSize, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, render::MemoryUse::Readback);
    std::memcpy(inBuf.mapped, &in, sizeof in);

    const VkShaderModuleCreateInfo smi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, nullptr, 0, sizeof kCheckSpirv, kCheckSpirv};
    render::OwnedShaderModule module;
    VK_CHECK(vkCreateShaderModule(d, &smi, nullptr, module.replace(d)));
    VkDescriptorSetLayoutBinding bindings[2] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
                                                {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
    const VkDescriptorSetLayoutCreateInfo dli{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO, nullptr, 0, 2, bindings};
    render::OwnedDescriptorSetLayout setLayout;
    VK_CHECK(vkCreateDescriptorSetLayout(d, &dli, nullptr, setLayout.replace(d)));
    const VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO, nullptr, 0, 1, setLayout.ptr(), 0, nullptr};
    render::OwnedPipelineLayout layout;
    VK_CHECK(vkCreatePipelineLayout(d, &pli, nullptr, layout.replace(d)));
    VkComputePipelineCreateInfo cpi{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    cpi.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_COMPUTE_BIT, module, "main", nullptr};
    cpi.layout = layout;
    render::OwnedPipeline pipeline;
    VK_CHECK(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &cpi, nullptr, pipeline.replace(d)));
    const VkDescriptorPoolSize ps{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
    const VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, nullptr, 0, 1, 1, &ps};
    render::OwnedDescriptorPool pool;
    VK_CHECK(vkCreateDescriptorPool(d, &dpi, nullptr, pool.replace(d)));
    const VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, nullptr, pool, 1, setLayout.ptr()};
    VkDescriptorSet set = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateDescriptorSets(d, &dai, &set));
    const VkDescriptorBufferInfo bi[2] = {{inBuf.buffer, 0, VK_WHOLE_SIZE}, {outBuf.buffer, 0, VK_WHOLE_SIZE}};
    VkWriteDescriptorSet w[2]{};
    for (uint32_t i = 0; i < 2; ++i)
        w[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, set, i, 0, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, nullptr, &bi[i], nullptr};
    vkUpdateDescriptorSets(d, 2, w, 0, nullptr);

    dev.submitAndWait([&](VkCommandBuffer cmd) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
        vkCmdDispatch(cmd, 1, 1, 1);
        const VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_HOST_READ_BIT};
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0, nullptr, 0, nullptr);
    });
    std::vector<float> out(gpu::kOutSize);
    std::memcpy(out.data(), outBuf.mapped, sizeof(float) * out.size());
    return out;  // every handle above frees itself
}

// Inputs: levels across every rounding boundary (and NaN, negative, past 64), pool quadruples with
// every tie pattern, boundary curves seen by a perspective camera, some behind it.
gpu::CheckInput makeInput() {
    gpu::CheckInput in{};
    const glm::mat4 proj = glm::perspective(glm::radians(45.0f), 1.5f, 0.1f, 100.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(3, -8, 4), glm::vec3(0, 0, 0.5f), glm::vec3(0, 0, 1));
    in.viewProj = proj * view;
    in.eye = {3, -8, 4, 1};
    in.params = {2.0f, 14.0f, 48.0f, 6.0f};
    in.exps = {6.0f, 1.5f, 0.0f, 0.0f};  // the pow2 distance curve: 64 at d0, 2.8 at d1
    in.viewport = {1200, 800, 0, 0};
    const float levels[] = {std::numeric_limits<float>::quiet_NaN(),
                            -3,
                            0,
                            0.25f,
                            1,
                            1.0001f,
                            1.5f,
                            2,
                            2.5f,
                            3,
                            3.999f,
                            4,
                            4.0001f,
                            4.5f,
                            5,
                            6.3f,
                            7,
                            7.99f,
                            8,
                            8.01f,
                            15,
                            16,
                            16.5f,
                            31,
                            32,
                            32.2f,
                            33,
                            62.5f,
                            63,
                            63.5f,
                            64,
                            64.5f,
                            100,
                            1e30f};
    std::mt19937 rng(18);
    std::uniform_real_distribution<float> level(0.0f, 70.0f), coord(-3.0f, 3.0f);
    for (int i = 0; i < gpu::kCheckLevels; ++i) in.levels[i] = i < int(std::size(levels)) ? levels[i] : level(rng);
    std::uniform_int_distribution<uint32_t> small(0, 3), big(0, 4000000000u);
    for (int i = 0; i < gpu::kCheckPools; ++i) {
        const bool ties = i < gpu::kCheckPools / 2;  // small indices: equal ends, equal middles, palindromes
        for (int k = 0; k < 4; ++k) in.pools[i][k] = ties ? small(rng) : big(rng);
    }
    for (int i = 0; i < gpu::kCheckEdges * 4; ++i) in.edges[i] = {coord(rng), coord(rng), coord(rng) + (i >= 120 ? 9.0f : 0.0f), 1};
    return in;
}

class PatchMath : public RenderTest {};

TEST_F(PatchMath, TheShadersAndTheCpuAgree) {
    const gpu::CheckInput in = makeInput();
    const std::vector<float> g = runOnGpu(sharedDevice(), in);

    for (int i = 0; i < gpu::kCheckLevels; ++i)
        for (uint32_t s = 0; s < 4; ++s) {
            const float cpu = gpu::roundLevel(in.levels[i], s), gpuValue = g[size_t(gpu::kOutRound + i * 4 + int(s))];
            EXPECT_EQ(cpu, gpuValue) << "roundLevel(" << in.levels[i] << ", spacing " << s << ")";
            if (s == gpu::kSpacingPow2 || s == gpu::kSpacingEqual) {
                EXPECT_EQ(cpu, std::round(cpu)) << "an integer level";
            }
        }
    for (int i = 0; i < gpu::kCheckBernstein; ++i) {
        const float t = float(i) / float(gpu::kCheckBernstein - 1), s = 1.0f - t;
        const glm::vec4 cpu[3] = {gpu::bernstein3(t, s), gpu::bernstein3D1(t, s), gpu::bernstein3D2(t, s)};
        for (int d = 0; d < 3; ++d)
            for (int k = 0; k < 4; ++k)
                EXPECT_NEAR(cpu[d][k], g[size_t(gpu::kOutBernstein + i * 12 + d * 4 + k)], 2e-6f * (1 + 11 * d))
                    << "derivative " << d << " weight " << k << " at t = " << t;
        // ... and the double instantiation the CPU evaluates with is the same formula.
        EXPECT_NEAR(gpu::bernstein3(double(t), double(s)).y, cpu[0].y, 1e-6);
    }
    for (int e = 0; e < 4; ++e)
        for (int k = 0; k < 4; ++k)
            for (int d = 0; d < 4; ++d) EXPECT_EQ(float(gpu::quadEdgeSlot(e, k, d)), g[size_t(gpu::kOutSlots + e * 16 + k * 4 + d)]);
    for (int e = 0; e < 3; ++e)
        for (int k = 0; k < 4; ++k) EXPECT_EQ(float(gpu::triEdgeSlot(e, k)), g[size_t(gpu::kOutSlots + 64 + e * 4 + k)]);
    int reversed = 0;
    for (int i = 0; i < gpu::kCheckPools; ++i) {
        const glm::uvec4 p = in.pools[i];
        const bool cpu = gpu::edgeReversed(p.x, p.y, p.z, p.w);
        reversed += cpu;
        EXPECT_EQ(cpu ? 1.0f : 0.0f, g[size_t(gpu::kOutReversed + i)]) << p.x << " " << p.y << " " << p.z << " " << p.w;
    }
    EXPECT_GT(reversed, 4);
    EXPECT_LT(reversed, gpu::kCheckPools - 4);

    for (int i = 0; i < gpu::kCheckEdges; ++i) {
        const glm::vec3 p0 = in.edges[i * 4], p1 = in.edges[i * 4 + 1], p2 = in.edges[i * 4 + 2], p3 = in.edges[i * 4 + 3];
        for (uint32_t m = 0; m < 4; ++m) {  // the fourth: distance on the pow2 curve
            const float cpu = gpu::adaptiveEdgeLevel(
                p0, p1, p2, p3, m == 3 ? gpu::kAdaptiveDistance : gpu::kAdaptiveDistance + m, in.params.z, in.eye, in.params.x, in.params.y,
                m == 3 ? gpu::kCurvePow2 : gpu::kCurveLinear, glm::vec2(in.exps), in.viewProj, in.viewport, in.params.w);
            EXPECT_NEAR(cpu, g[size_t(gpu::kOutAdaptive + i * 4 + int(m))], 1e-4f * std::max(1.0f, std::abs(cpu)))
                << "edge " << i << " mode " << m;
        }
        // The pow2 curve between its ends: 2^lerp(e0, e1, s), exactly the notes' formula.
        const float d = glm::distance(glm::vec3(in.eye), 0.5f * (p0 + p3));
        const float s = std::clamp((d - in.params.x) / (in.params.y - in.params.x), 0.0f, 1.0f);
        EXPECT_NEAR(g[size_t(gpu::kOutAdaptive + i * 4 + 3)], std::pow(2.0f, in.exps.x + (in.exps.y - in.exps.x) * s),
                    1e-4f * std::pow(2.0f, in.exps.x));
        const glm::uvec4 p = in.pools[i];
        const bool rev = gpu::edgeReversed(p.x, p.y, p.z, p.w);
        for (int j = 0; j < gpu::kCheckT; ++j) {
            const float t = float(j) / float(gpu::kCheckT - 1);
            const glm::vec3 cpu = gpu::canonicalBoundaryPoint(p0, p1, p2, p3, t, rev);
            const float* o = &g[size_t(gpu::kOutBoundary + (i * gpu::kCheckT + j) * 6)];
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(cpu[c], o[c], 1e-5f) << "edge " << i << " t " << t;
                uint32_t a, b;
                std::memcpy(&a, &o[c], 4);
                std::memcpy(&b, &o[3 + c], 4);
                EXPECT_EQ(a, b) << "the GPU's boundary point differs walked from the other end: edge " << i << " t " << t;
            }
        }
    }
}

}  // namespace
}  // namespace pw::test

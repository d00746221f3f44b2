// The Vulkan device: a 1.3 instance (optionally with VK_LAYER_KHRONOS_validation and a debug-utils
// messenger that counts every message), the chosen physical device (discrete GPU preferred, else
// any, e.g. lavapipe; `name` picks by substring), one graphics queue and a command pool.
// Missing devices or features raise pw::InputError (exit 2), never a crash.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "render/vk/vk_check.hpp"

namespace pw::render {
inline namespace vk {

struct DeviceOptions {
    std::string name;                             // substring of the device name; empty = best available
    bool validation = false;                      // also enabled by PATCHWORK_VALIDATION=1
    std::vector<const char*> instanceExtensions;  // e.g. surface extensions (editor)
    std::vector<const char*> deviceExtensions;    // e.g. VK_KHR_swapchain (editor)
};

// Optional features found on the device (required: tessellationShader, fillModeNonSolid, dynamicRendering).
struct DeviceCaps {
    bool geometryShader = false;
    bool pipelineStatistics = false;
    bool timestamps = false;
    bool wideLines = false;
    bool largePoints = false;
    bool storesAndAtomics = false;  // vertexPipelineStoresAndAtomics: culled-patch counter
    bool tessGeomPointSize = false;
    bool transformFeedback = false;  // VK_EXT_transform_feedback: export as displayed (render/surface_capture)
    float timestampPeriodNs = 1.0f;
    uint32_t maxTessLevel = 64;
    bool fixedPointTessellator = false;                        // Mesa's llvmpipe: places tessellated vertices as core/gpu/tess_place.h
    VkSampleCountFlagBits maxSamples = VK_SAMPLE_COUNT_1_BIT;  // colour and depth, at most 4
};

// True when PATCHWORK_VALIDATION is set to a non-empty value other than "0".
bool validationRequestedByEnv();

// The features and limits Patchwork needs that a device lacks, each preceded by a space ("" when
// none): tessellationShader, fillModeNonSolid, dynamicRendering, maxTessellationPatchSize>=16.
std::string missingRequiredFeatures(VkPhysicalDeviceFeatures features, const VkPhysicalDeviceVulkan13Features& f13,
                                    const VkPhysicalDeviceLimits& limits);

class Device {
public:
    explicit Device(const DeviceOptions& options);
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return queueFamily_; }
    VkCommandPool commandPool() const { return pool_; }
    const DeviceCaps& caps() const { return caps_; }
    // VK_EXT_transform_feedback's commands (null unless caps().transformFeedback).
    struct TransformFeedbackFns {
        PFN_vkCmdBindTransformFeedbackBuffersEXT bind = nullptr;
        PFN_vkCmdBeginTransformFeedbackEXT begin = nullptr;
        PFN_vkCmdEndTransformFeedbackEXT end = nullptr;
    };
    const TransformFeedbackFns& transformFeedback() const { return xfb_; }
    const VkPhysicalDeviceProperties& properties() const { return props_; }
    std::string name() const { return props_.deviceName; }
    // "llvmpipe Mesa 22.3.6": the driver's name and version as it reports them (Vulkan 1.2
    // driver properties), for stamping captures.
    std::string driverDescription() const;
    std::string apiVersionText() const;  // "1.3.255", the device's Vulkan version
    // Evaluation vertices per draw: kCpuDrawVertexBudget on CPU implementations (lavapipe), 0 =
    // unlimited on GPUs, where one draw per basis is fastest.
    uint32_t drawVertexBudget() const;
    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }

    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const;
    const VkPhysicalDeviceMemoryProperties& memoryProperties() const { return memProps_; }

    // Records with `record` into a one-time command buffer, submits and waits.
    template <class F>
    void submitAndWait(F&& record) {
        VkCommandBuffer cmd = beginOneTime();
        record(cmd);
        endOneTimeAndWait(cmd);
    }
    VkCommandBuffer beginOneTime();
    void endOneTimeAndWait(VkCommandBuffer cmd);

    // Validation messages (warnings and errors) seen by every Device of this process.
    static uint64_t validationMessageCount();
    static void resetValidationMessageCount();

    // Names of all Vulkan devices (for messages and `--device`).
    static std::vector<std::string> listDevices();

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties props_{};
    VkPhysicalDeviceMemoryProperties memProps_{};
    DeviceCaps caps_;
    TransformFeedbackFns xfb_;
};

}  // namespace vk
}  // namespace pw::render

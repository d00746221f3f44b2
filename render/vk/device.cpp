#include "render/vk/device.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include <sstream>
#include "core/tess/tess_levels.hpp"

#include "core/base/errors.hpp"

namespace pw::render {
inline namespace vk {

const char* vkResultName(VkResult r) {
    switch (r) {
        case VK_SUCCESS:
            return "VK_SUCCESS";
        case VK_NOT_READY:
            return "VK_NOT_READY";
        case VK_TIMEOUT:
            return "VK_TIMEOUT";
        case VK_ERROR_OUT_OF_HOST_MEMORY:
            return "VK_ERROR_OUT_OF_HOST_MEMORY";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY:
            return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
        case VK_ERROR_INITIALIZATION_FAILED:
            return "VK_ERROR_INITIALIZATION_FAILED";
        case VK_ERROR_DEVICE_LOST:
            return "VK_ERROR_DEVICE_LOST";
        case VK_ERROR_LAYER_NOT_PRESENT:
            return "VK_ERROR_LAYER_NOT_PRESENT";
        case VK_ERROR_EXTENSION_NOT_PRESENT:
            return "VK_ERROR_EXTENSION_NOT_PRESENT";
        case VK_ERROR_FEATURE_NOT_PRESENT:
            return "VK_ERROR_FEATURE_NOT_PRESENT";
        case VK_ERROR_INCOMPATIBLE_DRIVER:
            return "VK_ERROR_INCOMPATIBLE_DRIVER";
        default:
            return "VkResult error";
    }
}

void throwVkError(VkResult r, const char* call, const char* file, int line) {
    std::ostringstream os;
    os << file << ":" << line << ": " << call << " failed: " << vkResultName(r) << " (" << int(r) << ")";
    throw VulkanError(os.str());
}

namespace {

std::atomic<uint64_t> g_validationMessages{0};

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        ++g_validationMessages;
        std::cerr << "vulkan validation: " << (data && data->pMessage ? data->pMessage : "(no message)") << "\n";
    }
    return VK_FALSE;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

[[noreturn]] void deviceError(const std::string& what) { throw pw::InputError("vulkan", what); }

bool hasLayer(const char* name) {
    uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> layers(n);
    vkEnumerateInstanceLayerProperties(&n, layers.data());
    for (auto& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

bool hasDeviceExtension(VkPhysicalDevice d, const char* name) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(d, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> ext(n);
    vkEnumerateDeviceExtensionProperties(d, nullptr, &n, ext.data());
    for (auto& e : ext)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

int typeRank(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 3;
        default:
            return 4;
    }
}

VkInstance createInstance(bool validation, const std::vector<const char*>& extraExt, bool quiet) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "patchwork";
    app.pEngineName = "patchwork";
    app.apiVersion = VK_API_VERSION_1_3;
    std::vector<const char*> exts = extraExt;
    std::vector<const char*> layers;
    if (validation) {
        if (!hasLayer("VK_LAYER_KHRONOS_validation"))
            deviceError("validation requested but VK_LAYER_KHRONOS_validation is not installed (package vulkan-validationlayers)");
        layers.push_back("VK_LAYER_KHRONOS_validation");
        exts.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    ci.enabledLayerCount = uint32_t(layers.size());
    ci.ppEnabledLayerNames = layers.data();
    ci.enabledExtensionCount = uint32_t(exts.size());
    ci.ppEnabledExtensionNames = exts.data();
    VkInstance inst = VK_NULL_HANDLE;
    const VkResult r = vkCreateInstance(&ci, nullptr, &inst);
    if (r != VK_SUCCESS) {
        if (quiet) return VK_NULL_HANDLE;
        deviceError(std::string("cannot create a Vulkan 1.3 instance (") + vkResultName(r) +
                    "): is a Vulkan driver installed (e.g. mesa-vulkan-drivers)?");
    }
    return inst;
}

// The driver's identity (VkPhysicalDeviceDriverProperties, Vulkan 1.2): its ID, name and version text.
VkPhysicalDeviceDriverProperties driverProperties(VkPhysicalDevice physical) {
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    p2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(physical, &p2);
    return driver;
}

}  // namespace

std::string missingRequiredFeatures(VkPhysicalDeviceFeatures f, const VkPhysicalDeviceVulkan13Features& f13,
                                    const VkPhysicalDeviceLimits& limits) {
    // Test hook: PATCHWORK_PRETEND_MISSING=tessellationShader makes a capable device look like one
    // without it, so the refusal can be tested end to end on any machine.
    if (const char* p = std::getenv("PATCHWORK_PRETEND_MISSING"); p && std::strcmp(p, "tessellationShader") == 0)
        f.tessellationShader = VK_FALSE;
    std::string missing;
    if (!f.tessellationShader) missing += " tessellationShader";
    if (!f.fillModeNonSolid) missing += " fillModeNonSolid";
    if (!f13.dynamicRendering) missing += " dynamicRendering";
    if (limits.maxTessellationPatchSize < 16) missing += " maxTessellationPatchSize>=16";
    return missing;
}

bool validationRequestedByEnv() {
    const char* v = std::getenv("PATCHWORK_VALIDATION");
    return v && *v && std::strcmp(v, "0") != 0;
}

uint64_t Device::validationMessageCount() { return g_validationMessages.load(); }
void Device::resetValidationMessageCount() { g_validationMessages = 0; }

std::vector<std::string> Device::listDevices() {
    std::vector<std::string> names;
    VkInstance inst = createInstance(false, {}, true);
    if (!inst) return names;
    uint32_t n = 0;
    vkEnumeratePhysicalDevices(inst, &n, nullptr);
    std::vector<VkPhysicalDevice> devs(n);
    vkEnumeratePhysicalDevices(inst, &n, devs.data());
    for (auto d : devs) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(d, &p);
        names.emplace_back(p.deviceName);
    }
    vkDestroyInstance(inst, nullptr);
    return names;
}

Device::Device(const DeviceOptions& options) {
    const bool validation = options.validation || validationRequestedByEnv();
    instance_ = createInstance(validation, options.instanceExtensions, false);
    try {
        // Step 1: debug messenger (counts and prints every warning/error of the validation layer).
        if (validation) {
            auto create =
                reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
            VkDebugUtilsMessengerCreateInfoEXT mi{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
            mi.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
            mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                             VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
            mi.pfnUserCallback = debugCallback;
            if (!create) deviceError("validation requested but vkCreateDebugUtilsMessengerEXT is unavailable");
            VK_CHECK(create(instance_, &mi, nullptr, &messenger_));
        }

        // Step 2: choose the physical device.
        uint32_t n = 0;
        vkEnumeratePhysicalDevices(instance_, &n, nullptr);
        std::vector<VkPhysicalDevice> devs(n);
        vkEnumeratePhysicalDevices(instance_, &n, devs.data());
        if (devs.empty()) deviceError("no Vulkan device found (install a driver, e.g. mesa-vulkan-drivers for lavapipe)");
        std::vector<std::pair<int, VkPhysicalDevice>> candidates;
        std::string available;
        for (auto d : devs) {
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(d, &p);
            available += (available.empty() ? "" : ", ") + std::string("'") + p.deviceName + "'";
            if (!options.name.empty() && lower(p.deviceName).find(lower(options.name)) == std::string::npos) continue;
            if (p.apiVersion < VK_API_VERSION_1_3) continue;
            candidates.push_back({typeRank(p.deviceType), d});
        }
        if (candidates.empty()) {
            if (!options.name.empty())
                deviceError("no Vulkan 1.3 device matches --device '" + options.name + "' (available: " + available + ")");
            deviceError("no Vulkan 1.3 device found (available: " + available + ")");
        }
        std::stable_sort(candidates.begin(), candidates.end(), [](auto& a, auto& b) { return a.first < b.first; });
        physical_ = candidates.front().second;
        vkGetPhysicalDeviceProperties(physical_, &props_);
        vkGetPhysicalDeviceMemoryProperties(physical_, &memProps_);

        // Step 3: required and optional features.
        VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        f2.pNext = &f13;
        vkGetPhysicalDeviceFeatures2(physical_, &f2);
        const VkPhysicalDeviceFeatures& f = f2.features;
        std::string missing = missingRequiredFeatures(f, f13, props_.limits);
        if (!missing.empty())
            deviceError(std::string("device '") + props_.deviceName + "' lacks required features:" + missing +
                        " (Patchwork draws surfaces with the tessellation stages; use a device that has them, e.g. "
                        "lavapipe from mesa-vulkan-drivers)");

        caps_.geometryShader = f.geometryShader;
        caps_.pipelineStatistics = f.pipelineStatisticsQuery;
        caps_.wideLines = f.wideLines;
        caps_.largePoints = f.largePoints;
        caps_.storesAndAtomics = f.vertexPipelineStoresAndAtomics;
        caps_.tessGeomPointSize = f.shaderTessellationAndGeometryPointSize;
        caps_.timestampPeriodNs = props_.limits.timestampPeriod;
        caps_.maxTessLevel = props_.limits.maxTessellationGenerationLevel;
        caps_.fixedPointTessellator = driverProperties(physical_).driverID == VK_DRIVER_ID_MESA_LLVMPIPE;
        const VkSampleCountFlags both = props_.limits.framebufferColorSampleCounts & props_.limits.framebufferDepthSampleCounts;
        caps_.maxSamples = (both & VK_SAMPLE_COUNT_4_BIT)   ? VK_SAMPLE_COUNT_4_BIT
                           : (both & VK_SAMPLE_COUNT_2_BIT) ? VK_SAMPLE_COUNT_2_BIT
                                                            : VK_SAMPLE_COUNT_1_BIT;

        // Step 4: a graphics queue.
        uint32_t qn = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qn, nullptr);
        std::vector<VkQueueFamilyProperties> qf(qn);
        vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qn, qf.data());
        bool found = false;
        for (uint32_t i = 0; i < qn; ++i)
            if (qf[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
                queueFamily_ = i;
                found = true;
                caps_.timestamps = qf[i].timestampValidBits > 0 && props_.limits.timestampComputeAndGraphics;
                break;
            }
        if (!found) deviceError(std::string("device '") + props_.deviceName + "' has no graphics queue");

        // Step 5: the logical device with the features we use.
        VkPhysicalDeviceFeatures enable{};
        enable.tessellationShader = VK_TRUE;
        enable.fillModeNonSolid = VK_TRUE;
        // Optional features: enabled where present, reported in caps_ above.
        for (VkBool32 VkPhysicalDeviceFeatures::*m :
             {&VkPhysicalDeviceFeatures::geometryShader, &VkPhysicalDeviceFeatures::pipelineStatisticsQuery,
              &VkPhysicalDeviceFeatures::wideLines, &VkPhysicalDeviceFeatures::largePoints,
              &VkPhysicalDeviceFeatures::vertexPipelineStoresAndAtomics, &VkPhysicalDeviceFeatures::shaderTessellationAndGeometryPointSize,
              &VkPhysicalDeviceFeatures::depthBiasClamp})
            enable.*m = f.*m;
        VkPhysicalDeviceVulkan13Features e13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        e13.dynamicRendering = VK_TRUE;
        e13.maintenance4 = f13.maintenance4;  // relaxed interface matching (point-mode TES -> normals GS)
        // Transform feedback (optional): the tessellator's triangles read back for export.
        std::vector<const char*> extensions = options.deviceExtensions;
        VkPhysicalDeviceTransformFeedbackFeaturesEXT exfb{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT};
        if (hasDeviceExtension(physical_, VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME)) {
            VkPhysicalDeviceTransformFeedbackFeaturesEXT fx{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT};
            VkPhysicalDeviceFeatures2 q{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
            q.pNext = &fx;
            vkGetPhysicalDeviceFeatures2(physical_, &q);
            if (fx.transformFeedback) {
                exfb.transformFeedback = VK_TRUE;
                e13.pNext = &exfb;
                extensions.push_back(VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME);
                caps_.transformFeedback = true;
            }
        }
        VkPhysicalDeviceFeatures2 e2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        e2.features = enable;
        e2.pNext = &e13;
        const float prio = 1.0f;
        VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        qci.queueFamilyIndex = queueFamily_;
        qci.queueCount = 1;
        qci.pQueuePriorities = &prio;
        VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        dci.pNext = &e2;
        dci.queueCreateInfoCount = 1;
        dci.pQueueCreateInfos = &qci;
        dci.enabledExtensionCount = uint32_t(extensions.size());
        dci.ppEnabledExtensionNames = extensions.data();
        VK_CHECK(vkCreateDevice(physical_, &dci, nullptr, &device_));
        vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
        if (caps_.transformFeedback) {
            xfb_.bind = reinterpret_cast<PFN_vkCmdBindTransformFeedbackBuffersEXT>(
                vkGetDeviceProcAddr(device_, "vkCmdBindTransformFeedbackBuffersEXT"));
            xfb_.begin =
                reinterpret_cast<PFN_vkCmdBeginTransformFeedbackEXT>(vkGetDeviceProcAddr(device_, "vkCmdBeginTransformFeedbackEXT"));
            xfb_.end = reinterpret_cast<PFN_vkCmdEndTransformFeedbackEXT>(vkGetDeviceProcAddr(device_, "vkCmdEndTransformFeedbackEXT"));
            caps_.transformFeedback = xfb_.bind && xfb_.begin && xfb_.end;
        }

        VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pci.queueFamilyIndex = queueFamily_;
        VK_CHECK(vkCreateCommandPool(device_, &pci, nullptr, &pool_));
        VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(device_, &fci, nullptr, &fence_));
    } catch (...) {
        this->~Device();
        throw;
    }
}

Device::~Device() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        if (fence_) vkDestroyFence(device_, fence_, nullptr);
        if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
        vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
    }
    if (messenger_) {
        auto destroy =
            reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance_, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance_) {
        vkDestroyInstance(instance_, nullptr);
        instance_ = VK_NULL_HANDLE;
    }
}

uint32_t Device::drawVertexBudget() const { return props_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? kCpuDrawVertexBudget : 0u; }

uint32_t Device::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const {
    for (uint32_t i = 0; i < memProps_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memProps_.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw VulkanError("no suitable Vulkan memory type");
}

VkCommandBuffer Device::beginOneTime() {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd;
    VK_CHECK(vkAllocateCommandBuffers(device_, &ai, &cmd));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    return cmd;
}

void Device::endOneTimeAndWait(VkCommandBuffer cmd) {
    VK_CHECK(vkEndCommandBuffer(cmd));
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    VK_CHECK(vkResetFences(device_, 1, &fence_));
    VK_CHECK(vkQueueSubmit(queue_, 1, &si, fence_));
    VK_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
    vkFreeCommandBuffers(device_, pool_, 1, &cmd);
}

std::string Device::driverDescription() const {
    const VkPhysicalDeviceDriverProperties driver = driverProperties(physical_);
    std::string s = driver.driverName;
    if (driver.driverInfo[0] != 0) s += std::string(s.empty() ? "" : " ") + driver.driverInfo;
    return s;
}

std::string Device::apiVersionText() const {
    const uint32_t v = props_.apiVersion;
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
           std::to_string(VK_API_VERSION_PATCH(v));
}

}  // namespace vk
}  // namespace pw::render

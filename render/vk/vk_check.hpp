// VK_CHECK: throws pw::render::VulkanError naming the call, file and line when a Vulkan call fails.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace pw::render {
inline namespace vk {

class VulkanError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

const char* vkResultName(VkResult r);

[[noreturn]] void throwVkError(VkResult r, const char* call, const char* file, int line);

}  // namespace vk
}  // namespace pw::render

#define VK_CHECK(call)                                                                                         \
    do {                                                                                                       \
        const VkResult pw_vk_result_ = (call);                                                                 \
        if (pw_vk_result_ != VK_SUCCESS) ::pw::render::throwVkError(pw_vk_result_, #call, __FILE__, __LINE__); \
    } while (0)

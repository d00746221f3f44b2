#include "ui/platform/imgui_layer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include "core/base/embedded_data.hpp"
#include "render/vk/device.hpp"
#include "ui/platform/swapchain_target.hpp"

namespace pw::ui {
inline namespace platform {

namespace {
void checkVk(VkResult r) {
    if (r != VK_SUCCESS) std::fprintf(stderr, "patchwork: imgui vulkan backend: VkResult %d\n", int(r));
}
}  // namespace

ImGuiLayer::ImGuiLayer(render::Device& dev, GLFWwindow* window, SwapchainTarget& target, float contentScale) : dev_(dev), target_(target) {
    // Step 1: context, style and a font scaled for the monitor's content scale (HiDPI).
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // layout is fixed by the editor
    ImGui::StyleColorsDark();
    const float scale = contentScale > 0.5f ? contentScale : 1.0f;
    ImGui::GetStyle().ScaleAllSizes(scale);
    ImFontConfig cfg;
    cfg.SizePixels = 13.0f * scale;
    io.Fonts->AddFontDefault(&cfg);
    // The arrow of the domain labels (4.5 → 5) is not in the default font: merge it from DejaVu.
    static const ImWchar arrow[] = {0x2192, 0x2192, 0};
    ImFontConfig merge;
    merge.MergeMode = true;
    merge.FontDataOwnedByAtlas = false;
    io.Fonts->AddFontFromMemoryTTF(const_cast<char*>(embedded::uiFontTtf.data()), int(embedded::uiFontTtf.size()), 13.0f * scale, &merge,
                                   arrow);
    // Presentation mode's large text: the embedded DejaVu Sans at 3x, drawn scaled 0.5-1x (1.5-3x
    // the UI size) so it stays sharp.
    // Latin-1 and the labels' arrow.
    static const ImWchar bigRanges[] = {0x0020, 0x00FF, 0x2192, 0x2192, 0};
    ImFontConfig big;
    big.FontDataOwnedByAtlas = false;
    presentationFont_ = io.Fonts->AddFontFromMemoryTTF(const_cast<char*>(embedded::uiFontTtf.data()), int(embedded::uiFontTtf.size()),
                                                       39.0f * scale, &big, bigRanges);

    // Step 2: descriptor pool for the font texture (and nothing else).
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
    VkDescriptorPoolCreateInfo dp{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dp.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    dp.maxSets = 8;
    dp.poolSizeCount = 1;
    dp.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(dev.device(), &dp, nullptr, pool_.replace(dev.device())));

    // Step 3: backends.
    ImGui_ImplGlfw_InitForVulkan(window, true);
    ImGui_ImplVulkan_InitInfo ii{};
    ii.Instance = dev.instance();
    ii.PhysicalDevice = dev.physical();
    ii.Device = dev.device();
    ii.QueueFamily = dev.queueFamily();
    ii.Queue = dev.queue();
    ii.DescriptorPool = pool_;
    ii.Subpass = 0;
    ii.MinImageCount = target.minImageCount();
    ii.ImageCount = target.imageCount() < target.minImageCount() ? target.minImageCount() : target.imageCount();
    ii.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    ii.CheckVkResultFn = checkVk;
    ImGui_ImplVulkan_Init(&ii, target.overlayRenderPass());

    // Step 4: font texture upload (1.86: with a caller's command buffer).
    dev.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();

    cmd_ = render::OwnedCommandBuffer(dev.device(), dev.commandPool());
}

ImGuiLayer::~ImGuiLayer() {
    vkDeviceWaitIdle(dev_.device());
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();  // then the command buffer and the descriptor pool free themselves
}

void ImGuiLayer::newFrame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

VkCommandBuffer ImGuiLayer::record(std::span<const std::array<float, 4>> fills, const std::array<float, 4>& color) {
    VK_CHECK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd_, &bi));
    VkRenderPassBeginInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    rp.renderPass = target_.overlayRenderPass();
    rp.framebuffer = target_.overlayFramebuffer();
    rp.renderArea = {{0, 0}, target_.extent()};
    vkCmdBeginRenderPass(cmd_, &rp, VK_SUBPASS_CONTENTS_INLINE);
    // Opaque backgrounds as one clear each: a fill without texture or blending.
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    const VkExtent2D ext = target_.extent();
    std::vector<VkClearRect> rects;
    for (const auto& f : fills) {
        const int x0 = std::clamp(int(std::floor(f[0] * scale.x)), 0, int(ext.width));
        const int y0 = std::clamp(int(std::floor(f[1] * scale.y)), 0, int(ext.height));
        const int x1 = std::clamp(int(std::ceil((f[0] + f[2]) * scale.x)), x0, int(ext.width));
        const int y1 = std::clamp(int(std::ceil((f[1] + f[3]) * scale.y)), y0, int(ext.height));
        if (x1 > x0 && y1 > y0) rects.push_back({{{x0, y0}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}}, 0, 1});
    }
    if (!rects.empty()) {
        VkClearAttachment clear{VK_IMAGE_ASPECT_COLOR_BIT, 0, {}};
        clear.clearValue.color = {{color[0], color[1], color[2], color[3]}};
        vkCmdClearAttachments(cmd_, 1, &clear, uint32_t(rects.size()), rects.data());
    }
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd_);
    vkCmdEndRenderPass(cmd_);
    VK_CHECK(vkEndCommandBuffer(cmd_));
    return cmd_;
}

void ImGuiLayer::swapchainRecreated() { ImGui_ImplVulkan_SetMinImageCount(target_.minImageCount()); }

}  // namespace platform
}  // namespace pw::ui

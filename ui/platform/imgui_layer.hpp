// Dear ImGui 1.86 on the editor window: GLFW platform backend + Vulkan renderer backend drawing in
// the swapchain target's overlay render pass, HiDPI-scaled font and style.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <span>

#include "render/vk/vk_owned.hpp"

struct ImFont;

struct GLFWwindow;

namespace pw::render {
inline namespace vk {
class Device;
}  // namespace vk
}  // namespace pw::render

namespace pw::ui {
inline namespace platform {

class SwapchainTarget;  // ui/platform/swapchain_target.hpp

class ImGuiLayer {
public:
    // Call after the window's own GLFW callbacks are installed (the backend chains to them).
    ImGuiLayer(render::Device& dev, GLFWwindow* window, SwapchainTarget& target, float contentScale);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void newFrame();
    // Records the overlay pass: first `fills` (x, y, width, height in window pixels) cleared to the
    // opaque `color`, then the ImGui draw data from ImGui::Render().
    VkCommandBuffer record(std::span<const std::array<float, 4>> fills, const std::array<float, 4>& color);
    void swapchainRecreated();
    // DejaVu Sans at three times the UI size (presentation mode).
    ImFont* presentationFont() const { return presentationFont_; }

private:
    render::Device& dev_;
    SwapchainTarget& target_;
    render::OwnedDescriptorPool pool_;
    render::OwnedCommandBuffer cmd_;
    ImFont* presentationFont_ = nullptr;
};

}  // namespace platform
}  // namespace pw::ui

// The domain view (DESIGN §3): the parametric domain (quad, triangle or isoline) tessellated by the
// GPU's fixed tessellator with the given levels and partitioning. An evaluation shader outputs the
// tessellation coordinate as the position, so the picture is exactly the pattern the hardware made;
// pipeline statistics count its vertices (evaluation invocations) and primitives.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <string>
#include <vector>

#include "core/tess/tess_domain.hpp"
#include "core/tess/tess_pattern.hpp"
#include "render/targets/render_target.hpp"
#include "render/vk/device.hpp"
#include "render/vk/pipeline_builder.hpp"
#include "render/vk/vk_owned.hpp"

namespace pw::gpu {
struct DomainPush;
}

namespace pw::render {
inline namespace domain {

// The pattern one pane shows: a domain, its levels and partitioning.
struct DomainPane {
    DomainKind kind = DomainKind::Quad;
    DomainLevels levels;
    Spacing spacing = Spacing::Equal;
    // The D3D notes' and Vulkan's default (VK_TESSELLATION_DOMAIN_ORIGIN_UPPER_LEFT) picture: v
    // grows downwards, so the edge v = 0 (outer[1], SV_TessFactor[1]) is on top, and every edge is
    // tagged with its index. Off: GL's lower-left origin, v up. Triangles are drawn the same way
    // either way (tagged when on).
    bool upperLeft = false;
    bool operator==(const DomainPane&) const = default;
};

// The pane's levels in the push constants the domain shaders read: outer, inner and the pow2 flag
// (drawn panes and captured ones alike).
void setDomainLevels(gpu::DomainPush& push, const DomainPane& pane);

struct DomainViewOptions : DomainPane {
    // Where the domain goes, in target pixels (x, y, width, height); the domain keeps its aspect and
    // is centred with `margin` pixels free on every side (for labels).
    std::array<float, 4> rect{0, 0, 0, 0};
    float margin = 40.0f;
    bool clearRect = true;  // clear the rectangle to `background` first
    std::array<float, 4> background{0.97f, 0.97f, 0.95f, 1.0f};
    std::array<float, 4> fillColor{0.80f, 0.87f, 0.97f, 1.0f};
    std::array<float, 4> lineColor{0.10f, 0.14f, 0.22f, 1.0f};
    std::array<float, 4> pointColor{0.85f, 0.20f, 0.12f, 1.0f};
    float pointSize = 5.0f;  // pixels, where the device can size points from the evaluation stage
    std::string device;      // figures: the device that drew the pattern, named in the title
    std::string title;       // the pane's title; empty: "quad domain" (panes that compare partitionings: the partitioning)
    std::string countsNote;  // figures: words after the counts ("12 differ")
};

struct DomainStats {
    bool valid = false;       // pipeline statistics available
    uint64_t vertices = 0;    // tessellation evaluation invocations
    uint64_t primitives = 0;  // primitives reaching the clipper (triangles, or line segments)
};

// Where the domain's corners land: the square (quad, isoline) or equilateral triangle fitted into
// the options' rectangle. Domain coordinates (x right, y up, [0,1]^2) map to target pixels as
// px = origin + (x * size, -y * size).
struct DomainPlacement {
    float originX = 0, originY = 0;  // pixel position of domain (0, 0) as drawn with y up
    float size = 0;                  // pixels per domain unit
    bool flipY = false;              // the upper-left origin: y = 0 on top
    std::array<float, 2> toPixels(float x, float y) const { return {originX + x * size, originY - (flipY ? 1.0f - y : y) * size}; }
};
DomainPlacement placeDomain(const DomainViewOptions& o);

class DomainView {
public:
    // Pipelines for rendering into attachments of these formats and sample count.
    DomainView(Device& dev, VkFormat color, VkFormat depth, VkSampleCountFlagBits samples);
    ~DomainView();
    DomainView(const DomainView&) = delete;
    DomainView& operator=(const DomainView&) = delete;

    // Draws the domain into `target` (submit and wait). With `clearTarget` the whole target is
    // cleared first (beginRendering); otherwise what it holds stays (resumeRendering) and only the
    // rectangle is cleared. Statistics cover the fill pass (triangles, or the lines of isolines).
    DomainStats draw(RenderTarget& target, const DomainViewOptions& o, bool clearTarget);
    // Several panes in one submission (comparison views), each with its own statistics.
    std::vector<DomainStats> draw(RenderTarget& target, const std::vector<DomainViewOptions>& panes, bool clearTarget);

    bool pointsSupported() const { return pointsSupported_; }
    std::string deviceName() const { return dev_.name(); }

    // The pane's pattern read back through transform feedback (render/domain/domain_capture.cpp): what
    // vector figures draw and `patchwork capture` stores. Throws InputError on a device without
    // VK_EXT_transform_feedback.
    TessPattern capture(const DomainPane& pane);

private:
    VkPipeline pipeline(DomainKind kind, Spacing spacing, int pass) const;  // pass 0 fill, 1 lines, 2 points
    VkPipeline capturePipeline(DomainKind kind, Spacing spacing);           // built on first use
    void recordPass(VkCommandBuffer cmd, const DomainViewOptions& o, int pass, const DomainPlacement& at, const std::array<float, 4>& color,
                    VkExtent2D extent) const;

    Device& dev_;
    OwnedPipelineLayout layout_;
    std::vector<OwnedShaderModule> modules_;  // what pipes_ are made from, when first drawn
    // [domain][spacing][pass], made when first drawn (the editor draws one domain, one partitioning)
    std::array<std::array<std::array<LazyPipeline, 3>, 3>, 3> pipes_;
    std::array<std::array<OwnedPipeline, 3>, 3> capturePipes_;  // [domain][spacing]
    VkFormat color_, depth_;
    VkSampleCountFlagBits samples_;
    bool pointsSupported_ = false;
};

// Counts for many level sets in one submission (tests): each set is a pane of a small offscreen
// target, measured with its own pipeline-statistics query.
std::vector<DomainStats> countDomain(Device& dev, DomainKind kind, Spacing spacing, const std::vector<DomainLevels>& levels);

}  // namespace domain
}  // namespace pw::render

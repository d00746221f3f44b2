#include "render/domain/domain_view.hpp"

#include <algorithm>
#include <cmath>

#include "core/gpu/domain_interface.h"
#include "render/scene/shader_variants.hpp"
#include "render/targets/offscreen_target.hpp"
#include "render/vk/pipeline_builder.hpp"
#include "shaders/spirv.hpp"

namespace pw::render {
inline namespace domain {

namespace {

constexpr float kTriangleHeight = 0.8660254f;  // sqrt(3)/2: the equilateral triangle's height

// Results come in the order of the flag bits: clipping invocations, then evaluation invocations.
constexpr VkQueryPipelineStatisticFlags kDomainStatFlags =
    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT | VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT;

VkQueryPool makeStatsPool(Device& dev, uint32_t count) {
    if (!dev.caps().pipelineStatistics) return VK_NULL_HANDLE;
    VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    ci.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    ci.queryCount = count;
    ci.pipelineStatistics = kDomainStatFlags;
    VkQueryPool pool;
    VK_CHECK(vkCreateQueryPool(dev.device(), &ci, nullptr, &pool));
    return pool;
}

std::vector<DomainStats> readStats(Device& dev, VkQueryPool pool, uint32_t count) {
    std::vector<DomainStats> out(count);
    if (!pool) return out;
    std::vector<uint64_t> r(size_t(count) * 2);
    if (vkGetQueryPoolResults(dev.device(), pool, 0, count, r.size() * sizeof(uint64_t), r.data(), 2 * sizeof(uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) != VK_SUCCESS)
        return out;
    for (uint32_t i = 0; i < count; ++i) out[i] = {true, r[2 * i + 1], r[2 * i]};
    return out;
}

}  // namespace

void setDomainLevels(gpu::DomainPush& push, const DomainPane& pane) {
    for (int e = 0; e < 4; ++e) push.outer[e] = pane.levels.outer[size_t(e)];
    push.inner = {pane.levels.inner[0], pane.levels.inner[1], pane.spacing == Spacing::Pow2 ? 1.0f : 0.0f, 0.0f};
}

DomainPlacement placeDomain(const DomainViewOptions& o) {
    const float w = std::max(1.0f, o.rect[2] - 2.0f * o.margin), h = std::max(1.0f, o.rect[3] - 2.0f * o.margin);
    const float domainH = o.kind == DomainKind::Triangle ? kTriangleHeight : 1.0f;
    DomainPlacement p;
    p.size = std::max(1.0f, std::min(w, h / domainH));
    p.originX = o.rect[0] + 0.5f * (o.rect[2] - p.size);
    p.originY = o.rect[1] + 0.5f * (o.rect[3] + domainH * p.size);
    p.flipY = o.upperLeft && o.kind != DomainKind::Triangle;
    return p;
}

DomainView::DomainView(Device& dev, VkFormat color, VkFormat depth, VkSampleCountFlagBits samples)
    : dev_(dev), color_(color), depth_(depth), samples_(samples) {
    VkPushConstantRange pr{VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(gpu::DomainPush)};
    VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pl.pushConstantRangeCount = 1;
    pl.pPushConstantRanges = &pr;
    VK_CHECK(vkCreatePipelineLayout(dev.device(), &pl, nullptr, layout_.replace(dev.device())));

    pointsSupported_ = dev.caps().tessGeomPointSize;
    auto mod = [&](const spirv::Blob& b) { return modules_.emplace_back(dev.device(), makeModule(dev, b)).get(); };
    const auto lazy = [&](const PipelineDesc& pd) {
        return LazyPipeline(dev.device(), [&dev, layout = layout_.get(), pd, color, depth, samples] {
            return buildPipeline(dev, layout, VK_NULL_HANDLE, pd, color, depth, samples);
        });
    };
    const VkShaderModule vert = mod(spirv::domain_vert()), tesc = mod(spirv::domain_tesc()), frag = mod(spirv::line_frag());
    for (int d = 0; d < 3; ++d)
        for (int s = 0; s < 3; ++s) {
            PipelineDesc pd;
            pd.tess = true;
            pd.patchControlPoints = 1;
            pd.vertexLayout = -1;
            pd.depthTest = pd.depthWrite = false;
            pd.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert},
                         {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tesc},
                         {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, mod(spirv::domain_tese(size_t(d), size_t(s), 0))},
                         {VK_SHADER_STAGE_FRAGMENT_BIT, frag}};
            pipes_[size_t(d)][size_t(s)][0] = lazy(pd);
            if (d != int(DomainKind::Isoline)) {  // isolines are lines already
                pd.polygon = VK_POLYGON_MODE_LINE;
                pipes_[size_t(d)][size_t(s)][1] = lazy(pd);
            }
            if (pointsSupported_) {
                pd.polygon = VK_POLYGON_MODE_FILL;
                pd.stages[2].second = mod(spirv::domain_tese(size_t(d), size_t(s), spirv::domain_tese_output_points));
                pipes_[size_t(d)][size_t(s)][2] = lazy(pd);
            }
        }
}

DomainView::~DomainView() = default;

VkPipeline DomainView::pipeline(DomainKind kind, Spacing spacing, int pass) const {
    return pipes_[size_t(kind)][size_t(spacingVariant(spacing))][size_t(pass)];
}

void DomainView::recordPass(VkCommandBuffer cmd, const DomainViewOptions& o, int pass, const DomainPlacement& at,
                            const std::array<float, 4>& color, VkExtent2D extent) const {
    VkPipeline p = pipeline(o.kind, o.spacing, pass);
    if (!p) return;
    // Domain (x, y) -> pixels (originX + x size, originY - y size) -> clip ([-1, 1], y down).
    const float sx = 2.0f / float(extent.width), sy = 2.0f / float(extent.height);
    gpu::DomainPush push{};
    setDomainLevels(push, o);
    // The upper-left origin draws v downwards: pixels (originX + x size, originY - size + y size).
    push.transform = at.flipY ? glm::vec4(at.size * sx, at.size * sy, at.originX * sx - 1.0f, (at.originY - at.size) * sy - 1.0f)
                              : glm::vec4(at.size * sx, -at.size * sy, at.originX * sx - 1.0f, at.originY * sy - 1.0f);
    push.color = {color[0], color[1], color[2], color[3]};
    push.point = {o.pointSize, 0, 0, 0};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof push, &push);
    vkCmdDraw(cmd, 1, 1, 0, 0);
}

DomainStats DomainView::draw(RenderTarget& target, const DomainViewOptions& o, bool clearTarget) {
    return draw(target, std::vector<DomainViewOptions>{o}, clearTarget)[0];
}

std::vector<DomainStats> DomainView::draw(RenderTarget& target, const std::vector<DomainViewOptions>& panes, bool clearTarget) {
    const VkExtent2D ext = target.extent();
    const uint32_t n = uint32_t(panes.size());
    if (n == 0) return {};
    const OwnedQueryPool pool(dev_.device(), makeStatsPool(dev_, n));
    // Viewport the whole target; scissor the pane's rectangle, so nothing lands outside it.
    const auto viewportAndScissor = [&](VkCommandBuffer cmd, const DomainViewOptions& o) {
        const VkViewport vp{0, 0, float(ext.width), float(ext.height), 0, 1};
        vkCmdSetViewport(cmd, 0, 1, &vp);
        const int x0 = std::clamp(int(std::floor(o.rect[0])), 0, int(ext.width)),
                  y0 = std::clamp(int(std::floor(o.rect[1])), 0, int(ext.height));
        const int x1 = std::clamp(int(std::ceil(o.rect[0] + o.rect[2])), x0, int(ext.width));
        const int y1 = std::clamp(int(std::ceil(o.rect[1] + o.rect[3])), y0, int(ext.height));
        const VkRect2D sc{{x0, y0}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}};
        vkCmdSetScissor(cmd, 0, 1, &sc);
        return sc;
    };
    dev_.submitAndWait([&](VkCommandBuffer cmd) {
        if (pool) vkCmdResetQueryPool(cmd, pool, 0, n);
        for (uint32_t i = 0; i < n; ++i) {
            const DomainViewOptions& o = panes[i];
            const DomainPlacement at = placeDomain(o);
            // The statistics query of each fill pass sits outside rendering (render/vk/stats.hpp: lavapipe).
            if (pool) vkCmdBeginQuery(cmd, pool, i, 0);
            if (i == 0 && clearTarget)
                target.beginRendering(cmd, o.background);
            else
                target.resumeRendering(cmd);
            const VkRect2D sc = viewportAndScissor(cmd, o);
            const bool visible = sc.extent.width > 0 && sc.extent.height > 0;
            if (o.clearRect && !(i == 0 && clearTarget) && visible) {
                VkClearAttachment ca{VK_IMAGE_ASPECT_COLOR_BIT, 0, {}};
                ca.clearValue.color = {{o.background[0], o.background[1], o.background[2], o.background[3]}};
                const VkClearRect cr{sc, 0, 1};
                vkCmdClearAttachments(cmd, 1, &ca, 1, &cr);
            }
            if (visible) recordPass(cmd, o, 0, at, o.kind == DomainKind::Isoline ? o.lineColor : o.fillColor, ext);
            target.pauseRendering(cmd);
            if (pool) vkCmdEndQuery(cmd, pool, i);
            target.resumeRendering(cmd);
            viewportAndScissor(cmd, o);
            if (visible) {
                recordPass(cmd, o, 1, at, o.lineColor, ext);
                recordPass(cmd, o, 2, at, o.pointColor, ext);
            }
            if (i + 1 < n) target.pauseRendering(cmd);
        }
        target.endRendering(cmd);
    });
    std::vector<DomainStats> s = readStats(dev_, pool, n);
    return s;
}

std::vector<DomainStats> countDomain(Device& dev, DomainKind kind, Spacing spacing, const std::vector<DomainLevels>& levels) {
    if (levels.empty()) return {};
    // Each level set is a pane covering the whole small target; draw() measures each pane's fill.
    OffscreenTarget target(dev, 64, 64, false);
    target.setReadback(false);
    DomainView view(dev, target.colorFormat(), target.depthFormat(), target.samples());
    std::vector<DomainViewOptions> panes(levels.size());
    for (size_t i = 0; i < levels.size(); ++i) {
        panes[i].kind = kind;
        panes[i].spacing = spacing;
        panes[i].levels = levels[i];
        panes[i].rect = {0, 0, 64, 64};
        panes[i].margin = 2;
    }
    return view.draw(target, panes, true);
}

}  // namespace domain
}  // namespace pw::render

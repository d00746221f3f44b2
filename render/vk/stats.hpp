// Per-frame statistics: GPU time (timestamp queries), pipeline statistics of the surface pass
// (tessellation evaluation invocations, clipping invocations/primitives), patches culled (atomic
// counter written by the control shader), draws and wall-clock times.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "render/vk/device.hpp"
#include "render/vk/vk_owned.hpp"

namespace pw::render {
inline namespace vk {

struct FrameStats {
    double wallMs = 0.0;    // record + submit + wait
    double submitMs = 0.0;  // submit + wait
    double gpuMs = -1.0;    // timestamps; -1 when unsupported
    bool pipelineStatsValid = false;
    uint64_t inputPrimitives = 0;      // patches (or plain triangles) fed to the surface pass
    uint64_t vsInvocations = 0;        // vertex shader invocations (one per control point fed)
    uint64_t tcsPatches = 0;           // control shader patches
    uint64_t tesInvocations = 0;       // evaluation shader invocations
    uint64_t clippingInvocations = 0;  // triangles reaching the clipper = triangles drawn
    uint64_t clippingPrimitives = 0;   // primitives leaving the clipper
    uint32_t patchesCulled = 0;
    uint32_t displacedEdges = 0;     // window edges whose level the height map's detail raised (adaptive)
    uint32_t displacementLevel = 0;  // the largest of those levels
    uint32_t patches = 0;
    uint32_t mergedWindows = 0, mergedBlocks = 0;  // windows drawn B x B as one patch, and those patches
    uint32_t draws = 0;
    // Off-screen culling was on but the whole scene lay inside the frustum, so no patch could be
    // culled and the control shader without the per-patch test drew the frame.
    bool cullTestSkipped = false;
    uint64_t triangles() const { return clippingInvocations; }
};

nlohmann::json statsJson(const FrameStats& s);
std::string statsToJson(const FrameStats& s, int indent = 2);  // statsJson, dumped

class FrameQueries {
public:
    explicit FrameQueries(Device& dev);
    ~FrameQueries();
    FrameQueries(const FrameQueries&) = delete;
    FrameQueries& operator=(const FrameQueries&) = delete;

    void reset(VkCommandBuffer cmd);  // outside rendering
    void timestampBegin(VkCommandBuffer cmd);
    void timestampEnd(VkCommandBuffer cmd);
    // Around the surface pass, outside dynamic rendering (lavapipe 22.3 crashes on pipeline
    // statistics queries begun inside a rendering instance).
    void statsBegin(VkCommandBuffer cmd);
    void statsEnd(VkCommandBuffer cmd);
    void read(FrameStats& out);  // after the frame completed

private:
    Device& dev_;
    OwnedQueryPool ts_, stats_;
};

// Transform-feedback stream queries (the exports' and vector figures' captures): `count` of them
// created, and one read as {primitives written, primitives the draw needed} (waits for the result).
OwnedQueryPool makeTransformFeedbackQuery(Device& dev, uint32_t count = 1);
std::array<uint64_t, 2> readTransformFeedbackQuery(Device& dev, VkQueryPool pool, uint32_t index = 0);

}  // namespace vk
}  // namespace pw::render

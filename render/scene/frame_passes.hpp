// A frame of Renderer::render, pass by pass: the surface pass (inside the pipeline-statistics
// query, so the counts are the surface's), then the overlays in drawing order, each a row of
// FramePasses::overlays() with the test that says whether this frame wants it. A new overlay is
// one function in frame_passes.cpp and one row in that table; render() itself does not change.
#pragma once

#include <span>

#include "core/gpu/gpu_interface.h"
#include "render/scene/renderer_impl.hpp"

namespace pw::render {
inline namespace scene {

class FramePasses {
public:
    // What every pass reads, and the statistics they add to.
    struct Frame {
        VkCommandBuffer cmd;
        Device& dev;
        const RenderOptions& opt;
        const Renderer::FramePlan& plan;
        Renderer::Impl& m;
        const PipelineSet& pipes;
        const SurfacePipelines& fam;  // plain or displaced
        VaryingsVariant varyings;
        FrameStats& stats;
        gpu::DrawPush push{};  // the surface pass's push constants, which the untinted overlays reuse
    };
    struct Pass {
        const char* name;
        bool (*wanted)(const Frame&);
        void (*record)(Frame&);
    };
    static void surface(Frame& f);            // the windows and triangles, or the plain mesh
    static std::span<const Pass> overlays();  // after the surface, in drawing order
};

}  // namespace scene
}  // namespace pw::render

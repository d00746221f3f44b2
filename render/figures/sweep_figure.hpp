// The frames of a level sweep, shared by `patchwork sweep` and the editor's sweep export: a domain
// figure (1-4 panes) or the model (one view, or panes with their own partitioning, wireframe on so
// vertices popping and sliding show), each frame captioned with its level (and the model's
// partitioning and triangle count), rendered offscreen and handed to a sink in order.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/model/document.hpp"
#include "render/domain/domain_view.hpp"
#include "render/figures/model_figure.hpp"
#include "render/scene/renderer.hpp"
#include "render/vk/device.hpp"

namespace pw::render {
inline namespace figures {

struct SweepSpec {
    uint32_t width = 1280, height = 720;
    float from = 1.0f, to = 16.0f;
    int frames = 31;
    bool msaa = true;
    std::vector<DomainPane> domainPanes;         // non-empty: a domain sweep (the document is not drawn)
    const Document* document = nullptr;          // a model sweep: the document, with these options
    std::shared_ptr<const HeightMap> heightMap;  // the document's height map (its displacement), or none
    RenderOptions options;                       // (their levels are replaced frame by frame)
    std::vector<ModelPane> modelPanes;           // 2 or 4: the model side by side per partitioning
};

// The level of frame k (from .. to in equal steps).
float sweepLevel(const SweepSpec& s, int k);

// Renders every frame (width x height RGBA8) and calls `frame(k, rgba)` for each.
void renderSweep(Device& dev, const SweepSpec& s, const std::function<void(int, const std::vector<uint8_t>&)>& frame);

}  // namespace figures
}  // namespace pw::render

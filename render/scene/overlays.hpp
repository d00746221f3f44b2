// Overlay geometry: the control grid (deduplicated net lines over the pool; points drawn straight
// from the pool with hover/selection highlight) and patch boundaries coloured by continuity
// (open: grey, C0: red, C1: green, G1: blue, spline-window seams: cyan). Wireframe and normal
// vectors reuse the surface draws with their own pipelines (see renderer.cpp).
#pragma once

#include <array>
#include <vector>

#include "core/model/camera_math.hpp"

#include "core/model/document.hpp"
#include "render/vk/buffers.hpp"

namespace pw::render {
inline namespace scene {

struct OverlayScene {
    Buffer gridIndices;  // line pairs into the pool vertex buffer
    uint32_t gridIndexCount = 0;
    Buffer boundaryVerts;  // position + rgba, line list
    uint32_t boundaryVertexCount = 0;
};

// Deduplicated control-net line segments of every window (pairs of pool indices).
std::vector<uint32_t> controlGridLines(const Document& doc);

// Colour of a continuity (or of an open boundary when no join is recorded).
std::array<float, 4> continuityColor(const Continuity* c);

// The editor's ground grid: 21 lines each way in the z = 0 plane (y = 0 when y is up), `step`
// apart, the axes red (x) and green (the other); line-list vertices of position + rgba.
std::vector<float> groundGridVertices(double step, bool zUp);

// A debug camera's view frustum (RenderOptions::lodCamera) as coloured lines (position + rgba per
// vertex): the four side edges from the near plane out to `depth` along the view direction, the
// far rectangle there and, for a perspective camera, the eye's axis to it.
std::vector<float> frustumLineVertices(const ViewMatrices& vm, double depth);

OverlayScene uploadOverlayScene(Device& dev, const Document& doc);

}  // namespace scene
}  // namespace pw::render

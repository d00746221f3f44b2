// A CPU-tessellated mesh (core tessellateDocument) on the GPU, drawn as plain indexed triangles
// with the surface's shading: the reference for tests and the tessellated/plain benchmark ratio.
// Static data in device-local memory, like the tessellated input's indices (render/vk/buffers.hpp).
#pragma once

#include "core/mesh/mesh_tessellate.hpp"
#include "render/vk/buffers.hpp"

namespace pw::render {
inline namespace scene {

struct PlainMesh {
    Buffer positions, normals, uvs, indices;
    uint32_t indexCount = 0;
};

PlainMesh uploadPlainMesh(Device& dev, const TriangleMesh& mesh);
void recordPlainMesh(VkCommandBuffer cmd, const PlainMesh& m);

}  // namespace scene
}  // namespace pw::render

#include "render/scene/plain_mesh.hpp"

namespace pw::render {
inline namespace scene {

PlainMesh uploadPlainMesh(Device& dev, const TriangleMesh& mesh) {
    PlainMesh m;
    m.positions = uploadStatic(dev, mesh.positions, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    m.normals = uploadStatic(dev, mesh.normals, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    std::vector<std::array<float, 2>> uvs = mesh.uvs;
    uvs.resize(mesh.positions.size(), {0.0f, 0.0f});
    m.uvs = uploadStatic(dev, uvs, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    m.indices = uploadStatic(dev, mesh.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    m.indexCount = uint32_t(mesh.indices.size());
    return m;
}

void recordPlainMesh(VkCommandBuffer cmd, const PlainMesh& m) {
    if (m.indexCount == 0) return;
    const VkBuffer bufs[3] = {m.positions.buffer, m.normals.buffer, m.uvs.buffer};
    const VkDeviceSize offs[3] = {0, 0, 0};
    vkCmdBindVertexBuffers(cmd, 0, 3, bufs, offs);
    vkCmdBindIndexBuffer(cmd, m.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, m.indexCount, 1, 0, 0, 0);
}

}  // namespace scene
}  // namespace pw::render

// Welding a triangle soup into the export mesh (mesh_tessellate.hpp): what the GPU's tessellator
// made, read back vertex by vertex through transform feedback (render/surface_capture), becomes an
// indexed mesh. Positions within `tolerance` of each other are one vertex (seams are bit-identical
// by construction; collapsed edges and poles only agree to float rounding); at one position,
// normals within 2 degrees of each other are averaged (C1/G1 seams) and others keep their own
// vertex (C0 creases), like tessellateDocument. Triangles made degenerate by the welding (at
// collapsed edges) are left out, as the GPU's rasteriser draws nothing for them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh/mesh_tessellate.hpp"

namespace pw {
inline namespace mesh {

// One captured vertex, in the capture shaders' transform-feedback layout (36 bytes).
struct SoupVertex {
    float position[3];
    float normal[3];
    float uv[2];
    uint32_t item;  // window (expandPatches order), then windowCount + Bézier triangle
};
static_assert(sizeof(SoupVertex) == 36, "the transform-feedback stride of surface.tese's CAPTURE variant");

struct WeldStats {
    size_t soupTriangles = 0;        // triangles in the soup
    size_t degenerateTriangles = 0;  // of them, left out (collapsed by the welding)
};

// Every three vertices of `soup` are one triangle, in the order the GPU made them; a triangle's
// item is its first vertex's. The mesh's perWindow has windowCount ranges and perTriangle
// triangleCount, in item order. Throws std::invalid_argument on a soup whose size is not a
// multiple of three or an item outside the document.
TriangleMesh weldTriangleSoup(const std::vector<SoupVertex>& soup, size_t windowCount, size_t triangleCount, double tolerance,
                              WeldStats* stats = nullptr);

}  // namespace mesh
}  // namespace pw

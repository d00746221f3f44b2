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
#include <memory>
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
//
// Within one window, two vertices at different (u, v) merge within `tolerance` only where both lie
// on an edge that `collapsedEdges` (4 bits a window: bit e for Edge e, U0 u = 0, V0 v = 0, U1 u = 1,
// V1 v = 1) marks collapsed, else only when bit-identical: an edge that is merely short (the
// teaspoon's tip doubles back within 1e-6 of the model's size) keeps its vertices apart, so no
// triangle folds onto its neighbour. Without the mask every window merges within tolerance.
TriangleMesh weldTriangleSoup(const std::vector<SoupVertex>& soup, size_t windowCount, size_t triangleCount, double tolerance,
                              WeldStats* stats = nullptr, const std::vector<uint8_t>* collapsedEdges = nullptr);

// How a soup's triangles wind: as given, or turned (each triangle's second and third vertices
// swapped, read so without copying the soup).
enum class SoupWinding { AsGiven, Turned };

// The same weld fed in pieces, so that it can run while the GPU still makes the next piece (the
// as-displayed capture): each add() holds whole triangles whose items all come after the items of
// every earlier piece, and the result is the one weldTriangleSoup makes of all the pieces at once.
// The soup is read during add() only. Throws std::invalid_argument as weldTriangleSoup does, and
// on a piece whose items go back.
class SoupWelder {
public:
    // expectedVertices: about how many soup vertices all pieces hold (sizes the tables; 0: grow).
    SoupWelder(size_t windowCount, size_t triangleCount, double tolerance, const std::vector<uint8_t>* collapsedEdges,
               size_t expectedVertices);
    ~SoupWelder();
    SoupWelder(const SoupWelder&) = delete;
    SoupWelder& operator=(const SoupWelder&) = delete;

    void add(const SoupVertex* soup, size_t vertices, SoupWinding winding = SoupWinding::AsGiven);
    TriangleMesh finish(WeldStats* stats = nullptr);

private:
    struct State;
    std::unique_ptr<State> s_;
};

// The collapsed-edge bits of every window (expandPatches order) at these points: a Bézier window's
// edge whose four control points are one pool point or one position, as tessellateDocument shares them.
std::vector<uint8_t> collapsedWindowEdges(const std::vector<PatchInstance>& windows, const std::vector<Vec3>& points);

}  // namespace mesh
}  // namespace pw

// CPU tessellation of a document into a welded triangle mesh (DESIGN §5): each window as a grid at
// the chosen level, vertices on shared boundaries welded through the pool (bit-identical positions),
// normals shared across C1/G1 seams and split at C0 creases, collapsed edges fanned (no degenerate
// triangles), UVs per patch.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace mesh {

// An index slot not yet given a vertex (the mesh builders' grids and maps).
inline constexpr uint32_t kNoVertex = 0xFFFFFFFFu;

struct MeshRange {
    uint32_t firstIndex = 0, indexCount = 0;  // triangles of one window in `indices`
};

// The grid of a trimmed window as tessellateDocument made it: (level + 1)² vertex ids, row-major
// (row = v), for core/trim/trim_mesh.hpp to cut along the trims.
struct TrimmedGrid {
    uint32_t window = 0;
    int level = 0;
    std::vector<uint32_t> ids;
};

struct TriangleMesh {
    std::vector<std::array<float, 3>> positions;
    std::vector<std::array<float, 3>> normals;
    std::vector<std::array<float, 2>> uvs;
    std::vector<uint32_t> indices;          // triangles, counter-clockwise seen from the normal side
    std::vector<MeshRange> perWindow;       // one per expandPatches() entry
    std::vector<MeshRange> perTriangle;     // one per Document::triangles entry (after the windows)
    std::vector<TrimmedGrid> trimmedGrids;  // the windows of trimmed patches and nets (issue 64), drawn whole until cut

    // Appends triangle (a, b, c) unless it is degenerate: a repeated index or two equal positions
    // (a collapsed edge, as at the teapot's poles).
    void addTriangle(uint32_t a, uint32_t b, uint32_t c) {
        const auto& P = positions;
        if (a == b || b == c || a == c) return;
        if (P[a] == P[b] || P[b] == P[c] || P[a] == P[c]) return;
        indices.insert(indices.end(), {a, b, c});
    }
};

// Upper bounds of what tessellateDocument(doc, level) makes, from the counts alone (nothing is
// tessellated or allocated): (level+1)^2 vertices and 2 level^2 triangles a window, (level+1)(level+2)/2
// and level^2 a Bézier triangle. bytes: positions, normals and UVs (32 bytes a vertex) and indices.
struct MeshBound {
    double vertices = 0, triangles = 0, bytes = 0;
};
MeshBound meshBound(const Document& doc, int level);
// The highest level (>= 1, or 0 when even level 1 does not fit) whose meshBound bytes stay within
// maxBytes.
int highestLevelWithin(const Document& doc, double maxBytes);

// level >= 1 (limits::kMaxExportLevel at most). Windows first, then the Bézier triangles
// (triangle_mesh.hpp), each triangle as level² triangles.
TriangleMesh tessellateDocument(const Document& doc, int level);

// Removes the vertices no triangle uses (a window collapsed to a line or a point, triangles left
// out as degenerate) and renumbers the indices.
void removeUnusedVertices(TriangleMesh& mesh);

// Whether edge e (U0..V1) of Bézier window w is collapsed: its four control points one pool point
// or one position (a pole). Such edges share one vertex along their length.
bool windowEdgeCollapsed(const std::vector<Vec3>& points, const PatchInstance& w, Edge e);

// The control cage: pool points and the line segments of every window's 4x4 net and every
// triangle's net (deduplicated).
struct CageLines {
    std::vector<std::array<float, 3>> positions;
    std::vector<uint32_t> indices;  // pairs
};
CageLines controlCage(const Document& doc);

}  // namespace mesh
}  // namespace pw

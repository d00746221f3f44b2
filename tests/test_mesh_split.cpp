// splitMesh (core/mesh/mesh_split.hpp): a large mesh grouped by surface or as one is split within
// its own arrays; the result must be the copy's, array for array.
#include <gtest/gtest.h>

#include <cstdint>

#include "core/construct/model_builders.hpp"
#include "core/io/document_io.hpp"
#include "core/mesh/mesh_split.hpp"
#include "core/mesh/mesh_tessellate.hpp"

namespace pw::test {
namespace {

void expectSameSplit(const Document& doc, int level, MeshGrouping grouping) {
    SplitMesh copied = splitMesh(tessellateDocument(doc, level), grouping, SIZE_MAX);
    SplitMesh inPlace = splitMesh(tessellateDocument(doc, level), grouping, 0);
    EXPECT_EQ(inPlace.positions, copied.positions);
    EXPECT_EQ(inPlace.normals, copied.normals);
    EXPECT_EQ(inPlace.uvs, copied.uvs);
    EXPECT_EQ(inPlace.indices, copied.indices);
    ASSERT_EQ(inPlace.groups.size(), copied.groups.size());
    for (size_t g = 0; g < copied.groups.size(); ++g) {
        const MeshGroup &a = inPlace.groups[g], &b = copied.groups[g];
        EXPECT_EQ(a.firstIndex, b.firstIndex) << g;
        EXPECT_EQ(a.indexCount, b.indexCount) << g;
        EXPECT_EQ(a.firstVertex, b.firstVertex) << g;
        EXPECT_EQ(a.vertexCount, b.vertexCount) << g;
        EXPECT_EQ(a.closed, b.closed) << g;
        EXPECT_EQ(a.item, b.item) << g;
    }
}

// The teapot: several surfaces (body, lid, handle, spout), open and closed, collapsed poles
// (vertices no triangle uses); a grid, one surface; a dome of Bézier triangles beside the quads'
// ranges.
TEST(MeshSplit, InPlaceIsTheCopysSplit) {
    for (MeshGrouping g : {MeshGrouping::Surfaces, MeshGrouping::Single}) {
        expectSameSplit(builtinTeapot(), 9, g);
        expectSameSplit(makePatchGrid(3, 4), 5, g);
        expectSameSplit(makeTriangleDome(), 6, g);
    }
    // Nothing to split.
    const SplitMesh empty = splitMesh(TriangleMesh{}, MeshGrouping::Surfaces, 0);
    EXPECT_TRUE(empty.groups.empty());
    EXPECT_TRUE(empty.positions.empty());
    // Patches share vertices between groups: always copied, whatever the size.
    const SplitMesh patches = splitMesh(tessellateDocument(makePatchGrid(2, 2), 4), MeshGrouping::Patches, 0);
    EXPECT_EQ(patches.groups.size(), 4u);
    EXPECT_EQ(patches.positions.size(), 4u * 25u);
}

}  // namespace
}  // namespace pw::test

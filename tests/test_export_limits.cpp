// Issue 24: Patchwork never writes a file it refuses to read, and refuses before allocating. A
// 2 000-patch export at --tess 256 reached 14 GB before its refusal; 20 000 patches at the default
// level wrote a 325 MB .glb that `info` then refused (limit 256 MB).
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/limits.hpp"
#include "core/construct/model_builders.hpp"
#include "core/io/gltf_export.hpp"
#include "core/io/gltf_import.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "support.hpp"

using namespace pw;

TEST(ExportLimits, BoundsHoldForWhatTessellationMakes) {
    Document doc = makePatchGrid(3, 2);
    for (int level : {1, 2, 7, 16}) {
        const MeshBound b = meshBound(doc, level);
        const TriangleMesh m = tessellateDocument(doc, level);
        EXPECT_LE(double(m.positions.size()), b.vertices) << level;
        EXPECT_LE(double(m.indices.size() / 3), b.triangles) << level;
        EXPECT_EQ(double(m.indices.size() / 3), b.triangles) << level;  // a flat grid has no degenerate triangle
    }
}

TEST(ExportLimits, AnExportPastTheReadLimitIsRefusedBeforeTessellating) {
    const Document doc = makePatchGrid(45, 45);  // 2 025 patches
    // The room the mesh has in a .glb: the limit less the document's own JSON.
    const double room = double(limits::kMaxFileBytes) - double(documentToJson(doc).dump().size());
    const int fits = highestLevelWithin(doc, room);
    ASSERT_GT(fits, 1);
    EXPECT_LE(meshBound(doc, fits).bytes, room);
    EXPECT_GT(meshBound(doc, fits + 1).bytes, room);
    const auto dir = test::freshTempDir("export-limits");
    ExportOptions o;
    o.level = 256;
    try {
        exportGltf(doc, dir / "big.glb", o);
        FAIL() << "exported past the read limit";
    } catch (const OutputError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("big.glb"), std::string::npos) << msg;
        EXPECT_NE(msg.find("use --tess " + std::to_string(fits) + " or lower"), std::string::npos) << msg;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "big.glb"));
}

// The document travels as JSON text spliced into the glTF, not through tinygltf's values: it comes
// back whole from both containers, empty arrays and all.
TEST(ExportLimits, SplicedDocumentRoundTrips) {
    Document doc = makePatchGrid(2, 2);
    doc.name = "@patchwork-document-1-2@";  // looks like the marker; must not confuse the splice
    for (bool binary : {false, true}) {
        const std::string bytes = exportGltfBytes(doc, binary, ExportOptions{});
        EXPECT_EQ(parsePatchworkGltf(bytes, binary ? "x.glb" : "x.gltf"), doc) << binary;
    }
}

// glTF is +Y up and in metres: a Z-up document (the tea set) exports with its vertices turned -90°
// about X (exactly: coordinates swapped and negated) and no node transform, so that viewers show
// it upright and a reader that drops node transforms (Blender's Clear Parent) keeps it upright; a
// document in millimetres is scaled to metres; the import stays exact; a Y-up document is not turned.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "core/io/bpt_format.hpp"
#include "core/io/gltf_export.hpp"
#include "core/io/gltf_import.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

tinygltf::Model load(const fs::path& path) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, path.string())) << err;
    return model;
}

// The surface positions' bounds (every triangle primitive's accessor box).
std::pair<glm::dvec3, glm::dvec3> bounds(const tinygltf::Model& m) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const tinygltf::Primitive& p : m.meshes.at(0).primitives) {
        if (p.mode != TINYGLTF_MODE_TRIANGLES) continue;
        const tinygltf::Accessor& a = m.accessors.at(size_t(p.attributes.at("POSITION")));
        lo = glm::min(lo, glm::dvec3(a.minValues[0], a.minValues[1], a.minValues[2]));
        hi = glm::max(hi, glm::dvec3(a.maxValues[0], a.maxValues[1], a.maxValues[2]));
    }
    return {lo, hi};
}

bool noTransforms(const tinygltf::Model& m) {
    for (const tinygltf::Node& n : m.nodes)
        if (!n.rotation.empty() || !n.scale.empty() || !n.translation.empty() || !n.matrix.empty()) return false;
    return true;
}

}  // namespace

TEST(GltfUpAxis, AZUpTeapotStandsUprightInItsVertices) {
    const fs::path dir = pw::test::freshTempDir("gltf-up");
    pw::Document doc = pw::loadBpt(pw::test::dataDir() / "teapot.bpt");
    ASSERT_TRUE(doc.camera.zUp);
    pw::ExportOptions o;
    o.level = 4;
    // The same document marked Y-up is written as it is: the reference vertices.
    pw::Document asIs = doc;
    asIs.camera.zUp = false;
    pw::exportGltf(asIs, dir / "y.glb", o);
    const tinygltf::Model y = load(dir / "y.glb");
    EXPECT_TRUE(noTransforms(y));
    const auto [dlo, dhi] = bounds(y);
    EXPECT_NEAR(dlo.z, 0.0, 1e-6);  // the teapot stands on z = 0
    EXPECT_GT(dhi.z - dlo.z, 2.5);

    pw::exportGltf(doc, dir / "up.glb", o);
    const tinygltf::Model m = load(dir / "up.glb");
    EXPECT_TRUE(noTransforms(m));
    const auto [lo, hi] = bounds(m);
    // Its height is glTF +Y; the spout's side (+x) stays +x; its front (-y) faces the viewer (+z).
    EXPECT_EQ(lo.y, dlo.z);
    EXPECT_EQ(hi.y, dhi.z);
    EXPECT_EQ(hi.x, dhi.x);
    EXPECT_EQ(lo.x, dlo.x);
    EXPECT_EQ(hi.z, -dlo.y);
    EXPECT_EQ(lo.z, -dhi.y);
    EXPECT_TRUE(pw::importPatchworkGltf(dir / "up.glb") == doc);

    // In millimetres: the same shape, a thousandth the size (glTF is metres), the document intact.
    doc.unit = pw::LengthUnit::Millimetre;
    pw::exportGltf(doc, dir / "mm.glb", o);
    const tinygltf::Model mm = load(dir / "mm.glb");
    const auto [mlo, mhi] = bounds(mm);
    EXPECT_NEAR(mhi.y, 0.001 * hi.y, 1e-9);
    EXPECT_NEAR(mhi.x, 0.001 * hi.x, 1e-9);
    EXPECT_TRUE(pw::importPatchworkGltf(dir / "mm.glb") == doc);

    fs::remove_all(dir);
}

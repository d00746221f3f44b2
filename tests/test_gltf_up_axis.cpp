// glTF is +Y up: a Z-up document (the tea set) exports with its node turned -90° about X, so
// viewers show it upright; the vertices stay the document's surface and the import stays exact;
// a Y-up document gets no rotation.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>

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

// The surface positions' bounds after the node's rotation.
std::pair<glm::dvec3, glm::dvec3> shownBounds(const tinygltf::Model& m, bool turn = true) {
    const tinygltf::Node& node = m.nodes.at(0);
    glm::dquat q(1.0, 0.0, 0.0, 0.0);
    if (node.rotation.size() == 4 && turn) q = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const tinygltf::Primitive& p : m.meshes.at(0).primitives) {
        if (p.mode != TINYGLTF_MODE_TRIANGLES) continue;
        const tinygltf::Accessor& a = m.accessors.at(size_t(p.attributes.at("POSITION")));
        for (int c = 0; c < 8; ++c) {  // the corners of the accessor's box
            const glm::dvec3 v(a.minValues[0] + (c & 1 ? a.maxValues[0] - a.minValues[0] : 0.0),
                               a.minValues[1] + (c & 2 ? a.maxValues[1] - a.minValues[1] : 0.0),
                               a.minValues[2] + (c & 4 ? a.maxValues[2] - a.minValues[2] : 0.0));
            const glm::dvec3 r = q * v;
            lo = glm::min(lo, r), hi = glm::max(hi, r);
        }
    }
    return {lo, hi};
}

}  // namespace

TEST(GltfUpAxis, AZUpTeapotStandsUpright) {
    const fs::path dir = pw::test::freshTempDir("gltf-up");
    pw::Document doc = pw::loadBpt(pw::test::dataDir() / "teapot.bpt");
    ASSERT_TRUE(doc.camera.zUp);
    pw::ExportOptions o;
    o.level = 4;
    pw::exportGltf(doc, dir / "up.glb", o);
    const tinygltf::Model m = load(dir / "up.glb");
    const auto [lo, hi] = shownBounds(m);
    const auto [dlo, dhi] = shownBounds(m, false);  // the vertices: the document's own coordinates
    EXPECT_NEAR(dlo.z, 0.0, 1e-6);                  // the teapot stands on z = 0 ...
    EXPECT_GT(dhi.z - dlo.z, 2.5);
    // ... and shown, its height is glTF +Y; the spout's side (+x) stays +x; its front (-y) faces
    // the viewer (+z).
    EXPECT_NEAR(lo.y, dlo.z, 1e-6);
    EXPECT_NEAR(hi.y, dhi.z, 1e-6);
    EXPECT_NEAR(hi.x, dhi.x, 1e-6);
    EXPECT_NEAR(hi.z, -dlo.y, 1e-6);
    EXPECT_TRUE(pw::importPatchworkGltf(dir / "up.glb") == doc);

    doc.camera.zUp = false;  // a Y-up document needs no turn
    pw::exportGltf(doc, dir / "y.glb", o);
    const tinygltf::Model y = load(dir / "y.glb");
    EXPECT_TRUE(y.nodes.at(0).rotation.empty());
    fs::remove_all(dir);
}

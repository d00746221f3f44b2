// The exact sphere exported (issue 21): `patchwork export` of data/exact_sphere.patchwork writes a
// glTF whose every vertex lies on the unit sphere to the precision of a float (the distance from
// the centre, computed in double from the stored floats, is 1 within two float ulps) and whose
// triangles close up (every edge used by exactly two triangles, by vertex index); the Khronos
// validator and assimp read it without a complaint, and the OBJ closes up too.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "support.hpp"

namespace fs = std::filesystem;
using namespace pw::test;

namespace {

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// Edges used by other than exactly two triangles.
size_t unpairedEdges(const std::vector<std::array<uint32_t, 3>>& tris) {
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (const auto& t : tris)
        for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    size_t bad = 0;
    for (const auto& [e, n] : uses) bad += n != 2;
    return bad;
}

template <class T>
std::vector<T> accessorData(const tinygltf::Model& m, int index) {
    const tinygltf::Accessor& a = m.accessors[size_t(index)];
    const tinygltf::BufferView& v = m.bufferViews[size_t(a.bufferView)];
    const size_t comps = a.type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
    const size_t stride = v.byteStride ? v.byteStride : comps * sizeof(T);
    std::vector<T> out(a.count * comps);
    const unsigned char* base = m.buffers[size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset;
    for (size_t i = 0; i < a.count; ++i) std::memcpy(&out[i * comps], base + i * stride, comps * sizeof(T));
    return out;
}

}  // namespace

TEST(RationalExport, TheSphereIsASphereToTheLastBitOfAFloat) {
    const fs::path dir = freshTempDir("rational-export");
    const fs::path in = dataDir() / "exact_sphere.patchwork", glb = dir / "ball.glb", obj = dir / "ball.obj";
    for (const fs::path& out : {glb, obj}) {
        const RunResult r = runCommand(q(patchworkBinary()) + " export " + q(in) + " -o " + q(out) + " --tess 24 2>&1");
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    expectValidGltf({glb});

    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, glb.string())) << err;
    size_t vertices = 0, triangles = 0, unpaired = 0;
    double worst = 0.0;
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& prim : mesh.primitives) {
            if (prim.mode != TINYGLTF_MODE_TRIANGLES) continue;
            const std::vector<float> pos = accessorData<float>(model, prim.attributes.at("POSITION"));
            for (size_t i = 0; i < pos.size(); i += 3) {
                const double r = std::sqrt(double(pos[i]) * pos[i] + double(pos[i + 1]) * pos[i + 1] + double(pos[i + 2]) * pos[i + 2]);
                worst = std::max(worst, std::abs(r - 1.0));
            }
            vertices += pos.size() / 3;
            const tinygltf::Accessor& ia = model.accessors[size_t(prim.indices)];
            std::vector<uint32_t> idx;
            if (ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
                for (uint16_t i : accessorData<uint16_t>(model, prim.indices)) idx.push_back(i);
            else
                idx = accessorData<uint32_t>(model, prim.indices);
            std::vector<std::array<uint32_t, 3>> tris(idx.size() / 3);
            for (size_t i = 0; i < idx.size(); ++i) tris[i / 3][i % 3] = idx[i];
            triangles += tris.size();
            unpaired += unpairedEdges(tris);
        }
    EXPECT_GT(vertices, 8u * 24u * 24u / 2u);
    EXPECT_EQ(triangles, size_t(8 * 2 * 24 * 24 - 8 * 24));  // the pole rows fan: no degenerate triangles
    EXPECT_LE(worst, 2.0 * FLT_EPSILON);                     // a float's precision at radius 1 (rounding each coordinate)
    EXPECT_EQ(unpaired, 0u);                                 // watertight: a closed surface

    // assimp reads both without a warning; the OBJ's faces close up by position id.
    for (const fs::path& f : {glb, obj}) {
        const RunResult a = runCommand("assimp info " + q(f) + " --show-log 2>&1");
        EXPECT_EQ(a.exitCode, 0) << a.output;
        std::istringstream lines(a.output);
        for (std::string line; std::getline(lines, line);)
            EXPECT_FALSE(line.rfind("Warn", 0) == 0 || line.rfind("Error", 0) == 0) << f << ": " << line;
    }
    std::ifstream objIn(obj);
    std::vector<std::array<uint32_t, 3>> faces;
    for (std::string line; std::getline(objIn, line);) {
        if (line.rfind("f ", 0) != 0) continue;
        std::istringstream s(line.substr(2));
        std::array<uint32_t, 3> f{};
        for (uint32_t& i : f) {
            std::string t;
            s >> t;
            i = uint32_t(std::stoul(t.substr(0, t.find('/'))));
        }
        faces.push_back(f);
    }
    EXPECT_EQ(faces.size(), triangles);
    EXPECT_EQ(unpairedEdges(faces), 0u);
    fs::remove_all(dir);
}

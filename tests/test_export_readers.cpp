// Exports read by tools we did not write (issue 20): assimp (Debian's assimp-utils) reads the
// teapot's glTF and OBJ with no warning, upright (+Y up) and with the counts we wrote; the surfaces
// are welded: at level 16 the teapot has exactly its 256 real boundary edges (Blender saw 1 920 when
// every patch was its own piece), in the glTF's primitives and in the OBJ alike. OBJ layout: one
// group per patch, `l` lines for curves, an MTL beside it; failures leave neither file.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/base/errors.hpp"
#include "core/construct/primitives.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/gltf_export.hpp"
#include "core/io/obj_export.hpp"
#include "core/ops/patch_ops.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

struct AssimpInfo {
    bool ok = false;
    std::string log;
    long vertices = -1, faces = -1, meshes = -1;
    std::string minPoint, maxPoint;
};

// `assimp info FILE --show-log`: its counts, and every Warn/Error line of its log.
AssimpInfo assimpInfo(const fs::path& file) {
    AssimpInfo a;
    const auto r = pw::test::runCommand("assimp info " + q(file) + " --show-log");
    a.ok = r.exitCode == 0;
    std::istringstream in(r.output);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("Warn", 0) == 0 || line.rfind("Error", 0) == 0) a.log += line + "\n";
        auto field = [&](const char* name, long& v) {
            if (v < 0 && line.rfind(name, 0) == 0) v = std::strtol(line.c_str() + line.find(':') + 1, nullptr, 10);
        };
        field("Vertices:", a.vertices);
        field("Faces:", a.faces);
        field("Meshes:", a.meshes);
        if (line.rfind("Minimum point", 0) == 0) a.minPoint = line.substr(line.find('('));
        if (line.rfind("Maximum point", 0) == 0) a.maxPoint = line.substr(line.find('('));
    }
    return a;
}

// Edges used by one triangle only, and by more than two, over index triples.
std::pair<size_t, size_t> openAndOverused(const std::vector<std::array<uint32_t, 3>>& tris) {
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (const auto& t : tris)
        for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    size_t open = 0, over = 0;
    for (const auto& [e, n] : uses) {
        open += n == 1;
        over += n > 2;
    }
    return {open, over};
}

// A GLB's model as tinygltf reads it (a failure to read is a test failure, and an empty model).
tinygltf::Model glbModel(const std::string& bytes) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    EXPECT_TRUE(
        loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), unsigned(bytes.size())))
        << err;
    return model;
}

struct ObjText {
    size_t v = 0, vt = 0, vn = 0, groups = 0;
    std::vector<std::array<uint32_t, 3>> faces;  // position ids
    std::vector<std::vector<uint32_t>> lines;
    std::vector<std::array<double, 3>> positions;
    std::string mtllib;
};

ObjText readObj(const fs::path& p) {
    ObjText o;
    std::ifstream in(p);
    for (std::string line; std::getline(in, line);) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "v") {
            std::array<double, 3> x{};
            s >> x[0] >> x[1] >> x[2];
            o.positions.push_back(x);
            ++o.v;
        } else if (tag == "vt")
            ++o.vt;
        else if (tag == "vn")
            ++o.vn;
        else if (tag == "g")
            ++o.groups;
        else if (tag == "mtllib")
            s >> o.mtllib;
        else if (tag == "f") {
            std::array<uint32_t, 3> f{};
            for (auto& i : f) {
                std::string t;
                s >> t;
                i = uint32_t(std::stoul(t.substr(0, t.find('/'))));
            }
            o.faces.push_back(f);
        } else if (tag == "l") {
            std::vector<uint32_t> l;
            for (uint32_t i; s >> i;) l.push_back(i);
            o.lines.push_back(l);
        }
    }
    return o;
}

}  // namespace

TEST(ExportReaders, AssimpReadsTheTeapotGltfAndObjUprightWithoutWarnings) {
    const fs::path dir = pw::test::freshTempDir("export-readers");
    const fs::path bin = pw::test::patchworkBinary();
    const fs::path input = pw::test::dataDir() / "teapot.bpt";
    for (const std::string name : {"pot.glb", "pot.gltf", "pot.obj"}) {
        const auto r = pw::test::runCommand(q(bin) + " export " + q(input) + " -o " + q(dir / name) + " --tess 16");
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    pw::GltfExportStats stats;
    (void)pw::exportGltfBytes(pw::loadBpt(input), true, {16, pw::MeshGrouping::Surfaces, false}, &stats);
    for (const std::string name : {"pot.glb", "pot.gltf", "pot.obj"}) {
        SCOPED_TRACE(name);
        const AssimpInfo a = assimpInfo(dir / name);
        ASSERT_TRUE(a.ok);
        EXPECT_EQ(a.log, "");
        EXPECT_EQ(a.faces, long(stats.triangles));
        // Upright: the teapot stands on y = 0 and reaches y = 3.15 (its z in the document).
        EXPECT_EQ(a.minPoint, "(-3.000000 0.000000 -2.000000)");
        EXPECT_EQ(a.maxPoint.substr(a.maxPoint.find(' ')), " 3.150000 2.000000)");
        if (name != "pot.obj") {
            EXPECT_EQ(a.vertices, long(stats.vertices));  // the welded count: nothing copied per patch
            EXPECT_EQ(a.meshes, 1);                       // one piece (three welded primitives, one material)
        } else {
            EXPECT_EQ(a.meshes, 32);  // assimp makes a mesh of each OBJ group (one per patch)
        }
    }
    fs::remove_all(dir);
}

TEST(ExportReaders, TheSurfacesAreWeldedInGltfAndObj) {
    const fs::path dir = pw::test::freshTempDir("export-welded");
    const pw::Document doc = pw::loadBpt(pw::test::dataDir() / "teapot.bpt");
    // glTF: within each primitive (connected surface), by vertex index.
    {
        const tinygltf::Model model = glbModel(pw::exportGltfBytes(doc, true, {16, pw::MeshGrouping::Surfaces, false}));
        size_t open = 0, over = 0;
        for (const auto& mesh : model.meshes)
            for (const auto& prim : mesh.primitives) {
                const tinygltf::Accessor& acc = model.accessors[size_t(prim.indices)];
                const tinygltf::BufferView& view = model.bufferViews[size_t(acc.bufferView)];
                const unsigned char* base = model.buffers[0].data.data() + view.byteOffset + acc.byteOffset;
                std::vector<std::array<uint32_t, 3>> tris(acc.count / 3);
                for (size_t i = 0; i < acc.count; ++i) {
                    uint16_t v;
                    ASSERT_EQ(acc.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
                    std::memcpy(&v, base + 2 * i, 2);
                    tris[i / 3][i % 3] = v;
                }
                const auto [o, x] = openAndOverused(tris);
                open += o;
                over += x;
            }
        EXPECT_EQ(open, 256u);
        EXPECT_EQ(over, 0u);
    }
    // OBJ: by position id over the whole file.
    pw::exportObj(doc, dir / "pot.obj", 16);
    const ObjText obj = readObj(dir / "pot.obj");
    const auto [open, over] = openAndOverused(obj.faces);
    EXPECT_EQ(open, 256u);
    EXPECT_EQ(over, 0u);
    EXPECT_EQ(obj.groups, 32u);
    EXPECT_EQ(obj.mtllib, "pot.mtl");
    EXPECT_NE(pw::test::readBytes(dir / "pot.mtl").find("newmtl patchwork_surface"), std::string::npos);
    EXPECT_EQ(obj.faces.size(), size_t(32 * 2 * 16 * 16 - 8 * 16));  // the 8 pole rows fan: no degenerate triangles
    fs::remove_all(dir);
}

TEST(ExportReaders, ObjCurvesAreLinesAndFailuresLeaveNothing) {
    const fs::path dir = pw::test::freshTempDir("export-obj");
    pw::Document doc = pw::loadBpt(pw::test::dataDir() / "teapot.bpt");
    pw::curveFromEdge(doc, 0, pw::Edge::V0);
    const pw::ObjExportStats stats = pw::exportObj(doc, dir / "pot.obj", 6);
    EXPECT_EQ(stats.lineSegments, 6u);
    const ObjText obj = readObj(dir / "pot.obj");
    ASSERT_EQ(obj.lines.size(), 1u);
    ASSERT_EQ(obj.lines[0].size(), 7u);
    // The polyline's points are the curve's samples, turned +Y up like the surface.
    const auto samples = pw::sampleCurve(pw::curvePoints(doc, doc.curves[0]), 6);
    for (size_t k = 0; k < 7; ++k) {
        const auto& p = obj.positions[obj.lines[0][k] - 1];
        EXPECT_NEAR(p[0], samples[k].x, 1e-6);
        EXPECT_NEAR(p[1], samples[k].z, 1e-6);
        EXPECT_NEAR(p[2], -samples[k].y, 1e-6);
    }
    EXPECT_EQ(stats.bytes, fs::file_size(dir / "pot.obj") + fs::file_size(dir / "pot.mtl"));
    // An unwritable OBJ: neither file is left, and an existing MTL stays as it was.
    std::ofstream(dir / "keep.mtl") << "old";
    fs::create_directory(dir / "keep.obj");  // a directory where the OBJ should go
    EXPECT_THROW(pw::exportObj(doc, dir / "keep.obj", 2), pw::OutputError);
    EXPECT_EQ(pw::test::readBytes(dir / "keep.mtl"), "old");
    EXPECT_THROW(pw::exportObj(doc, dir / "missing" / "x.obj", 2), pw::OutputError);
    EXPECT_FALSE(fs::exists(dir / "missing"));
    fs::remove_all(dir);
}

// A C0 crease (a cylinder's rims) keeps its sharp normals with two glTF vertices at one position,
// one per normal: closed by position (what Blender's Merge by Distance and every other reader that
// welds by position see), open by vertex index only there, and never two vertices with one position
// and one normal (that would be a missed weld). docs/FILE_FORMAT.md, "Creases".
TEST(ExportReaders, CreasesShareTheirPositionsAndSplitOnlyTheirNormals) {
    pw::Document doc;
    pw::addCylinder(doc, {0, 0, 0}, 1.0, 2.0, true);
    const tinygltf::Model model = glbModel(pw::exportGltfBytes(doc, true, {8, pw::MeshGrouping::Single, false}));
    auto floats = [&](int accessor) {
        const tinygltf::Accessor& acc = model.accessors[size_t(accessor)];
        const tinygltf::BufferView& view = model.bufferViews[size_t(acc.bufferView)];
        std::vector<std::array<float, 3>> v(acc.count);
        std::memcpy(v.data(), model.buffers[0].data.data() + view.byteOffset + acc.byteOffset, acc.count * 12);
        return v;
    };
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
    const tinygltf::Primitive& prim = model.meshes[0].primitives[0];
    const auto positions = floats(prim.attributes.at("POSITION"));
    const auto normals = floats(prim.attributes.at("NORMAL"));
    const tinygltf::Accessor& acc = model.accessors[size_t(prim.indices)];
    const unsigned char* base = model.buffers[0].data.data() + model.bufferViews[size_t(acc.bufferView)].byteOffset + acc.byteOffset;
    std::vector<std::array<uint32_t, 3>> byIndex(acc.count / 3), byPosition(acc.count / 3);
    std::map<std::array<float, 3>, uint32_t> positionId;
    std::map<std::array<float, 3>, std::vector<uint32_t>> atPosition;
    for (uint32_t v = 0; v < positions.size(); ++v) {
        positionId.emplace(positions[v], uint32_t(positionId.size()));
        atPosition[positions[v]].push_back(v);
    }
    for (size_t i = 0; i < acc.count; ++i) {
        uint16_t v;
        ASSERT_EQ(acc.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        std::memcpy(&v, base + 2 * i, 2);
        byIndex[i / 3][i % 3] = v;
        byPosition[i / 3][i % 3] = positionId.at(positions[v]);
    }
    EXPECT_EQ(openAndOverused(byPosition), std::make_pair(size_t(0), size_t(0)));  // closed
    EXPECT_GT(openAndOverused(byIndex).first, 0u);                                 // the two rims, by index
    size_t split = 0;
    for (const auto& [p, vs] : atPosition)
        for (size_t a = 0; a < vs.size(); ++a)
            for (size_t b = a + 1; b < vs.size(); ++b) {
                const auto &n = normals[vs[a]], &m = normals[vs[b]];
                EXPECT_LT(n[0] * m[0] + n[1] * m[1] + n[2] * m[2], 0.99f) << "two vertices with one position and one normal";
                ++split;
            }
    EXPECT_GE(split, 2u * 8u * 4u);  // both rims, 8 segments a quarter
}

// glTF 2.0 export and import (DESIGN §5): the tea set at several levels, .glb and .gltf, one primitive
// per connected surface, per patch or one, with or without the control cage, passes the Khronos validator with no errors and no
// warnings; the file carries the editable document; import restores it; the command line refuses
// bad levels and unwritable paths.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/base/errors.hpp"
#include "core/base/up_axis.hpp"
#include "core/construct/model_builders.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/gltf_export.hpp"
#include "core/io/gltf_import.hpp"
#include "core/ops/net_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

std::string quote(const fs::path& p) { return "'" + p.string() + "'"; }

pw::Document loadModel(const std::string& name) { return pw::loadBpt(pw::test::dataDir() / (name + ".bpt")); }

tinygltf::Model loadWithTinygltf(const fs::path& path) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = path.extension() == ".glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, path.string())
                                               : loader.LoadASCIIFromFile(&model, &err, &warn, path.string());
    EXPECT_TRUE(ok) << path << ": " << err;
    return model;
}

// The float array behind an accessor (tightly packed VEC3 float data).
std::vector<std::array<float, 3>> readVec3(const tinygltf::Model& model, int accessor) {
    const tinygltf::Accessor& acc = model.accessors[accessor];
    const tinygltf::BufferView& view = model.bufferViews[acc.bufferView];
    const unsigned char* base = model.buffers[view.buffer].data.data() + view.byteOffset + acc.byteOffset;
    std::vector<std::array<float, 3>> out(acc.count);
    std::memcpy(out.data(), base, acc.count * 12);
    return out;
}

// The mesh of the root's child node named "<document> <what>", or nullptr.
const tinygltf::Mesh* childMesh(const tinygltf::Model& model, const std::string& what) {
    if (model.nodes.empty()) return nullptr;
    for (int c : model.nodes[0].children) {
        const tinygltf::Node& n = model.nodes[size_t(c)];
        if (n.name.size() > what.size() && n.name.compare(n.name.size() - what.size(), what.size(), what) == 0 && n.mesh >= 0)
            return &model.meshes[size_t(n.mesh)];
    }
    return nullptr;
}

template <typename T>
std::vector<uint32_t> readIndicesAs(const tinygltf::Model& model, const tinygltf::Accessor& acc) {
    const tinygltf::BufferView& view = model.bufferViews[acc.bufferView];
    const unsigned char* base = model.buffers[view.buffer].data.data() + view.byteOffset + acc.byteOffset;
    std::vector<uint32_t> out(acc.count);
    for (size_t i = 0; i < acc.count; ++i) {
        T v;
        std::memcpy(&v, base + i * sizeof(T), sizeof(T));
        out[i] = v;
    }
    return out;
}
std::vector<uint32_t> readIndices(const tinygltf::Model& model, int accessor) {
    const tinygltf::Accessor& acc = model.accessors[size_t(accessor)];
    return acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? readIndicesAs<uint16_t>(model, acc)
                                                                       : readIndicesAs<uint32_t>(model, acc);
}

// Layout: a root node with the surface (and cage) children; one surface primitive per group, each
// indexing exactly its own vertices (all of them); POSITION min/max exact; open groups double-sided.
void checkStructure(const fs::path& path, pw::MeshGrouping grouping, bool cage, size_t patches, size_t surfaces) {
    SCOPED_TRACE(path.string());
    const tinygltf::Model model = loadWithTinygltf(path);
    EXPECT_EQ(model.asset.generator, "Patchwork");
    EXPECT_EQ(model.asset.version, "2.0");
    ASSERT_EQ(model.scenes.size(), 1u);
    ASSERT_EQ(model.scenes[0].nodes, std::vector<int>{0});
    ASSERT_EQ(model.nodes.size(), cage ? 3u : 2u);
    EXPECT_EQ(model.nodes[0].mesh, -1);
    ASSERT_EQ(model.meshes.size(), cage ? 2u : 1u);
    EXPECT_TRUE(model.asset.extras.Has("patchwork"));
    ASSERT_TRUE(model.asset.extras.Has("patchworkExport"));
    EXPECT_EQ(model.asset.extras.Get("patchworkExport").Get("primitives").Get<std::string>(), pw::meshGroupingName(grouping));
    EXPECT_EQ(model.asset.extras.Get("patchworkExport").Get("cage").Get<bool>(), cage);
    const tinygltf::Mesh* surface = childMesh(model, " surface");
    ASSERT_NE(surface, nullptr);
    const size_t want = grouping == pw::MeshGrouping::Single ? 1 : grouping == pw::MeshGrouping::Patches ? patches : surfaces;
    ASSERT_EQ(surface->primitives.size(), want);
    for (const tinygltf::Primitive& p : surface->primitives) {
        ASSERT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
        EXPECT_EQ(p.attributes.count("NORMAL"), 1u);
        EXPECT_EQ(p.attributes.count("TEXCOORD_0"), 1u);
        ASSERT_GE(p.material, 0);
        EXPECT_EQ(model.materials[size_t(p.material)].extensions.count("KHR_materials_unlit"), 0u);
        const int posAcc = p.attributes.at("POSITION");
        const auto pos = readVec3(model, posAcc);
        const auto idx = readIndices(model, p.indices);
        std::vector<bool> used(pos.size(), false);
        for (uint32_t i : idx) {
            ASSERT_LT(i, pos.size());
            used[i] = true;
        }
        EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; })) << "a primitive carries a vertex it does not use";
        // Open (an edge, by position, used once) exactly when double-sided.
        std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, int> edges;
        for (size_t t = 0; t + 2 < idx.size(); t += 3)
            for (int k = 0; k < 3; ++k) {
                auto a = pos[idx[t + size_t(k)]], b = pos[idx[t + size_t(k + 1) % 3]];
                if (b < a) std::swap(a, b);
                ++edges[{a, b}];
            }
        const bool open = std::any_of(edges.begin(), edges.end(), [](const auto& e) { return e.second != 2; });
        EXPECT_EQ(model.materials[size_t(p.material)].doubleSided, open);
        std::array<float, 3> lo = pos.front(), hi = pos.front();
        for (const auto& q : pos)
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], q[k]);
                hi[k] = std::max(hi[k], q[k]);
            }
        const tinygltf::Accessor& pa = model.accessors[posAcc];
        ASSERT_EQ(pa.minValues.size(), 3u);
        ASSERT_EQ(pa.maxValues.size(), 3u);
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(pa.minValues[k], static_cast<double>(lo[k]));
            EXPECT_EQ(pa.maxValues[k], static_cast<double>(hi[k]));
        }
    }
    const tinygltf::Mesh* lines = childMesh(model, " control cage");
    ASSERT_EQ(lines != nullptr, cage);
    if (cage) {
        ASSERT_EQ(lines->primitives.size(), 1u);
        EXPECT_EQ(lines->primitives[0].mode, TINYGLTF_MODE_LINE);
        EXPECT_EQ(lines->primitives[0].attributes.count("NORMAL"), 0u);
        ASSERT_GE(lines->primitives[0].material, 0);
        EXPECT_EQ(model.materials[size_t(lines->primitives[0].material)].extensions.count("KHR_materials_unlit"), 1u);
        EXPECT_EQ(std::count(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_materials_unlit"), 1);
    }
}

constexpr pw::MeshGrouping kGroupings[] = {pw::MeshGrouping::Surfaces, pw::MeshGrouping::Patches, pw::MeshGrouping::Single};

TEST(Gltf, ValidatorIsInstalled) { EXPECT_FALSE(pw::test::gltfValidatorScript().empty()); }

TEST(Gltf, TeaSetExportsAreValidAndRoundTrip) {
    // Connected surfaces (by shared vertex positions): the teapot's rim, body, bottom and handle
    // (the handle's ends meet body vertices), its spout, its lid; the cup (handle included) and the
    // spoon are one each.
    const fs::path dir = pw::test::freshTempDir("gltf-teaset");
    for (const auto& [name, surfaces] : {std::pair<std::string, size_t>{"teapot", 3}, {"teacup", 1}, {"teaspoon", 1}}) {
        const pw::Document doc = loadModel(name);
        std::vector<fs::path> files;
        for (int level : {1, 4, 16}) {
            for (const std::string ext : {".glb", ".gltf"}) {
                for (pw::MeshGrouping grouping : kGroupings) {
                    for (bool cage : {false, true}) {
                        const fs::path out = dir / (name + "-L" + std::to_string(level) + "-" + pw::meshGroupingName(grouping) +
                                                    (cage ? "-cage" : "") + ext);
                        pw::ExportOptions options;
                        options.level = level;
                        options.primitives = grouping;
                        options.cage = cage;
                        pw::exportGltf(doc, out, options);
                        ASSERT_TRUE(fs::exists(out));
                        files.push_back(out);
                        checkStructure(out, grouping, cage, doc.patches.size(), surfaces);
                        // The editable document comes back unchanged.
                        const pw::Document back = pw::importPatchworkGltf(out);
                        EXPECT_TRUE(back == doc) << out << ": imported document differs";
                    }
                }
            }
        }
        SCOPED_TRACE(name);
        pw::test::expectValidGltf(files);
    }
    fs::remove_all(dir);
}

TEST(Gltf, BezierTriangleExportsAreValidAndRoundTrip) {
    // The triangle dome alone, and beside the teapot's patches: welded mesh, one primitive per
    // triangle (or merged), cage with the triangle nets; 0 errors and 0 warnings.
    const fs::path dir = pw::test::freshTempDir("gltf-triangles");
    pw::Document mixed = loadModel("teapot");
    {
        const pw::Document dome = pw::makeTriangleDome(1.0, 0.5);
        const uint32_t base = static_cast<uint32_t>(mixed.points.size());
        for (const pw::Vec3& p : dome.points) mixed.points.push_back(p + pw::Vec3(0.0, 0.0, 4.0));
        for (pw::TrianglePatch t : dome.triangles) {
            for (uint32_t& i : t.idx) i += base;
            mixed.triangles.push_back(t);
        }
    }
    std::vector<fs::path> files;
    int n = 0;
    for (const pw::Document& doc : {pw::makeTriangleDome(1.0, 0.5), mixed}) {
        for (int level : {1, 5, 16}) {
            for (pw::MeshGrouping grouping : kGroupings) {
                const fs::path out =
                    dir / ("tri" + std::to_string(n++) + "-" + pw::meshGroupingName(grouping) + (level == 5 ? ".gltf" : ".glb"));
                pw::ExportOptions options;
                options.level = level;
                options.primitives = grouping;
                options.cage = level == 5;
                pw::GltfExportStats stats;
                stats = pw::exportGltfWithStats(doc, out, options);
                if (doc.patches.empty()) {
                    EXPECT_EQ(stats.triangles, size_t(6 * level * level));
                }
                // The dome is one surface; beside the teapot's three it makes four.
                const size_t surfaces = doc.patches.empty() ? 1 : 4;
                checkStructure(out, grouping, options.cage, doc.patches.size() + doc.triangles.size(), surfaces);
                EXPECT_TRUE(pw::importPatchworkGltf(out) == doc) << out;
                files.push_back(out);
            }
        }
    }
    pw::test::expectValidGltf(files);
    fs::remove_all(dir);
}

TEST(Gltf, BezierCurvesExportAsLinesAndRoundTrip) {
    // Two curves alone, and a curve on a teapot edge beside the teapot: in a "curves" node, one
    // unlit LINES primitive, level + 1 points per curve at the curve's samples joined in pairs; the
    // document comes back from the extras; valid.
    const fs::path dir = pw::test::freshTempDir("gltf-curves");
    pw::Document alone;
    pw::addCurve(alone, pw::Vec3(0.0), 2.0);
    pw::addCurve(alone, pw::Vec3(0.0, 0.0, 1.0), 3.0, false);
    pw::Document mixed = loadModel("teapot");
    pw::curveFromEdge(mixed, 0, pw::Edge::V0);
    std::vector<fs::path> files;
    int n = 0;
    for (const pw::Document& doc : {alone, mixed}) {
        for (int level : {1, 7, 16}) {
            const fs::path out = dir / ("curves" + std::to_string(n++) + (level == 7 ? ".gltf" : ".glb"));
            pw::ExportOptions options;
            options.level = level;
            const pw::GltfExportStats stats = pw::exportGltfWithStats(doc, out, options);
            EXPECT_EQ(stats.curveSegments, doc.curves.size() * size_t(level));
            const tinygltf::Model model = loadWithTinygltf(out);
            const tinygltf::Mesh* curves = childMesh(model, " curves");
            ASSERT_NE(curves, nullptr);
            ASSERT_EQ(curves->primitives.size(), 1u);
            const tinygltf::Primitive& prim = curves->primitives[0];
            EXPECT_EQ(prim.mode, TINYGLTF_MODE_LINE);
            EXPECT_EQ(model.materials[size_t(prim.material)].extensions.count("KHR_materials_unlit"), 1u);
            const auto positions = readVec3(model, prim.attributes.at("POSITION"));
            const auto idx = readIndices(model, prim.indices);
            ASSERT_EQ(idx.size(), 2 * doc.curves.size() * size_t(level));
            for (size_t c = 0; c < doc.curves.size(); ++c) {
                const auto want = pw::sampleCurve(pw::curvePoints(doc, doc.curves[c]), level);
                for (size_t k = 0; k + 1 < want.size(); ++k)  // segment k of curve c joins its samples k and k + 1
                    for (size_t e = 0; e < 2; ++e) {
                        // glTF is +Y up: a Z-up document's points are turned, (x, y, z) -> (x, z, -y).
                        const pw::Vec3& w = want[k + e];
                        const std::array<float, 3> shown = pw::zUpToYUp({float(w.x), float(w.y), float(w.z)});
                        for (int a = 0; a < 3; ++a)
                            EXPECT_FLOAT_EQ(positions[idx[2 * (c * size_t(level) + k) + e]][size_t(a)],
                                            doc.camera.zUp ? shown[size_t(a)] : float(w[a]));
                    }
            }
            EXPECT_TRUE(pw::importPatchworkGltf(out) == doc) << out;
            files.push_back(out);
        }
    }
    pw::test::expectValidGltf(files);
    fs::remove_all(dir);
}

TEST(Gltf, SingleFileValidationAndTheDocumentsLevel) {
    // The validator's plain one-file use, on an export at the document's own level (16 by default).
    const fs::path dir = pw::test::freshTempDir("gltf-single");
    pw::Document doc = loadModel("teapot");
    EXPECT_EQ(pw::resolveExportLevel(doc, 0), 16);
    doc.tess.outer[2] = 7.5f;
    doc.tess.inner = {3, 3};
    doc.tess.outer = {2, 5, 7.5f, 1};
    EXPECT_EQ(pw::resolveExportLevel(doc, 0), 8);
    EXPECT_EQ(pw::resolveExportLevel(doc, 3), 3);
    EXPECT_EQ(pw::resolveExportLevel(doc, 100000), 256);
    const fs::path out = dir / "teapot.glb";
    pw::GltfExportStats stats = pw::exportGltfWithStats(doc, out, {});
    EXPECT_EQ(stats.level, 8);
    EXPECT_EQ(stats.triangles, static_cast<size_t>(32 * 2 * 8 * 8 - 8 * 8));
    EXPECT_EQ(stats.bytes, fs::file_size(out));
    // The file is written in pieces from the mesh arrays: the same bytes as in one string, .glb
    // (with the cage's and curves' blocks) and .gltf.
    for (const bool binary : {true, false}) {
        pw::Document withCurve = doc;
        withCurve.curves.push_back(pw::BezierCurve{{0, 1, 2, 3}});
        const pw::ExportOptions options{4, pw::MeshGrouping::Surfaces, true};
        const fs::path file = dir / (binary ? "pieces.glb" : "pieces.gltf");
        (void)pw::exportGltfWithStats(withCurve, file, options);
        EXPECT_EQ(pw::test::readBytes(file), pw::exportGltfBytes(withCurve, binary, options)) << binary;
    }
    const fs::path script = pw::test::gltfValidatorScript();
    if (!script.empty()) {
        const auto r = pw::test::runCommand("node " + quote(script) + " " + quote(out));
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("numErrors: 0"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("numWarnings: 0"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("numInfos:"), std::string::npos) << r.output;
    }
    EXPECT_TRUE(pw::importPatchworkGltf(out) == doc);
    fs::remove_all(dir);
}

// A document with every kind of surface: a closed B-spline tube, an open Catmull-Rom sheet, a
// 2x2-window Bézier surface, plus one loose patch.
pw::Document surfacesDocument() {
    pw::Document doc;
    doc.name = "surfaces";
    auto add = [&](double x, double y, double z) {
        doc.points.push_back(pw::Vec3(x, y, z));
        return static_cast<uint32_t>(doc.points.size() - 1);
    };
    pw::Surface tube;
    tube.basis = pw::Basis::BSpline;
    tube.rows = 5;
    tube.cols = 8;
    tube.closedU = true;
    for (uint32_t i = 0; i < tube.rows; ++i)
        for (uint32_t j = 0; j < tube.cols; ++j) {
            const double a = 2 * 3.14159265358979 * j / tube.cols;
            tube.idx.push_back(add(std::cos(a), std::sin(a), 0.5 * i));
        }
    pw::Surface sheet;
    sheet.basis = pw::Basis::CatmullRom;
    sheet.tension = 0.4;
    sheet.rows = 5;
    sheet.cols = 6;
    for (uint32_t i = 0; i < sheet.rows; ++i)
        for (uint32_t j = 0; j < sheet.cols; ++j) sheet.idx.push_back(add(4.0 + j, i, 0.2 * std::sin(double(i * j))));
    pw::Surface bez;
    bez.basis = pw::Basis::Bezier;
    bez.rows = 7;
    bez.cols = 7;
    for (uint32_t i = 0; i < bez.rows; ++i)
        for (uint32_t j = 0; j < bez.cols; ++j) bez.idx.push_back(add(-8.0 + j, i, 0.1 * (i + j)));
    bez.keepC1 = true;  // seams welded in the mesh, flag kept in the extras
    doc.surfaces = {tube, sheet, bez};
    pw::addNetSurface(doc, 6, 9, pw::NetShape::Torus, pw::Basis::BSpline, pw::Vec3(0.0, -6.0, 0.0), 3.0);  // closed both ways
    pw::Patch patch;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) patch.idx[i * 4 + j] = add(j, i, 5.0 + 0.1 * i * j);
    patch.name = "loose";
    doc.patches = {patch};
    return doc;
}

TEST(Gltf, SurfacesAndAnEmptyDocumentExportValid) {
    const fs::path dir = pw::test::freshTempDir("gltf-surfaces");
    const pw::Document doc = surfacesDocument();
    const pw::Document empty;
    std::vector<fs::path> files;
    for (bool cage : {false, true}) {
        pw::ExportOptions options;
        options.level = 6;
        options.cage = cage;
        const fs::path out = dir / (cage ? "surfaces-cage.glb" : "surfaces.gltf");
        pw::exportGltf(doc, out, options);
        files.push_back(out);
        EXPECT_TRUE(pw::importPatchworkGltf(out) == doc) << out;
        const fs::path none = dir / (cage ? "empty-cage.glb" : "empty.gltf");
        pw::exportGltf(empty, none, options);
        files.push_back(none);
        EXPECT_TRUE(pw::importPatchworkGltf(none) == empty) << none;
    }
    pw::test::expectValidGltf(files);
    fs::remove_all(dir);
}

TEST(Gltf, ValidatorReportsAnInvalidFile) {
    // The wrapper really fails on errors: a primitive with mode -1 and no POSITION min/max.
    const fs::path dir = pw::test::freshTempDir("gltf-invalid");
    const fs::path bad = dir / "bad.gltf";
    std::ofstream(bad) << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36,)"
                          R"("uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],)"
                          R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
                          R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
                          R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":-1}]}],)"
                          R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
    const fs::path script = pw::test::gltfValidatorScript();
    if (!script.empty()) {
        const auto r = pw::test::runCommand("node " + quote(script) + " " + quote(bad));
        EXPECT_NE(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find("numErrors: 0\n"), std::string::npos) << r.output;
    }
    fs::remove_all(dir);
}

TEST(Gltf, ImportOfAForeignGltfIsRefused) {
    const fs::path dir = pw::test::freshTempDir("gltf-foreign");
    const std::string expected =
        "not a Patchwork glTF: it has no patchwork extras (only files exported by Patchwork can be imported as patches)";
    // A JSON glTF and a binary one, written by tinygltf without any extras.
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "someone else";
    tinygltf::Node node;
    node.name = "empty";  // (tinygltf writes a node with no property as null)
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    for (bool binary : {false, true}) {
        const fs::path path = dir / (binary ? "foreign.glb" : "foreign.gltf");
        std::ostringstream out;
        tinygltf::TinyGLTF writer;
        ASSERT_TRUE(writer.WriteGltfSceneToStream(&model, out, true, binary));
        std::ofstream(path, std::ios::binary) << out.str();
        try {
            pw::importPatchworkGltf(path);
            ADD_FAILURE() << "no error for " << path;
        } catch (const pw::InputError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
        }
    }
    // Not glTF at all, and a missing file: InputError naming the file.
    const fs::path junk = dir / "junk.gltf";
    std::ofstream(junk) << "this is not json";
    for (const fs::path& p : {junk, dir / "missing.glb"}) {
        try {
            pw::importPatchworkGltf(p);
            ADD_FAILURE() << "no error for " << p;
        } catch (const pw::InputError& e) {
            EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
        }
    }
    fs::remove_all(dir);
}

TEST(Gltf, ExportErrorsNameThePathAndLeaveNoFile) {
    const pw::Document doc = loadModel("teacup");
    const fs::path dir = pw::test::freshTempDir("gltf-errors");
    EXPECT_THROW(pw::exportGltf(doc, dir / "missing-dir" / "cup.glb", {}), pw::OutputError);
    EXPECT_THROW(pw::exportGltf(doc, dir / "cup.obj", {}), pw::OutputError);
    EXPECT_FALSE(fs::exists(dir / "missing-dir"));
    EXPECT_FALSE(fs::exists(dir / "cup.obj"));
    EXPECT_TRUE(fs::is_empty(dir));
    fs::remove_all(dir);
}

// ---- the command line ----

TEST(GltfCli, ExportWritesAValidFileThatImportsBack) {
    const fs::path dir = pw::test::freshTempDir("gltf-cli");
    const fs::path bin = pw::test::patchworkBinary();
    ASSERT_TRUE(fs::exists(bin)) << bin << " is not built (build the patchwork target, or run scripts/test.sh)";
    const fs::path input = pw::test::dataDir() / "teapot.bpt";
    const fs::path glb = dir / "pot.glb", gltf = dir / "pot.gltf";
    auto r = pw::test::runCommand(quote(bin) + " export " + quote(input) + " -o " + quote(glb) + " --tess 4 --primitives single --cage");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("992 triangles"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("vertices"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(std::to_string(fs::file_size(glb)) + " bytes"), std::string::npos) << r.output;
    r = pw::test::runCommand(quote(bin) + " export " + quote(input) + " -o " + quote(gltf));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("level 16"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("3 primitives (one per connected surface), 3 open and double-sided"), std::string::npos) << r.output;
    checkStructure(glb, pw::MeshGrouping::Single, true, 32, 3);
    checkStructure(gltf, pw::MeshGrouping::Surfaces, false, 32, 3);
    pw::test::expectValidGltf({glb, gltf});
    const pw::Document original = pw::loadBpt(input);
    EXPECT_TRUE(pw::importPatchworkGltf(glb) == original);
    EXPECT_TRUE(pw::importPatchworkGltf(gltf) == original);
    // Re-exporting the imported glTF gives the same document again; without flags, the same file
    // (its options come from its extras); a flag given overrides only itself.
    const fs::path again = dir / "again.glb", same = dir / "same.glb", sameText = dir / "same.gltf";
    r = pw::test::runCommand(quote(bin) + " export " + quote(glb) + " -o " + quote(again) + " --tess 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(pw::importPatchworkGltf(again) == original);
    checkStructure(again, pw::MeshGrouping::Single, true, 32, 3);
    r = pw::test::runCommand(quote(bin) + " export " + quote(glb) + " -o " + quote(same));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(pw::test::readBytes(same), pw::test::readBytes(glb));
    r = pw::test::runCommand(quote(bin) + " export " + quote(gltf) + " -o " + quote(sameText));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(pw::test::readBytes(sameText), pw::test::readBytes(gltf));
    r = pw::test::runCommand(quote(bin) + " convert " + quote(glb) + " " + quote(same));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(pw::test::readBytes(same), pw::test::readBytes(glb));
    r = pw::test::runCommand(quote(bin) + " export " + quote(glb) + " -o " + quote(same) + " --primitives nonsense");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--primitives"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

TEST(GltfCli, UnwritablePathExitsTwoAndLeavesNoFile) {
    const fs::path dir = pw::test::freshTempDir("gltf-cli-unwritable");
    const fs::path bin = pw::test::patchworkBinary();
    ASSERT_TRUE(fs::exists(bin)) << bin << " is not built";
    const fs::path input = pw::test::dataDir() / "teapot.bpt";
    // A missing directory, and a "directory" that is a regular file.
    std::ofstream(dir / "plainfile") << "x";
    for (const fs::path& out : {dir / "no-such-dir" / "pot.glb", dir / "plainfile" / "pot.gltf"}) {
        const auto r = pw::test::runCommand(quote(bin) + " export " + quote(input) + " -o " + quote(out) + " --tess 2");
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(out.string()), std::string::npos) << "the message names the path: " << r.output;
        EXPECT_FALSE(fs::exists(out));
    }
    // Only the plain file is left: no partial or temporary file.
    size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1u);
    fs::remove_all(dir);
}

TEST(GltfCli, BadTessExitsTwo) {
    const fs::path dir = pw::test::freshTempDir("gltf-cli-tess");
    const fs::path bin = pw::test::patchworkBinary();
    ASSERT_TRUE(fs::exists(bin)) << bin << " is not built";
    const fs::path input = pw::test::dataDir() / "teapot.bpt";
    const fs::path out = dir / "pot.glb";
    for (const std::string tess : {"0", "-3", "257", "100000", "abc", "2.5"}) {
        const auto r = pw::test::runCommand(quote(bin) + " export " + quote(input) + " -o " + quote(out) + " --tess " + tess);
        EXPECT_EQ(r.exitCode, 2) << "--tess " << tess << ": " << r.output;
        EXPECT_NE(r.output.find("--tess"), std::string::npos) << "--tess " << tess << ": " << r.output;
        EXPECT_FALSE(fs::exists(out));
    }
    // A missing input file: exit 2 naming it.
    const auto r = pw::test::runCommand(quote(bin) + " export " + quote(dir / "nothing.bpt") + " -o " + quote(out));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("nothing.bpt"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    fs::remove_all(dir);
}

}  // namespace

TEST(Gltf, TheSameDocumentGivesTheSameBytes) {
    // The document is spliced in place of a random marker; the file must not depend on it (its
    // length once set the GLB's JSON padding). 16 exports cover markers of many lengths.
    const pw::Document doc = loadModel("teacup");
    for (bool binary : {true, false}) {
        const std::string first = pw::exportGltfBytes(doc, binary, {2, pw::MeshGrouping::Surfaces, true});
        for (int i = 0; i < 16; ++i) EXPECT_EQ(pw::exportGltfBytes(doc, binary, {2, pw::MeshGrouping::Surfaces, true}), first);
    }
}

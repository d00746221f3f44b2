// Cubic Bézier triangles in the document: the .patchwork round trip (optional "triangles"; files
// without triangles are written exactly as before), and the pool walkers that must know about
// triangles (compaction, merging, used-point masks, undo).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/construct/model_builders.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/io/document_io.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/model/edit_history.hpp"
#include "core/model/join_detect.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/select/picking.hpp"
#include "core/select/selection.hpp"
#include "support.hpp"

using namespace pw;

namespace {

// A flat quad patch (pool 0..15) and two triangles sharing an edge, one with a tess override.
Document docWithTriangles() {
    Document d;
    d.name = "tri";
    for (int i = 0; i < 16; ++i) d.points.push_back(Vec3(i % 4, i / 4, 0.0));
    for (int i = 0; i < 14; ++i) d.points.push_back(Vec3(0.1 * i, -1.0 - 0.05 * i, 0.25 * (i % 3)));
    Patch p;
    for (uint32_t k = 0; k < 16; ++k) p.idx[k] = k;
    d.patches.push_back(p);
    TrianglePatch a, b;
    a.idx = {16, 17, 18, 19, 20, 21, 22, 23, 24, 25};
    a.name = "first";
    b.idx = {26, 27, 28, 29, 24, 23, 22, 19, 17, 16};  // shares nothing but a few points: indices only
    b.tessOverride = std::array<float, 4>{3.0f, 5.5f, 7.0f, 2.0f};
    d.triangles = {a, b};
    return d;
}

std::string readFile(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

}  // namespace

TEST(TriangleFormat, RoundTripIsExact) {
    const Document doc = docWithTriangles();
    const std::string text = serializeDocument(doc);
    const Document again = parseDocument(text, "tri.patchwork");
    EXPECT_EQ(again, doc);
    EXPECT_EQ(serializeDocument(again), text);
    const nlohmann::json j = nlohmann::json::parse(text);
    ASSERT_EQ(j["triangles"].size(), 2u);
    EXPECT_EQ(j["triangles"][0]["idx"].size(), 10u);
    EXPECT_FALSE(j["triangles"][0].contains("tess"));
    EXPECT_EQ(j["triangles"][1]["tess"].size(), 4u);
    EXPECT_EQ(documentFromJson(documentToJson(doc), "tri"), doc);

    const auto dir = test::freshTempDir("trisave");
    saveDocument(doc, dir / "tri.patchwork");
    EXPECT_EQ(loadDocument(dir / "tri.patchwork"), doc);
    saveDocument(doc, dir / "tri.glb");  // the document travels in the glTF extras too
    EXPECT_EQ(loadDocument(dir / "tri.glb"), doc);
}

TEST(TriangleFormat, DocumentsWithoutTrianglesAreWrittenAsBefore) {
    // A file saved before triangles existed re-serialises to the same bytes, with no new key.
    const auto file = test::testsDir() / "corpus" / "good" / "teacup.patchwork";
    const std::string before = readFile(file);
    const Document doc = loadDocument(file);
    EXPECT_TRUE(doc.triangles.empty());
    const std::string after = serializeDocument(doc);
    EXPECT_EQ(after.find("triangles"), std::string::npos);
    EXPECT_EQ(after, before);
}

TEST(TriangleFormat, ErrorsNameTheField) {
    auto message = [](const std::string& text) {
        try {
            parseDocument(text, "t.patchwork");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string head = R"({"format":"patchwork","version":1,"points":[[0,0,0],[1,0,0]],"patches":[],)";
    EXPECT_NE(message(head + R"("triangles":[{"idx":[0,1,0,1,0,1,0,1,0,2]}]})").find("triangles[0].idx[9]"), std::string::npos);
    EXPECT_NE(message(head + R"("triangles":[{"idx":[0,1,0,1,0,1,0,1,0]}]})").find("expected an array of 10"), std::string::npos);
    EXPECT_NE(message(head + R"("triangles":[{"idx":[0,1,0,1,0,1,0,1,0,1],"tess":[1,2,3,0]}]})").find("triangles[0].tess[3]"),
              std::string::npos);
    EXPECT_NE(message(head + R"("triangles":[{"idx":[0,1,0,1,0,1,0,1,0,1e0]}]})").find("triangles[0].idx[9]"), std::string::npos);
}

TEST(TriangleDocument, CompactPoolKeepsAndRemapsTrianglePoints) {
    Document doc = docWithTriangles();
    // Unused points in front of the triangles' points: compaction must renumber the triangles.
    doc.points.insert(doc.points.begin() + 16, 3, Vec3(9, 9, 9));
    for (TrianglePatch& t : doc.triangles)
        for (uint32_t& i : t.idx) i += 3;
    std::vector<std::array<Vec3, 10>> before;
    for (const TrianglePatch& t : doc.triangles) {
        std::array<Vec3, 10> pts;
        for (int k = 0; k < 10; ++k) pts[k] = doc.points[t.idx[k]];
        before.push_back(pts);
    }
    compactPool(doc);
    EXPECT_EQ(doc.points.size(), 30u);
    for (size_t t = 0; t < doc.triangles.size(); ++t)
        for (int k = 0; k < 10; ++k) {
            ASSERT_LT(doc.triangles[t].idx[k], doc.points.size());
            EXPECT_EQ(doc.points[doc.triangles[t].idx[k]], before[t][k]);
        }
    // Deleting the only quad keeps every triangle point.
    deletePatch(doc, 0);
    EXPECT_EQ(doc.points.size(), 14u);
    for (size_t t = 0; t < doc.triangles.size(); ++t)
        for (int k = 0; k < 10; ++k) EXPECT_EQ(doc.points[doc.triangles[t].idx[k]], before[t][k]);
}

TEST(TriangleDocument, MergeCoincidentPointsAndUsedMaskSeeTriangles) {
    Document doc = docWithTriangles();
    doc.points.push_back(doc.points[20]);  // a duplicate used only by a triangle
    doc.triangles[0].idx[4] = uint32_t(doc.points.size() - 1);
    mergeCoincidentPoints(doc);
    EXPECT_EQ(doc.points.size(), 30u);
    EXPECT_EQ(doc.triangles[0].idx[4], 20u);
    const std::vector<bool> used = usedPointMask(doc);
    for (const TrianglePatch& t : doc.triangles)
        for (uint32_t i : t.idx) EXPECT_TRUE(used[i]);
}

TEST(TriangleDocument, UndoRestoresTriangleChanges) {
    Document doc = docWithTriangles();
    EditHistory history(16);
    Document before = doc;
    doc.triangles.pop_back();
    history.commit(before, doc, "delete triangle");
    history.undo(doc);
    EXPECT_EQ(doc, docWithTriangles());
    history.redo(doc);
    EXPECT_EQ(doc.triangles.size(), 1u);
}

TEST(TriangleFormat, BptRefusesTrianglesInsteadOfDroppingThem) {
    const auto dir = test::freshTempDir("tribpt");
    try {
        saveDocument(docWithTriangles(), dir / "t.bpt");
        ADD_FAILURE() << "no error";
    } catch (const OutputError& e) {
        EXPECT_NE(std::string(e.what()).find("triangles"), std::string::npos) << e.what();
    }
}

TEST(TriangleCli, InfoCountsTriangles) {
    const auto dir = test::freshTempDir("triinfo");
    const auto file = dir / "dome.patchwork";
    saveDocument(makeTriangleDome(), file);
    const std::string bin = "'" + test::patchworkBinary().string() + "'";
    auto r = test::runCommand(bin + " info '" + file.string() + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("triangles   6"), std::string::npos) << r.output;
    r = test::runCommand(bin + " info --json '" + file.string() + "' 2>/dev/null");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j["triangles"], 6);
    EXPECT_EQ(j["points"], 37);
}

TEST(TriangleOps, AddedTriangleIsFlatWithItsNormalUp) {
    for (bool zUp : {true, false}) {
        Document doc = builtinTeapot();
        const size_t before = doc.points.size();
        const Vec3 c(1.0, 2.0, 3.0);
        const uint32_t t = addTriangle(doc, c, 2.0, zUp);
        ASSERT_EQ(t, 0u);
        EXPECT_EQ(doc.points.size(), before + 10);
        const Net10 net = gatherTriangleNet(doc, doc.triangles[t].idx);
        const TriPoint mid = evaluateTriangle(net, 1.0 / 3.0, 1.0 / 3.0);
        EXPECT_NEAR(glm::length(mid.p - c), 0.0, 1e-12);  // the centroid is the centre
        EXPECT_NEAR(mid.n[zUp ? 2 : 1], 1.0, 1e-12) << "normal up (+z, or +y when y is up)";
        // Equilateral with side 2: the corners are 2 apart.
        const Vec3 U = evaluateTriangle(net, 1, 0).p, V = evaluateTriangle(net, 0, 1).p, W = evaluateTriangle(net, 0, 0).p;
        EXPECT_NEAR(glm::length(U - V), 2.0, 1e-12);
        EXPECT_NEAR(glm::length(V - W), 2.0, 1e-12);
        EXPECT_NEAR(glm::length(W - U), 2.0, 1e-12);
    }
}

TEST(TriangleOps, PickingFindsTheTriangleUnderTheRay) {
    Document doc;
    addTriangle(doc, Vec3(0.0), 2.0);
    addTriangle(doc, Vec3(5.0, 0.0, 0.0), 2.0);
    const Ray down{Vec3(5.1, 0.1, 10.0), Vec3(0.0, 0.0, -1.0)};
    const auto hit = pickSurface(doc, down);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->triangle, 1);
    EXPECT_EQ(hit->patch, -1);
    EXPECT_EQ(hit->instance, -1);
    EXPECT_NEAR(hit->t, 10.0, 1e-9);
    EXPECT_GT(hit->u, 0.0);
    EXPECT_GT(hit->v, 0.0);
    EXPECT_LT(hit->u + hit->v, 1.0);
    EXPECT_FALSE(pickSurface(doc, Ray{Vec3(2.5, 0.0, 10.0), Vec3(0.0, 0.0, -1.0)}));  // between them
    // A quad patch in front of the triangle wins: the nearest hit counts.
    addFlatPatch(doc, Vec3(5.0, 0.0, 1.0), 3.0);
    const auto front = pickSurface(doc, down);
    ASSERT_TRUE(front);
    EXPECT_EQ(front->patch, 0);
    EXPECT_EQ(front->triangle, -1);
}

TEST(TriangleOps, DuplicateAndDeleteKeepThePoolTidy) {
    Document doc;
    addTriangle(doc, Vec3(0.0), 1.0);
    const uint32_t copy = duplicateTriangle(doc, 0, Vec3(0.0, 0.0, 2.0));
    ASSERT_EQ(doc.triangles.size(), 2u);
    EXPECT_EQ(doc.points.size(), 20u);
    for (int k = 0; k < 10; ++k)
        EXPECT_EQ(doc.points[doc.triangles[copy].idx[size_t(k)]], doc.points[doc.triangles[0].idx[size_t(k)]] + Vec3(0.0, 0.0, 2.0));
    Selection sel;
    sel.triangle = 1;
    EXPECT_FALSE(sel.empty());
    EXPECT_NEAR(selectionCentroid(doc, sel).z, 2.0, 1e-12);
    deleteTriangle(doc, 0);
    EXPECT_EQ(doc.triangles.size(), 1u);
    EXPECT_EQ(doc.points.size(), 10u);
    for (uint32_t i : doc.triangles[0].idx) EXPECT_NEAR(doc.points[i].z, 2.0, 1e-12);
    clampSelection(sel, doc);
    EXPECT_EQ(sel.triangle, -1);
    EXPECT_THROW(deleteTriangle(doc, 3), EditError);
    EXPECT_THROW(duplicateTriangle(doc, 1, Vec3(0.0)), EditError);
    EXPECT_EQ(doc.triangles.size(), 1u);
}

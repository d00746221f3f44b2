// File formats: tea-set import (counts, shared points, detected joins), .patchwork round trips that
// are bit-identical, .bpt round trips, version refusal, and the built-in teapot.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <random>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/limits.hpp"
#include "core/edit/edit_session.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/document_io.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/model/join_detect.hpp"
#include "core/tess/tess_presets.hpp"
#include "support.hpp"

using namespace pw;

namespace {

struct JoinCounts {
    size_t c0 = 0, c1 = 0, g1 = 0;
};

JoinCounts countJoins(const Document& doc) {
    JoinCounts c;
    for (const Join& j : doc.joins) {
        if (j.continuity == Continuity::C0) ++c.c0;
        if (j.continuity == Continuity::C1) ++c.c1;
        if (j.continuity == Continuity::G1) ++c.g1;
    }
    return c;
}

// Every bit of every double and float the same (operator== would let -0.0 equal 0.0).
void expectBitIdentical(const Document& a, const Document& b) {
    EXPECT_TRUE(a == b);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (size_t i = 0; i < a.points.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(std::bit_cast<uint64_t>(a.points[i][c]), std::bit_cast<uint64_t>(b.points[i][c])) << "point " << i << " axis " << c;
    ASSERT_EQ(a.joins.size(), b.joins.size());
    for (size_t i = 0; i < a.joins.size(); ++i)
        EXPECT_EQ(std::bit_cast<uint64_t>(a.joins[i].alpha), std::bit_cast<uint64_t>(b.joins[i].alpha));
    EXPECT_EQ(std::memcmp(&a.camera.target, &b.camera.target, sizeof a.camera.target), 0);
}

double randomDouble(std::mt19937_64& rng) {
    // Mix of "nice" decimals, wide-range magnitudes and raw random mantissas.
    std::uniform_int_distribution<int> kind(0, 3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    switch (kind(rng)) {
        case 0:
            return std::round(unit(rng) * 1e4) / 1e4;
        case 1:
            return unit(rng) * std::pow(10.0, std::uniform_int_distribution<int>(-12, 8)(rng));
        case 2: {
            // Random bits with the exponent confined to ±1e9.
            uint64_t bits = rng();
            double d = std::bit_cast<double>((bits & 0x800FFFFFFFFFFFFFull) | (uint64_t(1023 + int(bits % 58) - 30) << 52));
            return d;
        }
        default:
            return unit(rng);
    }
}

float randomLevel(std::mt19937_64& rng) { return std::uniform_real_distribution<float>(limits::kMinTessLevel, limits::kMaxTessLevel)(rng); }

// A document with every field away from its default: patches with overrides and names, surfaces
// of each basis, joins of each continuity, and all settings changed.
Document randomDocument(uint64_t seed) {
    std::mt19937_64 rng(seed);
    Document doc;
    doc.name = "random \"doc\" é " + std::to_string(seed);
    const size_t nPoints = 200;
    for (size_t i = 0; i < nPoints; ++i) doc.points.push_back(Vec3(randomDouble(rng), randomDouble(rng), randomDouble(rng)));
    doc.points.push_back(Vec3(-0.0, 0.0, -0.0));
    doc.points.push_back(Vec3(1e9, -1e9, std::numeric_limits<double>::denorm_min()));
    std::uniform_int_distribution<uint32_t> pick(0, static_cast<uint32_t>(doc.points.size() - 1));
    for (int p = 0; p < 12; ++p) {
        Patch patch;
        for (auto& i : patch.idx) i = pick(rng);
        patch.basis = static_cast<Basis>(p % 3);
        patch.tension = 0.5 + std::uniform_real_distribution<double>(-0.25, 0.25)(rng);
        patch.name = p % 2 ? "patch " + std::to_string(p) : "";
        if (p % 3 == 1) {
            std::array<float, 6> t;
            for (auto& f : t) f = randomLevel(rng);
            t[0] = 1.0f;
            t[5] = 64.0f;
            patch.tessOverride = t;
        }
        doc.patches.push_back(patch);
    }
    for (int s = 0; s < 3; ++s) {
        Surface surf;
        surf.rows = 4 + s * 3;
        surf.cols = 7;
        surf.basis = static_cast<Basis>(s);
        surf.tension = 0.25 + s * 0.1;
        surf.closedU = s == 1;
        surf.closedV = s == 2;
        surf.name = "surface" + std::to_string(s);
        for (uint32_t k = 0; k < surf.rows * surf.cols; ++k) surf.idx.push_back(pick(rng));
        doc.surfaces.push_back(surf);
    }
    for (int j = 0; j < 9; ++j) {
        Join jn;
        jn.patchA = j;
        jn.edgeA = static_cast<Edge>(j % 4);
        jn.patchB = j + 3;
        jn.edgeB = static_cast<Edge>((j + 1) % 4);
        jn.reversed = j % 2 == 0;
        jn.continuity = static_cast<Continuity>(j % 3);
        jn.alpha = jn.continuity == Continuity::G1 ? std::uniform_real_distribution<double>(0.1, 10.0)(rng) : 1.0;
        doc.joins.push_back(jn);
    }
    TessSettings& t = doc.tess;
    t.outer = {randomLevel(rng), randomLevel(rng), randomLevel(rng), randomLevel(rng)};
    t.inner = {randomLevel(rng), randomLevel(rng)};
    t.linked = false;
    t.spacing = Spacing::FractionalOdd;
    t.adaptive = AdaptiveMode::ScreenSpace;
    t.distanceNear = 0.1f;
    t.distanceFar = 123.456f;
    t.targetPixels = 3.3f;
    t.maxLevel = 32.5f;
    t.cullBackfaces = true;
    t.cullOffscreen = false;
    DisplaySettings& d = doc.display;
    d.shading = ShadingMode::MeanCurvature;
    d.showGrid = false;
    d.showWireframe = true;
    d.showNormals = true;
    d.showBoundaries = true;
    d.normalLength = 0.3f;
    d.lightDir = {-0.1f, 0.7f, 1.0f / 3.0f};
    d.background = {0.9f, 0.01f, 1.0f};
    Camera& c = doc.camera;
    c.target = {randomDouble(rng), randomDouble(rng), 0.1 + 0.2};
    c.distance = 12.345678901234567;
    c.yawDeg = -123.4;
    c.pitchDeg = 89.999;
    c.fovYDeg = 1.0 / 3.0;
    c.orthographic = true;
    c.zUp = false;
    return doc;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Tea set import

TEST(Bpt, TeapotCountsAndJoins) {
    const Document doc = loadBpt(test::dataDir() / "teapot.bpt");
    EXPECT_EQ(doc.name, "teapot");
    EXPECT_EQ(doc.patches.size(), 32u);
    EXPECT_EQ(doc.points.size(), 290u);
    // 52 boundary curves are shared by exactly two patches; 8 degenerate ones get no join.
    ASSERT_EQ(doc.joins.size(), 52u);
    const JoinCounts c = countJoins(doc);
    // The teapot's seams are exactly proportional in its decimal data: 46 C1, and 6 G1
    // (rim to body α = 4, lid knob α = 1/4).
    EXPECT_EQ(c.c1, 46u);
    EXPECT_EQ(c.g1, 6u);
    EXPECT_EQ(c.c0, 0u);
    std::map<double, int> alphas;
    for (const Join& j : doc.joins) {
        EXPECT_LT(j.patchA, j.patchB);
        if (j.continuity == Continuity::G1) ++alphas[std::round(j.alpha * 1e6) / 1e6];
        if (j.continuity == Continuity::C1) {
            EXPECT_EQ(j.alpha, 1.0);
        }
        // Shared edge: the same four pool indices.
        for (int k = 0; k < 4; ++k)
            EXPECT_EQ(doc.patches[j.patchA].idx[edgeSlot(j.edgeA, k)],
                      doc.patches[j.patchB].idx[edgeSlot(j.edgeB, j.reversed ? 3 - k : k)]);
    }
    EXPECT_EQ(alphas[4.0], 4);
    EXPECT_EQ(alphas[0.25], 2);

    // Every boundary curve: 8 degenerate, 2×52 in joins, 16 open.
    int degenerate = 0, joined = 0;
    for (uint32_t p = 0; p < doc.patches.size(); ++p)
        for (int e = 0; e < 4; ++e) {
            const Edge edge = static_cast<Edge>(e);
            bool same = true;
            for (int k = 1; k < 4; ++k)
                same = same && doc.points[doc.patches[p].idx[edgeSlot(edge, k)]] == doc.points[doc.patches[p].idx[edgeSlot(edge, 0)]];
            degenerate += same;
            for (const Join& j : doc.joins) joined += (j.patchA == p && j.edgeA == edge) || (j.patchB == p && j.edgeB == edge);
        }
    EXPECT_EQ(degenerate, 8);
    EXPECT_EQ(joined, 104);
    EXPECT_EQ(128 - degenerate - joined, 16);

    // Camera framed on the model.
    const Bounds b = computeBounds(doc.points);
    EXPECT_DOUBLE_EQ(doc.camera.target[0], 0.5 * (b.min.x + b.max.x));
    EXPECT_DOUBLE_EQ(doc.camera.target[2], 0.5 * (b.min.z + b.max.z));
    EXPECT_NEAR(doc.camera.distance, 2.2 * b.diagonal(), 1e-9);
    EXPECT_EQ(doc.tess, TessSettings{});
}

TEST(Bpt, TeacupAndTeaspoonCounts) {
    const Document cup = loadBpt(test::dataDir() / "teacup.bpt");
    EXPECT_EQ(cup.patches.size(), 26u);
    EXPECT_EQ(cup.points.size(), 251u);
    EXPECT_EQ(cup.joins.size(), 46u);
    const JoinCounts cc = countJoins(cup);
    EXPECT_EQ(cc.c1, 26u);
    EXPECT_EQ(cc.g1, 16u);
    EXPECT_EQ(cc.c0, 4u);

    const Document spoon = loadBpt(test::dataDir() / "teaspoon.bpt");
    EXPECT_EQ(spoon.patches.size(), 16u);
    EXPECT_EQ(spoon.points.size(), 148u);
    EXPECT_EQ(spoon.joins.size(), 28u);
    // The teaspoon's decimals (6 digits) are smooth only to ~3e-5 of its size: every seam is G1
    // at the default tolerance, and those not exact to 1e-6 become C0 when asked for that.
    EXPECT_EQ(countJoins(spoon).g1, 28u);
    JoinDetectOptions strict;
    strict.relativeTolerance = 1e-6;
    strict.c1RatioTolerance = 1e-6;
    size_t strictG1 = 0;
    for (const Join& j : detectJoins(spoon, strict)) strictG1 += j.continuity == Continuity::G1;
    EXPECT_LT(strictG1, 28u);
}

TEST(Bpt, DetectedSmoothJoinsSatisfyTheirConstraintWithinTolerance) {
    for (const char* name : {"teapot.bpt", "teacup.bpt", "teaspoon.bpt"}) {
        const Document doc = loadBpt(test::dataDir() / name);
        const double tol = JoinDetectOptions{}.relativeTolerance * modelSize(doc);
        for (const Join& j : doc.joins) {
            if (j.continuity == Continuity::C0) continue;
            const Patch& A = doc.patches[j.patchA];
            const Patch& B = doc.patches[j.patchB];
            for (int k = 0; k < 4; ++k) {
                const int kb = j.reversed ? 3 - k : k;
                const Vec3 a = doc.points[A.idx[edgeSlot(j.edgeA, k, 0)]] - doc.points[A.idx[edgeSlot(j.edgeA, k, 1)]];
                const Vec3 b = doc.points[B.idx[edgeSlot(j.edgeB, kb, 1)]] - doc.points[B.idx[edgeSlot(j.edgeB, kb, 0)]];
                EXPECT_LE(glm::length(b - j.alpha * a), tol) << name;
            }
        }
    }
}

TEST(JoinDetect, SyntheticC1G1C0AndReversed) {
    // Two flat patches side by side along x, sharing column j=3 of A with column j=0 of B.
    auto build = [](double scaleB, bool flipB, double kink) {
        Document doc;
        Patch a, b;
        for (int i = 0; i < 4; ++i)
            for (int jj = 0; jj < 4; ++jj) {
                a.idx[i * 4 + jj] = static_cast<uint32_t>(doc.points.size());
                doc.points.push_back(Vec3(jj, i, 0));
            }
        for (int i = 0; i < 4; ++i)
            for (int jj = 0; jj < 4; ++jj) {
                const int row = flipB ? 3 - i : i;
                if (jj == 0) {
                    b.idx[row * 4] = a.idx[i * 4 + 3];
                } else {
                    b.idx[row * 4 + jj] = static_cast<uint32_t>(doc.points.size());
                    doc.points.push_back(Vec3(3 + jj * scaleB, i, jj == 1 ? kink * i : 0.0));
                }
            }
        doc.patches = {a, b};
        return detectJoins(doc);
    };
    auto c1 = build(1.0, false, 0.0);
    ASSERT_EQ(c1.size(), 1u);
    EXPECT_EQ(c1[0].continuity, Continuity::C1);
    EXPECT_EQ(c1[0].edgeA, Edge::U1);
    EXPECT_EQ(c1[0].edgeB, Edge::U0);
    EXPECT_FALSE(c1[0].reversed);

    auto g1 = build(2.5, true, 0.0);
    ASSERT_EQ(g1.size(), 1u);
    EXPECT_EQ(g1[0].continuity, Continuity::G1);
    EXPECT_NEAR(g1[0].alpha, 2.5, 1e-12);
    EXPECT_TRUE(g1[0].reversed);

    auto c0 = build(1.0, false, 0.3);
    ASSERT_EQ(c0.size(), 1u);
    EXPECT_EQ(c0[0].continuity, Continuity::C0);
}

TEST(JoinDetect, MergeCoincidentPointsRewritesIndices) {
    Document doc;
    doc.points = {Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(-0.0, 0, 0), Vec3(1, 2, 3), Vec3(1, 2, 3.0000000000000004)};
    Patch p;
    for (int k = 0; k < 16; ++k) p.idx[k] = k % 5;
    doc.patches = {p};
    Surface s;
    s.rows = 1;
    s.cols = 5;
    s.idx = {4, 3, 2, 1, 0};
    doc.surfaces = {s};
    mergeCoincidentPoints(doc);
    ASSERT_EQ(doc.points.size(), 3u);
    EXPECT_EQ(doc.patches[0].idx[2], 0u);
    EXPECT_EQ(doc.patches[0].idx[3], 1u);
    EXPECT_EQ(doc.patches[0].idx[4], 2u);
    EXPECT_EQ(doc.surfaces[0].idx, (std::vector<uint32_t>{2, 1, 0, 1, 0}));
}

TEST(Bpt, CrlfCommasAndBlankTailAreAccepted) {
    std::string text = "1\r\n3 3\r\n";
    for (int k = 0; k < 16; ++k) text += std::to_string(k % 4) + ",\t" + std::to_string(k / 4) + " +0.5e0\r\n";
    text += "\r\n\n";
    const Document doc = parseBpt(text, "dir/square.bpt");
    EXPECT_EQ(doc.name, "square");
    EXPECT_EQ(doc.points.size(), 16u);
    EXPECT_EQ(doc.points[5], Vec3(1, 1, 0.5));
}

TEST(Bpt, RoundTripIsExact) {
    for (const char* name : {"teapot.bpt", "teacup.bpt", "teaspoon.bpt"}) {
        const Document doc = loadBpt(test::dataDir() / name);
        const std::string text = formatBpt(doc);
        const Document again = parseBpt(text, name);
        expectBitIdentical(doc, again);
        EXPECT_EQ(formatBpt(again), text);
    }
    // Arbitrary doubles survive too.
    std::mt19937_64 rng(5);
    Document doc;
    for (int k = 0; k < 32; ++k) doc.points.push_back(Vec3(randomDouble(rng), randomDouble(rng), randomDouble(rng)));
    Patch a, b;
    for (int k = 0; k < 16; ++k) a.idx[k] = k, b.idx[k] = 16 + k;
    doc.patches = {a, b};
    doc.name = "r";
    const Document again = parseBpt(formatBpt(doc), "r.bpt");
    expectBitIdentical(doc, Document{again.name, again.points, again.patches, {}, {}, doc.tess, doc.display, doc.camera});
}

TEST(Bpt, SplineSurfacesAreRefused) {
    Document doc = randomDocument(3);
    EXPECT_THROW(formatBpt(doc), InputError);
    const auto dir = test::freshTempDir("bptsave");
    EXPECT_THROW(saveDocument(doc, dir / "x.bpt"), OutputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "x.bpt"));
}

// ---------------------------------------------------------------------------------------------
// .patchwork

TEST(PatchworkFormat, NlohmannDoublesRoundTripBitExact) {
    std::mt19937_64 rng(42);
    nlohmann::json arr = nlohmann::json::array();
    std::vector<double> values;
    for (int i = 0; i < 200000; ++i) {
        double d = std::bit_cast<double>(rng());
        if (!std::isfinite(d)) continue;
        values.push_back(d);
    }
    for (int i = 0; i < 20000; ++i) values.push_back(randomDouble(rng));
    values.push_back(std::numeric_limits<double>::denorm_min());
    values.push_back(std::numeric_limits<double>::max());
    values.push_back(-0.0);
    for (double d : values) arr.push_back(d);
    const auto back = nlohmann::json::parse(arr.dump());
    ASSERT_EQ(back.size(), values.size());
    for (size_t i = 0; i < values.size(); ++i)
        ASSERT_EQ(std::bit_cast<uint64_t>(back[i].get<double>()), std::bit_cast<uint64_t>(values[i])) << arr[i].dump();
}

TEST(PatchworkFormat, TeapotRoundTripIsBitIdentical) {
    const Document doc = loadBpt(test::dataDir() / "teapot.bpt");
    const std::string text = serializeDocument(doc);
    const Document again = parseDocument(text, "teapot.patchwork");
    expectBitIdentical(doc, again);
    EXPECT_EQ(serializeDocument(again), text);

    const auto dir = test::freshTempDir("pwsave");
    saveDocument(doc, dir / "teapot.patchwork");
    expectBitIdentical(doc, loadDocument(dir / "teapot.patchwork"));
}

TEST(PatchworkFormat, RandomDocumentRoundTripIsBitIdentical) {
    for (uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
        const Document doc = randomDocument(seed);
        const Document again = parseDocument(serializeDocument(doc), "random.patchwork");
        expectBitIdentical(doc, again);
        // Also straight through the JSON value (used by the glTF extras).
        expectBitIdentical(doc, documentFromJson(documentToJson(doc), "random"));
    }
}

TEST(PatchworkFormat, EveryFieldIsWritten) {
    const nlohmann::json j = nlohmann::json::parse(serializeDocument(randomDocument(9)));
    EXPECT_EQ(j["format"], "patchwork");
    EXPECT_EQ(j["version"], 1);
    EXPECT_EQ(j["patches"][1]["tess"].size(), 6u);
    EXPECT_FALSE(j["patches"][0].contains("tess"));
    for (const char* k : {"rows", "cols", "idx", "basis", "tension", "closedU", "closedV", "name"})
        EXPECT_TRUE(j["surfaces"][0].contains(k)) << k;
    for (const char* k : {"a", "edgeA", "b", "edgeB", "reversed", "continuity", "alpha"}) EXPECT_TRUE(j["joins"][0].contains(k)) << k;
    EXPECT_EQ(j["tess"].size(), 11u);
    EXPECT_EQ(j["display"].size(), 8u);
    EXPECT_EQ(j["camera"].size(), 7u);
    EXPECT_EQ(j["display"]["normalLength"].dump(), "0.3");  // floats written in their short form
}

TEST(PatchworkFormat, OptionalFieldsDefault) {
    const Document doc = parseDocument(R"({"format":"patchwork","version":1,"points":[[0,0,0]],
        "patches":[{"idx":[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]}]})",
                                       "min.patchwork");
    EXPECT_EQ(doc.patches.size(), 1u);
    EXPECT_EQ(doc.patches[0], Patch{});
    EXPECT_EQ(doc.tess, TessSettings{});
    EXPECT_EQ(doc.display, DisplaySettings{});
    EXPECT_EQ(doc.camera, Camera{});
    EXPECT_TRUE(doc.joins.empty());
}

TEST(PatchworkFormat, NewerVersionIsRefused) {
    Document doc = loadBpt(test::dataDir() / "teapot.bpt");
    nlohmann::json j = documentToJson(doc);
    j["version"] = Document::kFormatVersion + 1;
    try {
        parseDocument(j.dump(), "future.patchwork");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "version");
        EXPECT_NE(std::string(e.what()).find("was written by a newer Patchwork (format version 2); this build reads version 1"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("future.patchwork"), std::string::npos);
    }
}

TEST(PatchworkFormat, ErrorsNameFieldOrLine) {
    auto message = [](const std::string& text) -> std::pair<std::string, int> {
        try {
            parseDocument(text, "t.patchwork");
        } catch (const InputError& e) {
            return {e.field(), e.line()};
        }
        return {"<no error>", -1};
    };
    const std::string head = R"({"format":"patchwork","version":1,"points":[[0,0,0],[1,1,1]],)";
    EXPECT_EQ(message(head + R"("patches":[{"idx":[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,2]}]})").first, "patches[0].idx[15]");
    EXPECT_EQ(message(head + R"("patches":[{"idx":[0,0,0,0,0,0,0,-1,0,0,0,0,0,0,0,0]}]})").first, "patches[0].idx[7]");
    EXPECT_EQ(message(head + R"("patches":[{"idx":[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]}]})").first, "patches[0].idx");
    EXPECT_EQ(message(head + R"("patches":[{"idx":"none"}]})").first, "patches[0].idx");
    EXPECT_EQ(message(head + R"("patches":[{}]})").first, "patches[0].idx");
    EXPECT_EQ(message(head + R"("patches":[], "tess":{"outer":[1,2,3,100]}})").first, "tess.outer[3]");
    EXPECT_EQ(message(head + R"("patches":[], "camera":{"zUp":1}})").first, "camera.zUp");
    EXPECT_EQ(message(head + R"("patches":[], "joins":[{"a":0,"edgeA":"u0","b":1,"edgeB":"v0"}]})").first, "joins[0].a");
    EXPECT_EQ(message(R"({"format":"patchwork","version":1,"points":[[0,0,1e10]],"patches":[]})").first, "points[0][2]");
    EXPECT_EQ(message(R"({"format":"patchwork","version":1,"patches":[]})").first, "points");
    EXPECT_EQ(message(R"({"format":"other","version":1})").first, "format");
    EXPECT_EQ(message("{\n\"format\": \"patchwork\",\n\"version\": 1,\n\"points\": [[0,0,0]],,\n}").second, 4);
    EXPECT_EQ(message("{\n\"format\": \"patchwork\",\n\"version\": 1,\n\"points\": [[0,0,").second, 4);
}

TEST(PatchworkFormat, DeepNestingIsAnErrorNotACrash) {
    const std::string deep = std::string(200000, '[') + std::string(200000, ']');
    EXPECT_THROW(parseDocument(deep, "deep.patchwork"), InputError);
    try {
        parseDocument("{\n\"name\": \"[[[[\",\n\"x\":" + std::string(100, '[') + "\n", "deep.patchwork");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 3);  // brackets inside strings do not count
        EXPECT_NE(e.reason().find("nested"), std::string::npos) << e.what();
    }
}

// ---------------------------------------------------------------------------------------------
// Built-in teapot and dispatch by extension

TEST(DocumentIo, BuiltinTeapotEqualsTheDataFile) {
    Document builtin = builtinTeapot();
    EXPECT_EQ(builtin.name, "teapot");
    Document file = loadBpt(test::dataDir() / "teapot.bpt");
    file.name = builtin.name;
    EXPECT_TRUE(builtin == file);
}

TEST(DocumentIo, UnknownExtensionNamesSupportedOnes) {
    try {
        loadDocument("model.fbx");
        FAIL();
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("model.fbx"), std::string::npos);
        EXPECT_NE(m.find(".patchwork"), std::string::npos);
        EXPECT_NE(m.find(".bpt"), std::string::npos);
        EXPECT_NE(m.find(".glb"), std::string::npos);
    }
    const auto dir = test::freshTempDir("ext");
    EXPECT_THROW(saveDocument(builtinTeapot(), dir / "x.fbx"), OutputError);
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(DocumentIo, BptSaveAndLoadByExtension) {
    const auto dir = test::freshTempDir("bptio");
    const Document doc = builtinTeapot();
    saveDocument(doc, dir / "pot.BPT");
    Document again = loadDocument(dir / "pot.BPT");
    EXPECT_EQ(again.name, "pot");
    again.name = doc.name;
    EXPECT_TRUE(again == doc);
}

TEST(DocumentIo, GltfRoundTripRestoresTheDocument) {
    const auto dir = test::freshTempDir("gltfio");
    for (const Document& doc : {builtinTeapot(), randomDocument(7)}) {
        for (const char* name : {"m.glb", "m.gltf"}) {
            SCOPED_TRACE(name);
            // Spline surfaces and every setting travel in the extras; the mesh is only a view.
            saveDocument(doc, dir / name);
            expectBitIdentical(doc, loadDocument(dir / name));
        }
    }
}

// tess.cullFar (issue 41: the notes' level 0 beyond the far distance) round-trips, and is written
// only when on, so files saved before it stay byte for byte as they were.
TEST(PatchworkFormat, CullFarRoundTripsAndIsWrittenOnlyWhenOn) {
    Document doc = builtinTeapot();
    EXPECT_EQ(serializeDocument(doc).find("cullFar"), std::string::npos);
    doc.tess.cullFar = true;
    const std::string text = serializeDocument(doc);
    EXPECT_NE(text.find("\"cullFar\""), std::string::npos);
    EXPECT_TRUE(parseDocument(text, "t.patchwork").tess.cullFar);
    // tess.heightDetail likewise, written only when off.
    EXPECT_EQ(text.find("heightDetail"), std::string::npos);
    doc.tess.heightDetail = false;
    const std::string kept = serializeDocument(doc);
    EXPECT_EQ(nlohmann::json::parse(kept)["tess"]["heightDetail"], false);
    EXPECT_FALSE(parseDocument(kept, "t.patchwork").tess.heightDetail);
}

// The notes' distance variants (issue 41): tess.distanceCurve, distanceExponents and distanceFrom
// round-trip, are written only when they differ from the default (older files stay as they were),
// and a wrong name or exponent names its field.
TEST(PatchworkFormat, DistanceCurveAndOriginRoundTripAndAreChecked) {
    Document doc = builtinTeapot();
    const std::string plain = serializeDocument(doc);
    for (const char* k : {"distanceCurve", "distanceExponents", "distanceFrom"}) EXPECT_EQ(plain.find(k), std::string::npos) << k;
    applyNotesTerrainFormula(doc.tess);
    doc.tess.distanceExponents = {6.5f, 2.0f};
    const std::string text = serializeDocument(doc);
    const nlohmann::json j = nlohmann::json::parse(text);
    EXPECT_EQ(j["tess"]["distanceCurve"], "pow2");
    EXPECT_EQ(j["tess"]["distanceFrom"], "edges-inner-centre");
    EXPECT_EQ(parseDocument(text, "t.patchwork").tess, doc.tess);
    applyNotesDistanceFormula(doc.tess);
    EXPECT_EQ(parseDocument(serializeDocument(doc), "t.patchwork").tess.distanceFrom, DistanceFrom::Centre);
    const auto refused = [&](const std::string& from, const std::string& to, const std::string& field) {
        std::string bad = text;
        bad.replace(bad.find(from), from.size(), to);
        try {
            (void)parseDocument(bad, "t.patchwork");
            ADD_FAILURE() << "accepted " << to;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
    };
    refused("\"pow2\"", "\"cubic\"", "distanceCurve");
    refused("\"edges-inner-centre\"", "\"middle\"", "distanceFrom");
    refused("6.5", "99", "distanceExponents");
}

// display.domainOrigin (issue 41: the notes' convention kept with the document) round-trips, is
// written only when upper-left, and a wrong value names the field; the `domain-origin` command sets
// it as one undo step and refuses other words.
TEST(PatchworkFormat, DomainOriginRoundTripsAndIsCheckedByName) {
    Document doc = builtinTeapot();
    EXPECT_EQ(serializeDocument(doc).find("domainOrigin"), std::string::npos);
    doc.display.domainUpperLeft = true;
    const std::string text = serializeDocument(doc);
    EXPECT_EQ(nlohmann::json::parse(text)["display"]["domainOrigin"], "upper-left");
    EXPECT_TRUE(parseDocument(text, "t.patchwork").display.domainUpperLeft);
    std::string bad = text;
    bad.replace(bad.find("\"upper-left\""), 12, "\"upside\"");
    try {
        (void)parseDocument(bad, "t.patchwork");
        ADD_FAILURE() << "accepted domainOrigin \"upside\"";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("domainOrigin"), std::string::npos) << e.what();
    }
    EditSession s;
    s.reset(builtinTeapot(), "");
    test::runEditScript(s, "domain-origin upper-left");
    EXPECT_TRUE(s.doc.display.domainUpperLeft);
    EXPECT_THROW(test::runEditScript(s, "domain-origin sideways"), InputError);
    test::runEditScript(s, "undo");
    EXPECT_FALSE(s.doc.display.domainUpperLeft);
}

// Displacement on the CPU side (DESIGN §11): height maps read from 8- and 16-bit PNGs and sampled
// like the GPU, the document's displacement settings in files and commands, the per-window data the
// shaders get (map rectangles, shared-edge detail at every mip level), and the terrain shipped in data/.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/terrain.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/displacement.hpp"
#include "core/io/document_io.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/tess/tess_presets.hpp"
#include "png16.hpp"
#include "support.hpp"

using namespace pw;
using namespace pw::test;

namespace {

std::filesystem::path writeRamp8(const std::filesystem::path& dir, int w = 256, int h = 4) {
    std::vector<uint8_t> px(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) px[size_t(y) * w + x] = uint8_t(x * 255 / (w - 1));
    const auto file = dir / "ramp8.png";
    EXPECT_NE(stbi_write_png(file.c_str(), w, h, 1, px.data(), w), 0);
    return file;
}

}  // namespace

TEST(HeightMap, Reads8BitPngsAsSixteenBitsAndSamplesLikeALinearSampler) {
    const auto dir = freshTempDir("hm8");
    const HeightMap m = loadHeightMap(writeRamp8(dir));
    ASSERT_EQ(m.width, 256u);
    ASSERT_EQ(m.height, 4u);
    EXPECT_EQ(m.bits, 8);
    EXPECT_EQ(m.texels[0], 0);
    EXPECT_EQ(m.texels[255], 65535);  // 255 * 257
    EXPECT_EQ(m.texels[128], 128 * 257);
    // Texel centres read back exactly; halfway between two centres the mean; clamped outside.
    EXPECT_DOUBLE_EQ(m.sample(10.5 / 256, 0.5), 10.0 / 255);
    EXPECT_DOUBLE_EQ(m.sample(11.0 / 256, 0.5), 10.5 / 255);
    EXPECT_DOUBLE_EQ(m.sample(-3.0, 0.5), 0.0);
    EXPECT_DOUBLE_EQ(m.sample(0.1 / 256, 0.5), 0.0);
    EXPECT_DOUBLE_EQ(m.sample(7.0, 0.5), 1.0);
}

TEST(HeightMap, Reads16BitPngsExactly) {
    const auto dir = freshTempDir("hm16");
    std::vector<uint16_t> v(3 * 2);
    for (size_t i = 0; i < v.size(); ++i) v[i] = uint16_t(i * 12345 + 7);
    writeGreyPng16(dir / "m.png", 3, 2, v);
    const HeightMap m = loadHeightMap(dir / "m.png");
    EXPECT_EQ(m.bits, 16);
    ASSERT_EQ(m.width, 3u);
    ASSERT_EQ(m.height, 2u);
    EXPECT_EQ(m.texels, v);
    EXPECT_DOUBLE_EQ(m.texel(2, 1), v[5] / 65535.0);
}

TEST(HeightMap, BadFilesAreRefusedNamingThem) {
    const auto dir = freshTempDir("hmbad");
    std::ofstream(dir / "x.png") << "not a png at all";
    for (const auto& f : {dir / "x.png", dir / "missing.png"}) {
        try {
            (void)loadHeightMap(f);
            ADD_FAILURE() << f;
        } catch (const InputError& e) {
            EXPECT_EQ(e.file(), f.string());
        }
    }
    std::string truncated = readBytes(writeRamp8(dir));
    truncated.resize(60);
    std::ofstream(dir / "cut.png", std::ios::binary) << truncated;
    EXPECT_THROW((void)loadHeightMap(dir / "cut.png"), InputError);
}

namespace {

uint32_t crc32Of(const std::string& bytes, size_t from, size_t n) {  // PNG's CRC-32 (ISO 3309)
    uint32_t c = 0xffffffffu;
    for (size_t i = from; i < from + n; ++i) {
        c ^= uint8_t(bytes[i]);
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}
uint32_t be32(const std::string& b, size_t at) {
    return uint32_t(uint8_t(b[at])) << 24 | uint32_t(uint8_t(b[at + 1])) << 16 | uint32_t(uint8_t(b[at + 2])) << 8 | uint8_t(b[at + 3]);
}
void putBe32(std::string& b, size_t at, uint32_t v) {
    for (int k = 0; k < 4; ++k) b[at + size_t(k)] = char(uint8_t(v >> (24 - 8 * k)));
}

std::string loadRefusal(const std::filesystem::path& file) {
    try {
        (void)loadHeightMap(file);
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), file.string());
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

// A damaged PNG is refused, naming the chunk: a wrong CRC on IHDR or IDAT, a wrong Adler-32 at the
// end of the image data (its chunk's CRC made right again), where stb_image took all three.
TEST(HeightMap, DamagedPngsAreRefusedNamingTheChunk) {
    const auto dir = freshTempDir("hmcrc");
    const std::string good = readBytes(writeRamp8(dir, 64, 64));
    const size_t idat = good.find("IDAT") - 4, idatLength = be32(good, idat);
    ASSERT_EQ(good.substr(12, 4), "IHDR");
    const auto write = [&](const std::string& name, const std::string& bytes) {
        std::ofstream(dir / name, std::ios::binary) << bytes;
        return dir / name;
    };
    std::string ihdr = good;
    ihdr[8 + 8 + 13] ^= 0x01;  // IHDR's CRC
    EXPECT_NE(loadRefusal(write("ihdr.png", ihdr)).find("PNG chunk IHDR fails its CRC check"), std::string::npos);
    std::string crc = good;
    crc[idat + 8 + idatLength] ^= 0x01;  // IDAT's CRC
    EXPECT_NE(loadRefusal(write("idat.png", crc)).find("PNG chunk IDAT fails its CRC check"), std::string::npos);
    std::string data = good;
    data[idat + 8 + idatLength / 2] ^= 0x10;  // a byte of the image data: zlib finds it before the CRC is read
    EXPECT_NE(loadRefusal(write("data.png", data)).find("IDAT"), std::string::npos);
    std::string adler = good;
    adler[idat + 8 + idatLength - 1] ^= 0x01;  // the zlib stream's Adler-32, then the chunk's CRC made right
    putBe32(adler, idat + 8 + idatLength, crc32Of(adler, idat + 4, idatLength + 4));
    EXPECT_NE(loadRefusal(write("adler.png", adler)).find("fails its Adler-32 check"), std::string::npos);
    EXPECT_EQ(loadHeightMap(write("same.png", good)).texels, loadHeightMap(dir / "ramp8.png").texels);
}

TEST(DisplacementDocument, SettingsAndOwnValuesRoundTripAndBadFieldsAreNamed) {
    Document doc = makeTerrainDocument({4, 10.0, 2.0f, "maps/t.png"});
    doc.surfaces[0].displacement = DisplacementOverride{0.5f, -0.25f};
    doc.displacement.bias = 0.125f;
    const Document back = parseDocument(serializeDocument(doc), "t.patchwork");
    EXPECT_EQ(back, doc);
    // Documents without displacement are written as before (no "displacement" field).
    EXPECT_EQ(serializeDocument(Document{}).find("displacement"), std::string::npos);
    std::string text = serializeDocument(doc);
    text.replace(text.find("\"planar\""), 8, "\"sphere\"");
    try {
        (void)parseDocument(text, "t.patchwork");
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "displacement.mapping");
        EXPECT_NE(e.reason().find("planar"), std::string::npos);
    }
}

TEST(DisplacementWindows, NetWindowsTileTheMapAndSharedEdgesGetOneDetail) {
    const auto dir = freshTempDir("hmwin");
    Document doc = makeTerrainDocument({3, 6.0, 1.0f, "t.png"});
    const HeightMap map = makeTerrainHeightMap(64, 3);
    for (DisplacementMapping mapping : {DisplacementMapping::Planar, DisplacementMapping::Patch}) {
        doc.displacement.mapping = mapping;
        const std::vector<PatchInstance> w = expandPatches(doc);
        ASSERT_EQ(w.size(), 9u);
        const std::vector<WindowDisplacement> d = windowDisplacements(doc, w, &map);
        ASSERT_EQ(d.size(), 9u);
        for (size_t i = 0; i < w.size(); ++i) {
            EXPECT_FLOAT_EQ(d[i].uvRect[0], float(w[i].windowCol / 3.0));
            EXPECT_FLOAT_EQ(d[i].uvRect[3], float((w[i].windowRow + 1) / 3.0));
            for (int e = 0; e < 4; ++e) EXPECT_GT(d[i].detail[size_t(e)], 0.0f) << i << " " << e;
        }
        // Window (0,0)'s u1 edge is window (0,1)'s u0 edge; (0,0)'s v1 is (1,0)'s v0.
        EXPECT_EQ(d[0].detail[2], d[1].detail[0]);
        EXPECT_EQ(d[0].texels[2], d[1].texels[0]);
        EXPECT_EQ(d[0].detail[3], d[3].detail[1]);
        // Across the 64-texel map, a third of it per window: about 21 texels per edge.
        EXPECT_NEAR(d[4].texels[0], 64.0 / 3.0, 0.5);
    }
    // A flat map has no detail; no map, none either.
    const HeightMap flat = heightMapFromValues(8, 8, std::vector<double>(64, 0.5));
    for (const WindowDisplacement& wd : windowDisplacements(doc, expandPatches(doc), &flat)) EXPECT_EQ(wd.detail, (std::array<float, 4>{}));
    for (const WindowDisplacement& wd : windowDisplacements(doc, expandPatches(doc), nullptr))
        EXPECT_EQ(wd.texels, (std::array<float, 4>{}));
}

// Band limiting (DESIGN §11): the mip chain halves each side down to 1 x 1, every texel the mean of
// the four above it (one of them on a side of 1 texel); an edge's detail falls level by level on the
// terrain's fractal noise, whose finest octaves the filter removes, but stays on a parabola, which
// has the same second derivative at every resolution; the texels per unit are the map's over the
// model.
TEST(DisplacementWindows, MipLevelsAverageAndCarryTheirOwnDetail) {
    const HeightMap odd = heightMapFromValues(5, 3, {0, 0.2, 0.4, 0.6, 0.8, 0.1, 0.3, 0.5, 0.7, 0.9, 1, 1, 1, 1, 1});
    const std::vector<HeightMap> oddChain = heightMipChain(odd, 8);
    ASSERT_EQ(oddChain.size(), 2u);
    EXPECT_EQ(oddChain[0].width, 2u);
    EXPECT_EQ(oddChain[0].height, 1u);
    EXPECT_NEAR(oddChain[0].texel(1, 0), (0.4 + 0.6 + 0.5 + 0.7) / 4, 1e-4);
    EXPECT_EQ(oddChain[1].width * oddChain[1].height, 1u);
    EXPECT_NEAR(oddChain[1].texel(0, 0), (oddChain[0].texel(0, 0) + oddChain[0].texel(1, 0)) / 2, 1e-4);
    EXPECT_EQ(heightMipChain(makeTerrainHeightMap(64, 3), 3).size(), 3u);  // at most the levels asked for

    const HeightMap noise = makeTerrainHeightMap(256, 3);
    std::vector<double> bowl(256 * 256);
    for (size_t i = 0; i < bowl.size(); ++i) {
        const double x = (double(i % 256) + 0.5) / 256.0 - 0.5;
        bowl[i] = 2.0 * x * x;
    }
    const HeightMap parabola = heightMapFromValues(256, 256, bowl);
    std::vector<std::array<double, 2>> row(257);  // across the middle half (clear of the clamped border), two samples a texel
    for (size_t k = 0; k < row.size(); ++k) row[k] = {0.25 + double(k) / 512.0, 0.5};
    const EdgeDetail n = edgeDetail(noise, heightMipChain(noise, 8), row);
    EXPECT_NEAR(n.texels, 128.0, 1e-9);
    EXPECT_LT(n.coarser[0], 0.8 * n.detail);
    for (size_t l = 1; l < 6; ++l) EXPECT_LT(n.coarser[l], n.coarser[l - 1]) << l;
    const EdgeDetail p = edgeDetail(parabola, heightMipChain(parabola, 8), row);
    EXPECT_GT(p.detail, 0.9);  // h'' = 1 per unit parameter^2 (the linear filter's kinks measure up to twice that)
    EXPECT_LT(p.detail, 2.1);
    for (size_t l = 0; l < 4; ++l) EXPECT_NEAR(p.coarser[l], p.detail, 0.05 * p.detail) << l + 1;  // down to 16 x 16

    Document doc = makeTerrainDocument({4, 8.0, 1.0f, "t.png"});
    const std::vector<PatchInstance> w = expandPatches(doc);
    EXPECT_DOUBLE_EQ(mapTexelsPerUnit(doc, w, &noise), 256.0 / 8.0);  // planar over the 8 x 8 square
    doc.displacement.mapping = DisplacementMapping::Patch;
    EXPECT_NEAR(mapTexelsPerUnit(doc, w, &noise), 256.0 / 8.0, 1e-6);  // the net tiles it evenly
    EXPECT_EQ(mapTexelsPerUnit(doc, w, nullptr), 0.0);
}

TEST(DisplacementCommands, MapScaleBiasMappingAndOwnValuesAreUndoableSteps) {
    const auto dir = freshTempDir("hmcmd");
    const auto ramp = writeRamp8(dir);
    EditSession s;
    runEditScript(s, "add-patch");
    EXPECT_THROW(runEditScript(s, "displacement-scale 2"), std::exception);  // no map yet
    EXPECT_THROW(runEditScript(s, "displacement " + (dir / "none.png").string()), std::exception);
    EXPECT_FALSE(s.doc.displacement.active());
    runEditScript(s, "displacement " + ramp.string() + "; displacement-scale 0.5; displacement-bias -0.25; displacement-mapping patch");
    EXPECT_EQ(s.doc.displacement.map, ramp.string());  // an unsaved document names the map absolutely
    EXPECT_EQ(s.doc.displacement.scale, 0.5f);
    EXPECT_EQ(s.doc.displacement.bias, -0.25f);
    EXPECT_EQ(s.doc.displacement.mapping, DisplacementMapping::Patch);
    runEditScript(s, "select patch 0; displacement-own 2 1");
    ASSERT_TRUE(s.doc.patches[0].displacement.has_value());
    EXPECT_EQ(s.doc.patches[0].displacement->scale, 2.0f);
    runEditScript(s, "undo; undo");
    EXPECT_FALSE(s.doc.patches[0].displacement.has_value());
    EXPECT_EQ(s.doc.displacement.mapping, DisplacementMapping::Planar);
    runEditScript(s, "displacement off");
    EXPECT_FALSE(s.doc.displacement.active());
}

// The terrain notes' preset (data/terrain_notes.patchwork): the same map under a terrain eight
// times larger (1024 units, 32-unit windows), so the notes' distances 10..200 fall inside it, with
// their formula: 2^lerp(20, 4, s), edges from midpoints and inner levels from the centre, fractional_even.
Document notesTerrainDocument() {
    Document doc = makeTerrainDocument({32, 1024.0, 112.0f, "terrain.png"});
    doc.name = "terrain of the notes";
    applyNotesTerrainFormula(doc.tess);
    return doc;
}

TEST(Terrain, DataFolderHoldsTheGeneratedTerrainAndItsMap) {
    const HeightMap generated = makeTerrainHeightMap();
    const Document doc = makeTerrainDocument();
    if (std::getenv("PATCHWORK_REGENERATE_DATA")) {  // rewrites data/terrain.* from the generators
        writeGreyPng16(dataDir() / "terrain.png", generated.width, generated.height, generated.texels);
        std::ofstream(dataDir() / "terrain.patchwork") << serializeDocument(doc);
        std::ofstream(dataDir() / "terrain_notes.patchwork") << serializeDocument(notesTerrainDocument());
    }
    EXPECT_EQ(loadDocument(dataDir() / "terrain_notes.patchwork"), notesTerrainDocument());
    const HeightMap shipped = loadHeightMap(dataDir() / "terrain.png");
    EXPECT_EQ(shipped.bits, 16);
    EXPECT_EQ(shipped.width, generated.width);
    EXPECT_TRUE(shipped.texels == generated.texels) << "data/terrain.png is not makeTerrainHeightMap()'s map";
    EXPECT_EQ(loadDocument(dataDir() / "terrain.patchwork"), doc);
    EXPECT_EQ(resolveMapPath(doc.displacement, dataDir() / "terrain.patchwork"), dataDir() / "terrain.png");
}

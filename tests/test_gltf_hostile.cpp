// Hostile glTF input: the importer reads no file a URI names, and bytes import like the file.
#include <gtest/gtest.h>

#include <fstream>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/io/gltf_import.hpp"
#include "support.hpp"

using namespace pw;

TEST(GltfHostile, ExternalBufferUriIsNotRead) {
    const auto dir = test::freshTempDir("gltf-hostile");
    // A real file beside it, that a naive loader would read through the relative URI.
    { std::ofstream(dir / "secret.bin") << "0123456789abcdef"; }
    const std::string gltf = R"({"asset":{"version":"2.0","extras":{"patchwork":{"format":"patchwork","version":1}}},
        "buffers":[{"uri":"secret.bin","byteLength":16}]})";
    writeFileAtomic(dir / "x.gltf", gltf);
    try {
        (void)importPatchworkGltf(dir / "x.gltf");
        FAIL() << "a glTF with an external buffer was imported";
    } catch (const InputError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("x.gltf"), std::string::npos) << msg;
        // Refused by the structure check, before the glTF reader (whose file system reports no file
        // as existing) is asked.
        EXPECT_EQ(e.field(), "buffers[0].uri") << msg;
        EXPECT_NE(msg.find("secret.bin"), std::string::npos) << msg;
    }
}

TEST(GltfHostile, BytesImportLikeTheFile) {
    const auto file = test::testsDir() / "corpus" / "good" / "teacup-l1.gltf";
    const Document fromFile = importPatchworkGltf(file);
    const Document fromBytes = parsePatchworkGltf(readFileLimited(file), "teacup-l1.gltf");
    EXPECT_EQ(fromFile, fromBytes);
    EXPECT_EQ(fromFile.patches.size(), 26u);
}

TEST(GltfHostile, TruncatedBinaryIsAnInputError) {
    const std::string glb = readFileLimited(test::testsDir() / "corpus" / "good" / "teaspoon-l1.glb");
    for (size_t cut : {size_t(0), size_t(4), size_t(12), size_t(20), glb.size() / 2, glb.size() - 1}) {
        EXPECT_THROW((void)parsePatchworkGltf(std::string_view(glb).substr(0, cut), "cut.glb"), InputError) << cut;
    }
}

namespace {

// A GLB holding `json` (padded with spaces) and a BIN chunk of `bin` bytes.
std::string makeGlb(std::string json, size_t bin) {
    while (json.size() % 4) json += ' ';
    const size_t binPadded = (bin + 3) / 4 * 4;
    const uint32_t total = uint32_t(12 + 8 + json.size() + (bin ? 8 + binPadded : 0));
    std::string out;
    auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    out += "glTF";
    u32(2);
    u32(total);
    u32(uint32_t(json.size()));
    u32(0x4E4F534Au);
    out += json;
    if (bin) {
        u32(uint32_t(binPadded));
        u32(0x004E4942u);
        out.append(binPadded, '\0');
    }
    return out;
}

InputError importError(std::string_view bytes, const std::string& name) {
    try {
        (void)parsePatchworkGltf(bytes, name);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << name << " was imported";
    return InputError(name, "imported");
}

}  // namespace

// Issue 24: 20 000 nested arrays in an extras (40 KB) overflowed the stack inside the glTF reader.
TEST(GltfHostile, DeepNestingInAnyExtrasIsRefusedBeforeParsing) {
    const std::string deep = std::string(20000, '[') + std::string(20000, ']');
    const std::string head = R"({"asset":{"version":"2.0","extras":{"patchwork":{"format":"patchwork","version":1}}},)";
    for (const std::string& where : {R"("nodes":[{"extras":)" + deep + "}]}", R"("extras":{"x":)" + deep + "}}",
                                     R"("scenes":[{"extras":{"patchwork":)" + deep + "}}]}"}) {
        const std::string json = head + where;
        for (bool glb : {false, true}) {
            const InputError e = importError(glb ? makeGlb(json, 0) : json, glb ? "deep.glb" : "deep.gltf");
            EXPECT_NE(std::string(e.what()).find("nested deeper than"), std::string::npos) << e.what();
            EXPECT_EQ(e.file(), glb ? "deep.glb" : "deep.gltf");
            EXPECT_EQ(e.line(), 1);
        }
    }
}

// Issue 24: a .glb whose buffer says 0 bytes beside a 4-byte BIN chunk exited 1 with
// "internal error: vector::_M_range_check" and no file name.
TEST(GltfHostile, ZeroLengthBufferNamesTheField) {
    const std::string json = R"({"asset":{"version":"2.0","extras":{"patchwork":{"format":"patchwork","version":1}}},)"
                             R"("buffers":[{"byteLength":0}]})";
    const InputError e = importError(makeGlb(json, 4), "zero.glb");
    EXPECT_EQ(e.file(), "zero.glb");
    EXPECT_EQ(e.field(), "buffers[0].byteLength");
}

// Issue 24: integers went through 32 bits, so the point index 2^32 + 1 loaded as 1.
TEST(GltfHostile, WideIntegersAreNotTruncated) {
    const std::string doc = R"({"format":"patchwork","version":1,"points":[)" + [] {
        std::string p;
        for (int i = 0; i < 16; ++i) p += std::string(i ? "," : "") + "[" + std::to_string(i) + ",0,0]";
        return p;
    }() + R"(],"patches":[{"idx":[0,4294967297,2,3,4,5,6,7,8,9,10,11,12,13,14,15]}]})";
    const std::string json = R"({"asset":{"version":"2.0","extras":{"patchwork":)" + doc + "}}}";
    for (bool glb : {false, true}) {
        const InputError e = importError(glb ? makeGlb(json, 0) : json, "wide");
        EXPECT_EQ(e.field(), "asset.extras.patchwork.patches[0].idx[1]") << e.what();
        EXPECT_NE(std::string(e.what()).find("4294967297"), std::string::npos) << e.what();
    }
}

// Errors inside the document name the field from the glTF's root, not from the extras.
TEST(GltfHostile, DocumentErrorsNameTheFieldFromTheRoot) {
    const std::string json = R"({"asset":{"version":"2.0"},"scenes":[{},{"extras":{"patchwork":)"
                             R"({"format":"patchwork","version":1,"points":[[0,0,"x"]]}}}]})";
    const InputError e = importError(json, "scene.gltf");
    EXPECT_EQ(e.field(), "scenes[1].extras.patchwork.points[0][2]") << e.what();
}

// Hostile glTF input: the importer reads no file a URI names, and bytes import like the file.
#include <gtest/gtest.h>

#include <fstream>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/gltf_import.hpp"
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
        // The importer's file system reports no file as existing, so tinygltf never opens it.
        EXPECT_NE(msg.find("not a valid glTF"), std::string::npos) << msg;
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

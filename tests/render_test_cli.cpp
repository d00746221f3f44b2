// `patchwork render`: option validation (exit 2 naming the option), stats JSON, device choice.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "render/vk/device.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

std::string bin() { return patchworkBinary().string(); }

TEST(RenderCli, WritesPngAndStats) {
    const auto dir = freshTempDir("render-cli");
    const auto png = dir / "teapot.png", stats = dir / "stats.json";
    const RunResult r = runCommand("PATCHWORK_VALIDATION=1 " + bin() + " render -o " + png.string() +
                                   " --size 320x240 --tess 16 --overlay grid,wire --stats " + stats.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    ASSERT_TRUE(std::filesystem::exists(png));
    EXPECT_GT(std::filesystem::file_size(png), 1000u);
    std::ifstream in(stats);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["triangles"].get<uint64_t>(), 32u * 2 * 16 * 16);
    EXPECT_GT(j["tess_eval_invocations"].get<uint64_t>(), 0u);
    EXPECT_GE(j["gpu_ms"].get<double>(), 0.0);
}

TEST(RenderCli, RejectsBadOptionsNamingThem) {
    const auto dir = freshTempDir("render-cli-bad");
    const std::string out = " -o " + (dir / "x.png").string() + " --size 64x64";
    struct Case {
        std::string args, option;
    };
    const Case cases[] = {
        {"--tess 0", "--tess"},
        {"--tess 65", "--tess"},
        {"--tess nan", "--tess"},
        {"--tess abc", "--tess"},
        {"--outer 1,2,3", "--outer"},
        {"--outer 1,2,3,nan --inner 2,2", "--outer"},
        {"--inner 0,4", "--inner"},
        {"--spacing odd", "--spacing"},
        {"--adaptive far", "--adaptive"},
        {"--shading glossy", "--shading"},
        {"--overlay grid,foo", "--overlay"},
        {"--view diagonal", "--view"},
        {"--size 0x10", "--size"},
        {"--tess 4 --outer 1,1,1,1", "--tess"},
    };
    for (const Case& c : cases) {
        const RunResult r = runCommand(bin() + " render" + out + " " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.option), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    }
}

TEST(RenderCli, UnknownDeviceIsAClearError) {
    const auto dir = freshTempDir("render-cli-dev");
    const RunResult r = runCommand(bin() + " render -o " + (dir / "x.png").string() + " --device no-such-gpu-xyz");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("no-such-gpu-xyz"), std::string::npos) << r.output;
}

TEST(RenderCli, DeviceWithoutTessellationIsReportedClearly) {
    const auto dir = freshTempDir("render-cli-notess");
    const auto png = dir / "x.png";
    const RunResult r = runCommand("PATCHWORK_PRETEND_MISSING=tessellationShader " + bin() + " render -o " + png.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("lacks required features: tessellationShader"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(png));
    // The check itself: a device with everything passes, without tessellation it is named.
    VkPhysicalDeviceFeatures f{};
    f.tessellationShader = f.fillModeNonSolid = VK_TRUE;
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    f13.dynamicRendering = VK_TRUE;
    VkPhysicalDeviceLimits limits{};
    limits.maxTessellationPatchSize = 32;
    EXPECT_EQ(render::missingRequiredFeatures(f, f13, limits), "");
    f.tessellationShader = VK_FALSE;
    limits.maxTessellationPatchSize = 8;
    EXPECT_EQ(render::missingRequiredFeatures(f, f13, limits), " tessellationShader maxTessellationPatchSize>=16");
}

TEST(RenderCli, MissingInputFileIsAnInputError) {
    const auto dir = freshTempDir("render-cli-missing");
    const RunResult r = runCommand(bin() + " render " + (dir / "nope.patchwork").string() + " -o " + (dir / "x.png").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
}

// `bench --file`: a user's own document measured with its own settings (issue 43, item 7): its
// levels, not the bench's; against a plain mesh of the same triangles where they are uniform, and
// alone where they are adaptive.
TEST(RenderCli, BenchMeasuresADocumentAtItsOwnSettings) {
    const auto dir = freshTempDir("bench-file");
    ASSERT_EQ(runCommand(bin() + " convert " + (dataDir() / "teapot.bpt").string() + " " + (dir / "pot.patchwork").string()).exitCode, 0);
    nlohmann::json doc = nlohmann::json::parse(readBytes(dir / "pot.patchwork"));
    doc["tess"]["outer"] = {5.0, 5.0, 5.0, 5.0};
    doc["tess"]["inner"] = {5.0, 5.0};
    std::ofstream(dir / "five.patchwork") << doc.dump();
    doc["tess"]["adaptive"] = "screen";
    std::ofstream(dir / "adaptive.patchwork") << doc.dump();
    for (const char* name : {"five.patchwork", "adaptive.patchwork"}) {
        const auto json = dir / (std::string(name) + ".json");
        const RunResult r = runCommand("PATCHWORK_VALIDATION=1 " + bin() + " bench --frames 2 --validation --file " +
                                       (dir / name).string() + " --json " + json.string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find(name), std::string::npos) << r.output;
        const nlohmann::json j = nlohmann::json::parse(readBytes(json));
        ASSERT_EQ(j["scenes"].size(), 1u) << j.dump();
        const nlohmann::json& sc = j["scenes"][0];
        EXPECT_EQ(sc["patches"].get<int>(), 32);
        if (std::string(name) == "five.patchwork") {
            EXPECT_EQ(sc["triangles"].get<uint64_t>(), 32u * 2 * 5 * 5);  // its own level 5, not the bench's 16
            // The plain mesh leaves out the lid's zero-area triangles at the poles (1 560 of 1 600).
            EXPECT_LE(sc["plain"]["triangles"].get<uint64_t>(), sc["triangles"].get<uint64_t>());
            EXPECT_GE(sc["plain"]["triangles"].get<uint64_t>(), 32u * 2 * 5 * 5 * 95 / 100);
            // The raw tessellator (trivial shaders): the same patches at the same levels, measured beside.
            EXPECT_EQ(sc["raw_tessellator"]["triangles"].get<uint64_t>(), sc["triangles"].get<uint64_t>());
            EXPECT_GT(sc["throughput_ratio_tess_over_raw"].get<double>(), 0.0);
            EXPECT_GT(sc["level_edit"]["scene_upload_ms"].get<double>(), 0.0);
        } else {
            EXPECT_TRUE(sc["adaptive"].get<bool>());
            EXPECT_FALSE(sc.contains("plain"));
            EXPECT_FALSE(sc.contains("raw_tessellator"));
            EXPECT_GT(sc["triangles"].get<uint64_t>(), 0u);
        }
    }
    EXPECT_EQ(runCommand(bin() + " bench --file " + (dir / "missing.patchwork").string()).exitCode, 2);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pw::test

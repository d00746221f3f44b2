// Multi-file outputs of the CLI (issue 24): the PNG and its stats, or every frame of a sweep,
// appear together or not at all, and an unwritable output is refused before the work.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>

#include "support.hpp"

namespace fs = std::filesystem;

namespace pw::test {
namespace {

std::string bin() { return patchworkBinary().string(); }

// `render -o ok.png --stats nodir/s.json` exited 2 but left ok.png behind.
TEST(CliOutputs, RenderWithAnUnwritableStatsFileWritesNoPng) {
    const fs::path dir = freshTempDir("out-render");
    for (const char* kind : {"", "--domain quad ", "--compare equal,pow2 "}) {
        const RunResult r = runCommand(bin() + " render " + kind + "--size 64x48 -o " + (dir / "ok.png").string() + " --stats " +
                                       (dir / "nodir" / "s.json").string());
        EXPECT_EQ(r.exitCode, 2) << kind << r.output;
        EXPECT_NE(r.output.find("nodir"), std::string::npos) << r.output;
        EXPECT_EQ(entryCount(dir), 0u) << kind;
    }
}

TEST(CliOutputs, RenderOntoAFifoIsRefusedAndTheFifoStays) {
    const fs::path dir = freshTempDir("out-fifo");
    ASSERT_EQ(::mkfifo((dir / "x.png").c_str(), 0644), 0);
    const RunResult r = runCommand(bin() + " render --size 64x48 -o " + (dir / "x.png").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("a FIFO"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::is_fifo(dir / "x.png"));
    EXPECT_EQ(entryCount(dir), 1u);
}

// A sweep that fails at frame 3 of 5 (the frame's name is taken by a FIFO) leaves no frame, and
// takes away the folder it made.
TEST(CliOutputs, SweepIsAllFramesOrNone) {
    const fs::path dir = freshTempDir("out-sweep");
    ASSERT_EQ(::mkfifo((dir / "f02.png").c_str(), 0644), 0);
    const RunResult r =
        runCommand(bin() + " sweep --domain quad --from 1 --to 5 --frames 5 --size 64x64 -o " + (dir / "f%02d.png").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("f02.png"), std::string::npos) << r.output;
    EXPECT_EQ(entryCount(dir), 1u);  // the FIFO only

    // A failure after the frame folders were made (no such device) takes them away again.
    const RunResult m = runCommand(bin() + " sweep --domain quad --from 1 --to 5 --frames 5 --size 64x64 --device no-such-gpu-xyz -o " +
                                   (dir / "new" / "deeper").string());
    EXPECT_NE(m.exitCode, 0) << m.output;
    EXPECT_FALSE(fs::exists(dir / "new")) << m.output;
    EXPECT_EQ(entryCount(dir), 1u);
}

}  // namespace
}  // namespace pw::test

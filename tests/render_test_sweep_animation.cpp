// `sweep ... -o sweep.gif|.mp4|.webm`: one animation with one frame per step (ffprobe counts them),
// at the figure's size and the requested rate; when ffmpeg is missing or fails the command exits 2
// naming the file, the old file stays and no temporary file is left. Validation layer on.
#include <gtest/gtest.h>

#include <fstream>

#include "support.hpp"

namespace pw::test {
namespace {

std::string bin() { return "PATCHWORK_VALIDATION=1 " + patchworkBinary().string(); }

// "width,height,frames,rate" of the first video stream, decoded frame by frame.
std::string probe(const std::filesystem::path& file) {
    const RunResult r = runCommand(
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
        "stream=width,height,nb_read_frames,r_frame_rate -of csv=p=0 " +
        file.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::string s = r.output;
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    return s;
}

}  // namespace

TEST(SweepAnimation, OneFramePerStepInEachFormat) {
    const auto dir = freshTempDir("sweep-anim");
    const auto tmp = freshTempDir("sweep-anim-tmp");
    struct Case {
        const char* name;
        const char* args;
        const char* want;  // ffprobe: width,height,rate,frames
    };
    const Case cases[] = {
        {"d.gif", "--domain quad --compare equal,fractional_odd,fractional_even,pow2 --from 1 --to 8 --frames 9 --fps 5 --size 512x320",
         "512,320,5/1,9"},
        {"d.mp4", "--preset tri-4.9_4.5_4.1-4.4 --from 2 --to 6 --frames 6 --fps 12 --size 400x300", "400,300,12/1,6"},
        {"m.webm", "--from 1 --to 4 --frames 4 --fps 8 --size 321x201", "320,200,8/1,4"},  // odd sizes: even for yuv420p
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const RunResult r = runCommand("TMPDIR=" + tmp.string() + " " + bin() + " sweep " + c.args + " -o " + (dir / c.name).string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(probe(dir / c.name), c.want);
    }
    EXPECT_EQ(entryCount(dir), 3u) << "one file per animation, no frame folders";
    EXPECT_EQ(entryCount(tmp), 0u) << "the encoder's temporary folder is removed";
}

TEST(SweepAnimation, WithoutAWorkingFfmpegNothingIsLost) {
    const auto dir = freshTempDir("sweep-anim-fail");
    const auto tmp = freshTempDir("sweep-anim-fail-tmp");
    const auto gif = dir / "s.gif";
    std::ofstream(gif) << "old";
    for (const std::string ffmpeg : {"/nonexistent/ffmpeg", "false"}) {
        SCOPED_TRACE(ffmpeg);
        const RunResult r = runCommand("TMPDIR=" + tmp.string() + " PATCHWORK_FFMPEG=" + ffmpeg + " " + bin() +
                                       " sweep --domain quad --frames 3 --size 200x120 -o " + gif.string());
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(gif.string()), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("ffmpeg"), std::string::npos) << r.output;
        EXPECT_EQ(readBytes(gif), "old");
        EXPECT_EQ(entryCount(dir), 1u);
        EXPECT_EQ(entryCount(tmp), 0u);
    }
}

// A model sweep draws the document's displacement as render does, and takes the same displacement
// options: a height map that cannot be read, or a bad --height-detail, is exit 2 with no frame
// written (they were accepted and ignored).
TEST(SweepAnimation, DisplacementOptionsApplyToModelSweeps) {
    const auto dir = freshTempDir("sweep-displacement");
    const std::string base =
        bin() + " sweep " + (dataDir() / "teapot.bpt").string() + " --from 2 --to 3 --fps 2 --seconds 1 --size 160x90 ";
    const RunResult missing = runCommand(base + "--displacement " + (dir / "none.png").string() + " -o " + (dir / "a").string() + "/ 2>&1");
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("none.png"), std::string::npos) << missing.output;
    const RunResult bad = runCommand(base + "--height-detail maybe -o " + (dir / "b").string() + "/ 2>&1");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "a" / "frame_0000.png"));
    const RunResult map = runCommand(base + "--displacement " + (dataDir() / "terrain.png").string() + " --displacement-scale 0.3 -o " +
                                     (dir / "c").string() + "/ 2>&1");
    EXPECT_EQ(map.exitCode, 0) << map.output;
}

}  // namespace pw::test

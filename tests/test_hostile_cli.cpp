// Issue 24, the minor cases: numbers on the command line are plain decimals, a singular field of
// view is refused, and control characters from a file never reach the terminal raw.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/base/errors.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace pw::test {
namespace {

std::string bin() { return patchworkBinary().string(); }

fs::path writeDoc(const fs::path& dir, const std::string& name, const std::string& extra) {
    const fs::path p = dir / name;
    std::ofstream(p) << R"({"format":"patchwork","version":1,"points":[[0,0,0]],"patches":[{"idx":[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]}])"
                     << extra << "}\n";
    return p;
}

TEST(HostileCli, NumbersArePlainDecimals) {
    const fs::path dir = freshTempDir("hostile-numbers");
    const fs::path doc = writeDoc(dir, "d.patchwork", "");
    for (const std::string& args : {"export " + doc.string() + " --tess 0x20 -o " + (dir / "x.glb").string(),
                                    "export " + doc.string() + " --tess 0b11 -o " + (dir / "x.glb").string(),
                                    "render " + doc.string() + " --adaptive screen --target-px 0.5abc -o " + (dir / "x.png").string(),
                                    "render " + doc.string() + " --tess 0x10 -o " + (dir / "x.png").string(),
                                    "render " + doc.string() + " --tess inf -o " + (dir / "x.png").string(),
                                    "sweep --domain quad --from 0x2 -o " + (dir / "f%d.png").string()}) {
        const RunResult r = runCommand(bin() + " " + args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("not a"), std::string::npos) << args << "\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(dir / "x.glb"));
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    const RunResult ok = runCommand(bin() + " export " + doc.string() + " --tess 2 -o " + (dir / "x.glb").string());
    EXPECT_EQ(ok.exitCode, 0) << ok.output;
}

TEST(HostileCli, SingularFieldOfViewIsRefused) {
    const fs::path dir = freshTempDir("hostile-fov");
    for (const char* fov : {"180", "0", "170.5"}) {
        const fs::path doc = writeDoc(dir, "fov.patchwork", std::string(R"(,"camera":{"fovYDeg":)") + fov + "}");
        const RunResult r = runCommand(bin() + " info " + doc.string());
        EXPECT_EQ(r.exitCode, 2) << fov << r.output;
        EXPECT_NE(r.output.find("camera.fovYDeg"), std::string::npos) << r.output;
    }
    const fs::path doc = writeDoc(dir, "fov.patchwork", R"(,"camera":{"fovYDeg":170})");
    EXPECT_EQ(runCommand(bin() + " info " + doc.string()).exitCode, 0);
}

TEST(HostileCli, ControlCharactersAreEscaped) {
    EXPECT_EQ(printable("a\x1b]0;owned\x07z\n"), "a\\x1b]0;owned\\x07z\\x0a");
    EXPECT_EQ(printable("Bézier"), "Bézier");  // UTF-8 passes
    const fs::path dir = freshTempDir("hostile-control");
    const fs::path named = writeDoc(dir, "named.patchwork", R"(,"name":"\u001b[2J\u001b]0;owned\u0007")");
    const RunResult r = runCommand(bin() + " info " + named.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\\x1b[2J"), std::string::npos) << r.output;
    // In an error: a bad value that carries an escape sequence.
    const fs::path bad = writeDoc(dir, "bad.patchwork", R"(,"tess":{"spacing":"\u001b[2Jx"})");
    const RunResult e = runCommand(bin() + " info " + bad.string());
    EXPECT_EQ(e.exitCode, 2) << e.output;
    EXPECT_EQ(e.output.find('\x1b'), std::string::npos) << e.output;
}

}  // namespace
}  // namespace pw::test

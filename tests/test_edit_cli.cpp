// `patchwork edit`: scripts build and save documents headless; a bad line names SCRIPT:LINE, exits 2
// and writes nothing (neither OUT nor the files its `save` lines named).
#include <gtest/gtest.h>

#include <fstream>

#include "core/io/document_io.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using namespace pw;

namespace {

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }
std::string bin() { return q(test::patchworkBinary()); }

}  // namespace

TEST(EditCli, ScriptBuildsAJoinedShapeAndSavesIt) {
    const fs::path dir = test::freshTempDir("editcli");
    {
        std::ofstream s(dir / "pair.txt");
        s << "# two patches side by side, joined C1\nadd-patch\ncursor 3 0 0; add-patch\njoin 0:u1 1:u0 C1\n"
          << "select all; rotate X 30\nsave " << (dir / "copy.patchwork").string() << "\n";
    }
    const auto r = test::runCommand(bin() + " edit -o " + q(dir / "pair.patchwork") + " --run " + q(dir / "pair.txt"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Document d = loadDocument(dir / "pair.patchwork");
    EXPECT_EQ(d.patches.size(), 2u);
    ASSERT_EQ(d.joins.size(), 1u);
    EXPECT_EQ(d.joins[0].continuity, Continuity::C1);
    EXPECT_EQ(loadDocument(dir / "copy.patchwork").patches.size(), 2u);
    // Starting from that file: -c commands, OUT's format from its extension.
    const auto r2 =
        test::runCommand(bin() + " edit " + q(dir / "pair.patchwork") + " -o " + q(dir / "pair.glb") + " -c 'select patch 1; delete'");
    ASSERT_EQ(r2.exitCode, 0) << r2.output;
    EXPECT_EQ(loadDocument(dir / "pair.glb").patches.size(), 1u);
}

TEST(EditCli, BadLineExitsTwoAndWritesNothing) {
    const fs::path dir = test::freshTempDir("editbad");
    const fs::path out = dir / "out.patchwork";
    {
        std::ofstream o(out);
        o << "keep me";
        std::ofstream s(dir / "bad.txt");
        s << "add-patch\nsave " << (dir / "early.patchwork").string() << "\n\nmove 1 2\n";
    }
    const auto r = test::runCommand(bin() + " edit -o " + q(out) + " --run " + q(dir / "bad.txt"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("bad.txt:4: move: expected 3 arguments, got 2"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "early.patchwork"));
    std::ifstream in(out);
    std::string kept((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(kept, "keep me");
    const auto r2 = test::runCommand(bin() + " edit -o " + q(dir / "x.patchwork") + " -c 'add-patch; frobnicate'");
    EXPECT_EQ(r2.exitCode, 2);
    EXPECT_NE(r2.output.find("-c:1: unknown command 'frobnicate'"), std::string::npos) << r2.output;
    EXPECT_FALSE(fs::exists(dir / "x.patchwork"));
    const auto r3 = test::runCommand(bin() + " edit -o " + q(dir / "x.txt") + " -c add-patch");
    EXPECT_EQ(r3.exitCode, 2);
    EXPECT_FALSE(fs::exists(dir / "x.txt"));
}

TEST(EditCli, VersionPrintsTheProjectVersion) {
    const auto r = test::runCommand(bin() + " --version");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.output, "patchwork " PATCHWORK_VERSION "\n");
}

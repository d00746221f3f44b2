// Fault injection for saves: a child process writes a large file over an existing one with
// writeFileAtomic (what every save and export uses) and is killed with SIGKILL at random moments
// during the save. Afterwards the file must hold either the old bytes or the complete new bytes,
// never a mix or a truncation; the kills must really land inside the save (temporary file seen).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/io/document_io.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

// Leftover temporary files of interrupted saves in dir (".<name>.tmp-<pid>-<n>").
int temporaries(const fs::path& dir) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().rfind(".doc.patchwork.tmp", 0) == 0) ++n;
    return n;
}

// A child process that saves `data` over `target` with writeFileAtomic and exits (3 when the save
// throws); its pid, for the parent to kill in the middle.
pid_t forkWriter(const fs::path& target, const std::string& data) {
    const pid_t child = fork();
    if (child == 0) {
        try {
            pw::writeFileAtomic(target, data);
        } catch (...) {
            _exit(3);
        }
        _exit(0);
    }
    return child;
}

}  // namespace

TEST(AtomicSave, KilledInTheMiddleOfASaveLeavesTheOldFileIntact) {
    const fs::path dir = pw::test::freshTempDir("atomic-save");
    const fs::path target = dir / "doc.patchwork";
    // Two contents of the same size that differ everywhere, large enough that a save takes a while.
    const size_t size = 24u << 20;
    std::string oldData(size, 'o'), newData(size, 'n');
    for (size_t i = 0; i < size; i += 4096) oldData[i] = '\n', newData[i] = '\n';

    // How long one whole save takes here.
    pw::writeFileAtomic(target, newData);
    const auto t0 = std::chrono::steady_clock::now();
    pw::writeFileAtomic(target, oldData);
    const double saveUs = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(pw::test::readBytes(target), oldData);

    std::mt19937 rng(42);
    std::uniform_real_distribution<double> when(0.0, 1.2 * saveUs);
    int intact = 0, replaced = 0, interrupted = 0;
    for (int trial = 0; trial < 16; ++trial) {
        const pid_t child = forkWriter(target, newData);
        ASSERT_GE(child, 0);
        usleep(useconds_t(when(rng)));
        kill(child, SIGKILL);
        int status = 0;
        waitpid(child, &status, 0);
        const std::string now = pw::test::readBytes(target);
        ASSERT_TRUE(now == oldData || now == newData)
            << "trial " << trial << ": the file holds " << now.size() << " bytes of neither version";
        const bool killed = WIFSIGNALED(status);
        if (now == oldData) ++intact;
        if (now == newData) ++replaced;
        if (killed && temporaries(dir) > 0) ++interrupted;
        // Back to the old version for the next trial, and no leftovers.
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path() != target) fs::remove(e.path());
        if (now != oldData) pw::writeFileAtomic(target, oldData);
    }
    EXPECT_GT(interrupted, 0) << "no kill landed inside a save (one save takes " << saveUs << " µs)";
    // A killed writer's temporary file is removed by the next write into the folder.
    const pid_t child = forkWriter(target, newData);
    ASSERT_GE(child, 0);
    for (int i = 0; i < 2000 && temporaries(dir) == 0; ++i) usleep(500);
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    if (temporaries(dir) > 0) {
        pw::writeFileAtomic(dir / "other.txt", "x");
        EXPECT_EQ(temporaries(dir), 0) << "a dead writer's temporary file stayed";
    }
    EXPECT_GT(intact, 0);
    std::printf("atomic save: %.0f ms per save; 16 kills: %d left the old file, %d the new one, %d interrupted a save\n", saveUs / 1000.0,
                intact, replaced, interrupted);
    fs::remove_all(dir);
}

// A document the program writes is read back through its reader before it replaces anything
// (issue 44): a write that does not read back is refused naming the reason, the old file stays and
// no temporary file is left. Saving a document through the formats' table reads it back for real.
TEST(AtomicSave, AWriteThatDoesNotReadBackReplacesNothing) {
    const fs::path dir = pw::test::freshTempDir("read-back");
    const fs::path target = dir / "doc.patchwork";
    pw::writeFileAtomic(target, "old");
    fs::path seen;
    try {
        pw::writeFileAtomic(target, "new", [&](const fs::path& staged) {
            seen = staged;
            EXPECT_EQ(pw::test::readBytes(staged), "new");  // the staged file, complete, not yet in place
            throw pw::InputError(target.string(), "no patches", 3);
        });
        FAIL() << "a write that does not read back was accepted";
    } catch (const pw::OutputError& e) {
        EXPECT_NE(std::string(e.what()).find("does not read back (no patches at line 3)"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(seen.empty());
    EXPECT_EQ(pw::test::readBytes(target), "old");
    EXPECT_EQ(temporaries(dir), 0);

    // Leftovers: a dead writer's is removed by the next write; a running writer's (this process)
    // and files of other forms stay.
    const pid_t dead = fork();
    ASSERT_GE(dead, 0);
    if (dead == 0) _exit(0);
    waitpid(dead, nullptr, 0);
    const std::string deadTemp = ".doc.patchwork.tmp-" + std::to_string(dead) + "-17",
                      liveTemp = ".doc.patchwork.tmp-" + std::to_string(getpid()) + "-18";
    for (const std::string& name : {deadTemp, liveTemp, std::string(".doc.patchwork.tmp-x-1"), std::string("notes.tmp-1-2")})
        std::ofstream(dir / name) << "left";
    pw::writeFileAtomic(dir / "another.patchwork", "x");
    EXPECT_FALSE(fs::exists(dir / deadTemp));
    for (const char* kept : {".doc.patchwork.tmp-x-1", "notes.tmp-1-2"}) EXPECT_TRUE(fs::exists(dir / kept)) << kept;
    EXPECT_TRUE(fs::exists(dir / liveTemp));

    const pw::Document teapot = pw::builtinTeapot();
    for (const char* name : {"t.patchwork", "t.bpt", "t.glb", "t.gltf"}) {
        pw::saveDocument(teapot, dir / name);
        EXPECT_EQ(pw::loadDocument(dir / name).patches.size(), teapot.patches.size()) << name;
    }
    fs::remove_all(dir);
}

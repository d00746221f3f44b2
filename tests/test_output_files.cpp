// Outputs (issue 24): written through symlinks, refused onto anything but a regular writable file,
// permissions kept, hard-linked targets replaced atomically, several outputs all or nothing, no
// temporary file left behind; inputs that are not regular files refused before any read.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/io/document_io.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using namespace pw;

namespace {

std::string outputError(const fs::path& p, std::string_view data) {
    try {
        writeFileAtomic(p, data);
    } catch (const OutputError& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(OutputFiles, WritesThroughASymlinkToItsTarget) {
    const fs::path dir = test::freshTempDir("out-symlink");
    fs::create_directory(dir / "real");
    writeFileAtomic(dir / "real" / "a.txt", "old");
    fs::create_symlink("real/a.txt", dir / "link.txt");
    writeFileAtomic(dir / "link.txt", "new");
    EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
    EXPECT_EQ(test::readBytes(dir / "real" / "a.txt"), "new");
    EXPECT_EQ(test::entryCount(dir), 2u);
    EXPECT_EQ(test::entryCount(dir / "real"), 1u);
}

TEST(OutputFiles, RefusesADanglingSymlink) {
    const fs::path dir = test::freshTempDir("out-dangling");
    fs::create_symlink("nowhere/x.txt", dir / "link.txt");
    EXPECT_NE(outputError(dir / "link.txt", "x").find("link.txt"), std::string::npos);
    EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
    EXPECT_EQ(test::entryCount(dir), 1u);
}

TEST(OutputFiles, RefusesAFifoAndADeviceNode) {
    const fs::path dir = test::freshTempDir("out-special");
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0644), 0);
    const std::string e = outputError(dir / "fifo", "x");
    EXPECT_NE(e.find("a FIFO"), std::string::npos) << e;
    EXPECT_TRUE(fs::is_fifo(dir / "fifo"));
    // A character device like /dev/null, made in the temporary folder (needs root; never aimed at /dev).
    if (::mknod((dir / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
        const std::string d = outputError(dir / "null", "x");
        EXPECT_NE(d.find("a character device"), std::string::npos) << d;
        EXPECT_TRUE(fs::is_character_file(dir / "null"));
    }
    // Through a symlink too.
    fs::create_symlink("fifo", dir / "to-fifo");
    EXPECT_NE(outputError(dir / "to-fifo", "x").find("a FIFO"), std::string::npos);
    EXPECT_EQ(test::entryCount(dir), fs::exists(dir / "null") ? 3u : 2u);
}

TEST(OutputFiles, RefusesAReadOnlyFileAndKeepsIt) {
    const fs::path dir = test::freshTempDir("out-readonly");
    writeFileAtomic(dir / "ro.txt", "keep");
    fs::permissions(dir / "ro.txt", fs::perms::owner_read | fs::perms::group_read);
    EXPECT_NE(outputError(dir / "ro.txt", "lost").find("read-only"), std::string::npos);
    EXPECT_EQ(test::readBytes(dir / "ro.txt"), "keep");
    EXPECT_EQ(test::entryCount(dir), 1u);
}

TEST(OutputFiles, KeepsPermissions) {
    const fs::path dir = test::freshTempDir("out-mode");
    writeFileAtomic(dir / "secret.txt", "a");
    fs::permissions(dir / "secret.txt", fs::perms::owner_read | fs::perms::owner_write);
    writeFileAtomic(dir / "secret.txt", "b");
    EXPECT_EQ(fs::status(dir / "secret.txt").permissions(), fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(test::readBytes(dir / "secret.txt"), "b");
}

TEST(OutputFiles, AHardLinkedTargetIsReplacedAtomically) {
    // Rewriting a multiply linked file in place kept its other names on it, but a kill in the
    // middle left every name empty (issue 73): it is replaced like any other file, and the other
    // names keep the old one.
    const fs::path dir = test::freshTempDir("out-hardlink");
    writeFileAtomic(dir / "a.txt", "old");
    fs::create_hard_link(dir / "a.txt", dir / "b.txt");
    writeFileAtomic(dir / "a.txt", "new and longer");
    EXPECT_EQ(test::readBytes(dir / "a.txt"), "new and longer");
    EXPECT_EQ(test::readBytes(dir / "b.txt"), "old");
    EXPECT_EQ(fs::hard_link_count(dir / "a.txt"), 1u);
    EXPECT_EQ(test::entryCount(dir), 2u);
}

TEST(InputFiles, FifosDevicesAndKernelFilesAreRefusedBeforeAnyRead) {
    // A FIFO hung the .bpt reader (it peeked at the header first); /dev/zero read 2 GB; /proc files
    // say they are empty. Each is refused at once, naming what it is.
    const fs::path dir = test::freshTempDir("in-special");
    const fs::path fifo = dir / "model.bpt";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const fs::path& p : {fifo, fs::path(dir / "doc.patchwork")}) {
        if (p != fifo) {
            ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
        }
        try {
            (void)loadDocument(p);
            ADD_FAILURE() << p << " was read";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("a FIFO"), std::string::npos) << e.what();
        }
    }
    const fs::path zero = dir / "zero.patchwork";
    fs::create_symlink("/dev/zero", zero);
    EXPECT_THROW((void)readFileLimited(zero), InputError);
    try {
        (void)readFileLimited("/proc/self/status");
        ADD_FAILURE() << "/proc/self/status was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/proc or /sys"), std::string::npos) << e.what();
    }
    EXPECT_EQ(readFileHead("/proc/self/exe", 4).size(), 4u);  // a link to a regular file is read
    EXPECT_THROW((void)readFileLimited(dir), InputError);
}

TEST(OutputFiles, ABatchIsAllOrNothing) {
    const fs::path dir = test::freshTempDir("out-batch");
    writeFileAtomic(dir / "one.txt", "old one");
    {
        OutputBatch batch;
        batch.stage(dir / "one.txt", "new one");
        batch.stage(dir / "two.txt", "new two");
        EXPECT_THROW(batch.stage(dir / "missing" / "three.txt", "x"), OutputError);
    }  // not committed
    EXPECT_EQ(test::readBytes(dir / "one.txt"), "old one");
    EXPECT_FALSE(fs::exists(dir / "two.txt"));
    EXPECT_EQ(test::entryCount(dir), 1u);  // no temporary file left
    OutputBatch batch;
    batch.stage(dir / "one.txt", "new one");
    batch.stage(dir / "two.txt", "new two");
    EXPECT_EQ(test::readBytes(dir / "one.txt"), "old one");  // nothing visible before commit
    batch.commit();
    EXPECT_EQ(test::readBytes(dir / "one.txt"), "new one");
    EXPECT_EQ(test::readBytes(dir / "two.txt"), "new two");
    EXPECT_EQ(test::entryCount(dir), 2u);
}

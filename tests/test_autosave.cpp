// Autosave and crash recovery: an autosave left by a dead process is offered, one of a running
// process is not; discard removes the files; the recovered document equals the saved one.
#include <gtest/gtest.h>

#include <unistd.h>

#include "core/base/errors.hpp"
#include "core/construct/model_builders.hpp"
#include "core/edit/autosave.hpp"
#include "core/io/document_io.hpp"
#include "support.hpp"

using namespace pw;

TEST(EditorAutosave, DeadProcessIsRecoverable) {
    const auto dir = test::freshTempDir("autosave");
    Document doc = makePatchGrid(2, 2);
    doc.points[3].z += 0.25;
    // A pid that cannot be running (beyond the default pid_max).
    Autosaver dead(dir, 0x3ffffff0);
    dead.save(doc, "/somewhere/model.patchwork");
    Autosaver alive(dir, int(::getppid()));
    alive.save(doc, "");

    const auto found = findRecoverableAutosaves(dir);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].originalPath, "/somewhere/model.patchwork");
    EXPECT_EQ(found[0].pid, 0x3ffffff0);
    const Document back = loadDocument(found[0].document);
    EXPECT_EQ(back.points, doc.points);
    EXPECT_EQ(back.patches, doc.patches);
    EXPECT_EQ(back.joins, doc.joins);

    removeAutosave(found[0]);
    EXPECT_TRUE(findRecoverableAutosaves(dir).empty());
    alive.discard();
    EXPECT_FALSE(std::filesystem::exists(alive.documentPath()));
}

TEST(EditorAutosave, DirectoryFollowsXdgStateHome) {
    const char* old = std::getenv("XDG_STATE_HOME");
    const std::string keep = old ? old : "";
    setenv("XDG_STATE_HOME", "/tmp/xdg-test-state", 1);
    EXPECT_EQ(autosaveDirectory(), std::filesystem::path("/tmp/xdg-test-state/patchwork"));
    unsetenv("XDG_STATE_HOME");
    setenv("HOME", "/home/someone", 1);
    EXPECT_EQ(autosaveDirectory(), std::filesystem::path("/home/someone/.local/state/patchwork"));
    if (old) setenv("XDG_STATE_HOME", keep.c_str(), 1);
}

// Issue 24: Recover deleted the autosave at once, so a second crash within 30 s lost the work.
TEST(EditorAutosave, RecoveredAutosaveIsKeptUntilTheWorkIsSafeAgain) {
    const auto dir = test::freshTempDir("autosave-adopt");
    const Document doc = makePatchGrid(1, 1);
    Autosaver dead(dir, 0x3ffffff0);
    dead.save(doc, "");
    const auto found = findRecoverableAutosaves(dir);
    ASSERT_EQ(found.size(), 1u);
    {
        Autosaver me(dir, int(::getpid()));
        me.adopt(found[0]);
        // Recovered, not yet autosaved again: a crash now must still find it.
        EXPECT_TRUE(std::filesystem::exists(found[0].document));
        EXPECT_EQ(findRecoverableAutosaves(dir).size(), 1u);
        me.save(doc, "");  // our own autosave holds the work: the old one goes
        EXPECT_FALSE(std::filesystem::exists(found[0].document));
        EXPECT_FALSE(std::filesystem::exists(found[0].note));
        me.discard();
    }
    // Adopted, then saved to a file (discard): the old one goes too.
    dead.save(doc, "");
    Autosaver me(dir, int(::getpid()));
    me.adopt(findRecoverableAutosaves(dir).at(0));
    me.discard();
    EXPECT_TRUE(findRecoverableAutosaves(dir).empty());
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 0);
}

// Issue 24: with HOME unset autosaves went to a shared temp folder that another local user could
// plant files in, and they were world-readable.
TEST(EditorAutosave, TheFolderIsPrivate) {
    namespace fs = std::filesystem;
    const auto root = test::freshTempDir("autosave-private");
    const fs::path dir = root / "state";
    fs::create_directory(dir);
    fs::permissions(dir, fs::perms::all);  // 0777, as a shared folder
    Autosaver dead(dir, 0x3ffffff0);
    dead.save(makePatchGrid(1, 1), "");
    EXPECT_EQ(fs::status(dir).permissions() & fs::perms::all, fs::perms::owner_all);  // made private
    EXPECT_EQ(findRecoverableAutosaves(dir).size(), 1u);
    // Opened up again (or planted by someone): nothing is offered from it.
    fs::permissions(dir, fs::perms::all);
    EXPECT_TRUE(findRecoverableAutosaves(dir).empty());
    // A symlink in the folder's place is refused.
    fs::create_directory_symlink(dir, root / "link");
    EXPECT_THROW(ensurePrivateDirectory(root / "link"), OutputError);
    // Owned by another user (root can make one to try): refused.
    if (::geteuid() == 0) {
        fs::create_directory(root / "theirs");
        ASSERT_EQ(::chown((root / "theirs").c_str(), 65534, 65534), 0);
        EXPECT_THROW(ensurePrivateDirectory(root / "theirs"), OutputError);
    }
    // HOME unset: the temp folder's entry carries this user's id.
    const char* home = std::getenv("HOME");
    const char* xdg = std::getenv("XDG_STATE_HOME");
    const std::string keepHome = home ? home : "", keepXdg = xdg ? xdg : "";
    unsetenv("HOME");
    unsetenv("XDG_STATE_HOME");
    EXPECT_NE(autosaveDirectory().filename().string().find(std::to_string(::geteuid())), std::string::npos);
    if (home) setenv("HOME", keepHome.c_str(), 1);
    if (xdg) setenv("XDG_STATE_HOME", keepXdg.c_str(), 1);
}

// Autosave and crash recovery: an autosave left by a dead process is offered, one of a running
// process is not; discard removes the files; the recovered document equals the saved one.
#include <gtest/gtest.h>

#include <unistd.h>

#include "core/autosave.hpp"
#include "core/document_io.hpp"
#include "core/model_builders.hpp"
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

// BackgroundWriter (issue 24: a Ctrl+S during a long export was lost while the export held the
// editor's frame): exports are written in order on a worker, reported once each, and the caller's
// thread goes on meanwhile.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/construct/model_builders.hpp"
#include "core/edit/background_writer.hpp"
#include "core/io/document_io.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using namespace pw;

TEST(BackgroundWriter, WritesInOrderAndReportsEachOnce) {
    const fs::path dir = test::freshTempDir("background-writer");
    const Document big = makePatchGrid(24, 24);
    ExportOptions opts;
    opts.level = 40;
    BackgroundWriter w;
    EXPECT_EQ(w.enqueue(big, (dir / "a.glb").string(), opts), 0u);
    EXPECT_EQ(w.enqueue(makePatchGrid(2, 2), (dir / "b.gltf").string(), opts), 1u);
    // The caller is not held: both are still queued or being written (the first takes far longer
    // than these two calls).
    EXPECT_GE(w.pending(), 1u);
    EXPECT_FALSE(w.current().empty());
    w.waitIdle();
    EXPECT_EQ(w.pending(), 0u);
    EXPECT_EQ(w.current(), "");
    const auto done = w.takeFinished();
    ASSERT_EQ(done.size(), 2u);
    EXPECT_EQ(done[0].path, (dir / "a.glb").string());
    EXPECT_EQ(done[1].path, (dir / "b.gltf").string());
    EXPECT_EQ(done[0].error, "");
    EXPECT_EQ(done[1].error, "");
    EXPECT_TRUE(w.takeFinished().empty());
    EXPECT_EQ(loadDocument(dir / "a.glb").patches.size(), big.patches.size());
    EXPECT_EQ(loadDocument(dir / "b.gltf").patches.size(), 4u);
    fs::remove_all(dir);
}

TEST(BackgroundWriter, AFailedWriteIsReportedWithItsPathAndLeavesNothing) {
    const fs::path dir = test::freshTempDir("background-writer-fail");
    BackgroundWriter w;
    w.enqueue(makePatchGrid(2, 2), (dir / "missing" / "x.glb").string(), {});
    w.enqueue(makePatchGrid(2, 2), (dir / "ok.glb").string(), {});
    w.waitIdle();
    const auto done = w.takeFinished();
    ASSERT_EQ(done.size(), 2u);
    EXPECT_NE(done[0].error.find("missing"), std::string::npos) << done[0].error;
    EXPECT_EQ(done[1].error, "");  // one failure does not stop the queue
    EXPECT_EQ(test::entryCount(dir), 1u);
    fs::remove_all(dir);
}

TEST(BackgroundWriter, DestroyingItFinishesTheQueuedWrites) {
    const fs::path dir = test::freshTempDir("background-writer-exit");
    {
        BackgroundWriter w;
        for (int i = 0; i < 3; ++i) w.enqueue(makePatchGrid(8, 8), (dir / ("e" + std::to_string(i) + ".glb")).string(), {});
    }
    for (int i = 0; i < 3; ++i) EXPECT_NO_THROW((void)loadDocument(dir / ("e" + std::to_string(i) + ".glb"))) << i;
    fs::remove_all(dir);
}

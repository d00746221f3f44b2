// The bounded child that OpenCASCADE's readers and writers run in (core/io/bounded_child): its
// budget is processor time, so a child that waits (as on a loaded machine) is not refused, while
// one that computes past it is; its failures read the same for imports and exports.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/io/bounded_child.hpp"

using namespace pw;

TEST(BoundedChild, TheBudgetIsProcessorTimeNotWallTime) {
    // 0.4 s of waiting against a 0.2 s budget: no processor time used, so it finishes.
    const BoundedResult waited = runBounded(
        [] {
            std::this_thread::sleep_for(std::chrono::milliseconds(400));
            return std::string("slept");
        },
        0.2, 0);
    ASSERT_EQ(waited.kind, BoundedResult::Kind::Done);
    EXPECT_EQ(waited.output, "slept");
    // Computing without end: ended once its processor time passes the budget.
    const BoundedResult spun = runBounded(
        [] {
            volatile unsigned long x = 0;
            for (;;) x = x + 1;
            return std::string();
        },
        0.2, 0);
    EXPECT_EQ(spun.kind, BoundedResult::Kind::TimedOut);
    // Waiting past three budgets of wall time ends it too.
    const BoundedResult stuck = runBounded(
        [] {
            std::this_thread::sleep_for(std::chrono::seconds(30));
            return std::string();
        },
        0.1, 0);
    EXPECT_EQ(stuck.kind, BoundedResult::Kind::TimedOut);
}

TEST(BoundedChild, FailuresReadTheSameForImportsAndExports) {
    BoundedResult r;
    r.kind = BoundedResult::Kind::TimedOut;
    const std::string timed = cadChildFailure(r, "reading it", 8.0, std::size_t{1} << 30);
    EXPECT_NE(timed.find("did not finish reading it within 8 s of processor time"), std::string::npos) << timed;
    EXPECT_NE(timed.find("PATCHWORK_CAD_SECONDS"), std::string::npos) << timed;
    r.kind = BoundedResult::Kind::OutOfMemory;
    EXPECT_NE(cadChildFailure(r, "writing it", 8.0, std::size_t{1} << 30).find("needed more than 1024 MiB writing it"), std::string::npos);
    r.kind = BoundedResult::Kind::Crashed;
    r.signal = 11;
    EXPECT_NE(cadChildFailure(r, "writing it", 8.0, 0).find("crashed writing it (signal 11"), std::string::npos);
}

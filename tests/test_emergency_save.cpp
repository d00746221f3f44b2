// The emergency save (issue 72): a process that dies of SIGABRT (a failed assertion) or SIGSEGV
// leaves its last committed document where the next start offers it for recovery; a process whose
// document was unmodified leaves nothing. Each case runs in a forked child that really dies.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>
#include <cstdlib>

#include "core/construct/model_builders.hpp"
#include "core/edit/autosave.hpp"
#include "core/edit/emergency_save.hpp"
#include "core/io/document_io.hpp"
#include "support.hpp"

using namespace pw;

namespace {

Document committedState(double lift) {
    Document doc = makePatchGrid(2, 2);
    doc.points[4].z += lift;
    doc.name = "lifted";
    return doc;
}

// Forks a child that installs the emergency save, submits `states` documents (the last one with
// `lastModified`), then dies of `sig`; returns the child's pid after checking that it died of it.
pid_t dieAfterCommits(const std::filesystem::path& dir, int states, bool lastModified, int sig) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        rlimit none{0, 0};
        ::setrlimit(RLIMIT_CORE, &none);  // no core file for the deliberate crash
        Autosaver paths(dir);
        EmergencySave emergency(paths.documentPath(), paths.notePath());
        for (int i = 1; i <= states; ++i) {
            if (i == states && !lastModified)
                emergency.clear(uint64_t(i));
            else
                emergency.submit(committedState(0.1 * i), "/work/model.patchwork", uint64_t(i));
            emergency.waitIdle();
        }
        if (emergency.published() != uint64_t(states)) std::_Exit(3);
        if (sig == SIGSEGV) {
            ::raise(SIGSEGV);
        } else {
            std::abort();
        }
        std::_Exit(4);
    }
    int status = 0;
    EXPECT_EQ(::waitpid(pid, &status, 0), pid);
    // It died of the signal; under AddressSanitizer a SIGSEGV goes on to ASan's own handler
    // (restored after ours), which reports it and exits with status 1. Statuses 3 and 4 are the
    // child's own failures.
    const bool exitedByAsan = WIFEXITED(status) && WEXITSTATUS(status) == 1 && sig == SIGSEGV;
    EXPECT_TRUE(WIFSIGNALED(status) || exitedByAsan) << "the child exited with " << WEXITSTATUS(status);
    if (WIFSIGNALED(status)) {
        EXPECT_EQ(WTERMSIG(status), sig);
    }
    return pid;
}

}  // namespace

TEST(EmergencySave, AnAbortLeavesTheLastCommittedEditForRecovery) {
    const auto dir = test::freshTempDir("emergency-abort");
    ensurePrivateDirectory(dir);
    const pid_t child = dieAfterCommits(dir, 3, true, SIGABRT);
    const std::vector<AutosaveEntry> found = findRecoverableAutosaves(dir);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pid, int(child));
    EXPECT_EQ(found[0].originalPath, "/work/model.patchwork");
    const Document back = loadDocument(found[0].document);
    const Document last = committedState(0.3);  // the third commit, not an earlier one
    EXPECT_EQ(back.points, last.points);
    EXPECT_EQ(back.patches, last.patches);
    EXPECT_EQ(back.name, "lifted");
    // Nothing half-written is left beside it.
    for (const auto& e : std::filesystem::directory_iterator(dir)) EXPECT_EQ(e.path().extension() == ".emergency", false) << e.path();
}

TEST(EmergencySave, ASegmentationFaultSavesToo) {
    const auto dir = test::freshTempDir("emergency-segv");
    ensurePrivateDirectory(dir);
    dieAfterCommits(dir, 1, true, SIGSEGV);
    const std::vector<AutosaveEntry> found = findRecoverableAutosaves(dir);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(loadDocument(found[0].document).points, committedState(0.1).points);
}

TEST(EmergencySave, AnUnmodifiedDocumentLeavesNothing) {
    const auto dir = test::freshTempDir("emergency-clean");
    ensurePrivateDirectory(dir);
    dieAfterCommits(dir, 2, false, SIGABRT);  // saved after the first edit: nothing to recover
    EXPECT_TRUE(findRecoverableAutosaves(dir).empty());
}

TEST(EmergencySave, OnlyOneInstallPerProcess) {
    const auto dir = test::freshTempDir("emergency-twice");
    EmergencySave first(dir / "a.patchwork", dir / "a.json");
    EXPECT_THROW(EmergencySave(dir / "b.patchwork", dir / "b.json"), std::logic_error);
}

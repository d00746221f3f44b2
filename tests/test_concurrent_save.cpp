// Two editors on one file (issue 73): the second save used to discard the first's work silently.
// A session remembers its file's stamp when it opens or saves it; a save over a file another
// program wrote since is refused, naming what to do, and goes ahead with `overwrite`.
#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/model_builders.hpp"
#include "core/edit/edit_session.hpp"
#include "core/io/document_io.hpp"
#include "support.hpp"

using namespace pw;

namespace {

// Saves for real (the `save` command through a host that writes, as the editor's does).
class WritingHost final : public CommandHost {
public:
    void write(const Document& doc, const std::string& path) override { saveDocument(doc, path); }
};

void run(EditSession& s, const std::string& line) {
    static const CommandTable table = makeCommandTable();
    WritingHost host;
    test::runCommands(table, s, host, line);
}

}  // namespace

TEST(ConcurrentSave, ASecondEditorsSaveIsNotDiscardedSilently) {
    const auto dir = test::freshTempDir("concurrent-save");
    const std::string file = (dir / "model.patchwork").string();
    saveDocument(makePatchGrid(2, 2), file);

    EditSession first, second;
    first.open(file);
    second.open(file);
    run(second, "select patch 0; move 0 0 0.2");
    run(second, "save " + file);  // the second editor saves first
    const Document secondsWork = loadDocument(file);

    run(first, "select patch 1; move 0 0 -0.2");
    try {
        run(first, "save " + file);
        FAIL() << "the first editor's save replaced the second's work";
    } catch (const EditError& e) {
        EXPECT_NE(std::string(e.what()).find("changed by another program"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("overwrite"), std::string::npos) << e.what();
    }
    EXPECT_EQ(loadDocument(file).points, secondsWork.points);  // nothing was written
    EXPECT_TRUE(first.isModified());

    // Asked for, it replaces the file; then its own later saves go ahead without asking.
    run(first, "save " + file + " overwrite");
    EXPECT_EQ(loadDocument(file).points, first.doc.points);
    run(first, "select patch 2; move 0.2 0 0");
    run(first, "save " + file);
    EXPECT_EQ(loadDocument(file).points, first.doc.points);
    // Saving under another name is never refused.
    run(second, "select patch 3; move 0 1 0");
    run(second, "save " + (dir / "other.patchwork").string());
}

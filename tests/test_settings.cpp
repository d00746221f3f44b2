// The settings table (core/model/settings.hpp) read by the panels, the `set` command and the
// .patchwork reader: one range per setting, so what one accepts the others accept (issue 38: a
// level typed as -5 in the Tessellation panel was saved, and the file was refused on reopening).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/edit/edit_session.hpp"
#include "core/io/document_io.hpp"
#include "core/model/settings.hpp"
#include "support.hpp"

using namespace pw;
namespace fs = std::filesystem;

namespace {

void run(EditSession& s, const std::vector<std::string>& words) {
    test::NoWritesHost host;
    makeCommandTable().run(s, host, words);
}

std::string refusal(EditSession& s, const std::vector<std::string>& words) {
    try {
        run(s, words);
    } catch (const EditError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Settings, EveryRowHoldsItsDefaultAndReadsBackWhatItWrites) {
    const Document d;
    ASSERT_GE(settings().size(), 20u);
    for (const Setting& s : settings()) {
        const std::vector<double> v = s.get(d);
        EXPECT_EQ(v.size(), size_t(s.count)) << s.key;
        EXPECT_FALSE(settingProblem(s, v).has_value()) << s.key << ": " << settingProblem(s, v).value_or("");
        EXPECT_FALSE(s.label.empty() || s.tooltip.empty()) << s.key;
        EXPECT_EQ(findSetting(s.key), &s);
        // Through the words of a command line and back to the same floats the document holds.
        const std::vector<double> back = parseSettingValues(s, formatSettingValues(s, v));
        ASSERT_EQ(back.size(), v.size()) << s.key;
        for (size_t i = 0; i < v.size(); ++i) EXPECT_EQ(float(back[i]), float(v[i])) << s.key;
    }
    EXPECT_EQ(findSetting("tess.nonsense"), nullptr);
}

TEST(Settings, SetRefusesAValueOutsideTheRowsRangeAndLeavesTheDocument) {
    EditSession s;
    const Document before = s.doc;
    EXPECT_NE(refusal(s, {"set", "tess.level", "-5"}).find("set: tess.level: value -5 is outside [1, 64]"), std::string::npos);
    EXPECT_NE(refusal(s, {"set", "tess.outer", "4", "4", "4"}).find("expected 4 values, got 3"), std::string::npos);
    EXPECT_NE(refusal(s, {"set", "tess.maxLevel", "nan"}).find("not a finite number"), std::string::npos);
    EXPECT_NE(refusal(s, {"set", "tess.spacing", "integer_ish"}).find("expected one of equal, fractional_odd"), std::string::npos);
    EXPECT_NE(refusal(s, {"set", "display.showGrid", "maybe"}).find("expected on or off"), std::string::npos);
    EXPECT_NE(refusal(s, {"set", "display.combDensity", "5.5"}).find("not a whole number"), std::string::npos);
    EXPECT_NE(refusal(s, {"set", "tess.wobble", "1"}).find("no setting named 'tess.wobble'; keys: tess.linked"), std::string::npos);
    EXPECT_NE(refusal(s, {"tess", "-5"}).find("value -5 is outside [1, 64]"), std::string::npos);
    EXPECT_EQ(s.doc, before);
    EXPECT_FALSE(s.history().canUndo());
}

TEST(Settings, SetIsOneUndoStepNamedByTheRow) {
    EditSession s;
    run(s, {"set", "tess.maxLevel", "12"});
    run(s, {"set", "tess.spacing", "fractional_odd"});
    run(s, {"set", "display.showGrid", "off"});
    run(s, {"set", "display.background", "1", "0.5", "0.25"});
    run(s, {"set", "tess.outer", "2", "3", "4", "5"});
    EXPECT_EQ(s.doc.tess.maxLevel, 12.0f);
    EXPECT_EQ(s.doc.tess.spacing, Spacing::FractionalOdd);
    EXPECT_FALSE(s.doc.display.showGrid);
    EXPECT_EQ(s.doc.display.background, (std::array<float, 3>{1.0f, 0.5f, 0.25f}));
    EXPECT_EQ(s.doc.tess.outer, (std::array<float, 4>{2, 3, 4, 5}));
    EXPECT_EQ(s.history().size(), 5u);
    s.undo();
    EXPECT_EQ(s.doc.tess.outer, (std::array<float, 4>{16, 16, 16, 16}));
    run(s, {"set", "tess.level", "7"});  // the linked level writes all six and links them
    EXPECT_EQ(s.doc.tess.inner, (std::array<float, 2>{7, 7}));
    EXPECT_TRUE(s.doc.tess.linked);
    // "integer" is the notes' name for equal spacing, accepted wherever equal is.
    run(s, {"set", "tess.spacing", "integer"});
    EXPECT_EQ(s.doc.tess.spacing, Spacing::Equal);
    run(s, {"set", "tess.spacing", "pow2"});
    run(s, {"tess-fixed", "integer", "1", "2", "3", "4", "4", "4"});
    EXPECT_EQ(s.doc.tess.spacing, Spacing::Equal);
    EXPECT_EQ(s.doc.tess.outer, (std::array<float, 4>{1, 2, 3, 4}));
}

// A panel's slider: previews while it moves (no undo step), then the same command commits once.
TEST(Settings, APreviewChangesTheDocumentWithoutAnUndoStepUntilTheCommandRuns) {
    EditSession s;
    test::NoWritesHost host;
    const CommandTable table = makeCommandTable();
    const uint64_t version = s.version();
    for (const char* level : {"20", "30", "40"}) table.preview(s, host, {"set", "tess.level", level});
    EXPECT_EQ(s.doc.tess.outer[0], 40.0f);
    EXPECT_GT(s.version(), version);
    EXPECT_FALSE(s.history().canUndo());
    table.run(s, host, std::vector<std::string>{"set", "tess.level", "40"});
    EXPECT_EQ(s.history().size(), 1u);
    s.undo();
    EXPECT_EQ(s.doc.tess.outer[0], 16.0f);
    // A refused preview leaves the document; commands that are not previewable are refused.
    EXPECT_THROW(table.preview(s, host, {"set", "tess.level", "-5"}), EditError);
    EXPECT_EQ(s.doc.tess.outer[0], 16.0f);
    EXPECT_THROW(table.preview(s, host, {"add-patch"}), EditError);
}

// Whatever the command accepts, the file reader reopens; what it refuses, the reader refuses too.
TEST(Settings, TheFileReaderAcceptsExactlyTheRowsRange) {
    const fs::path dir = test::freshTempDir("settings");
    for (const Setting& row : settings()) {
        if (row.kind != SettingKind::Number) continue;
        // Displacement settings are saved with a height map only (DESIGN §11): their range is checked below.
        const bool savedAlone = !row.key.starts_with("displacement.");
        for (double edge : {row.min, row.max}) {
            if (!savedAlone) break;
            EditSession s;
            std::vector<std::string> words = {"set", std::string(row.key)};
            for (int i = 0; i < row.count; ++i) words.push_back(formatSettingValues(row, {edge})[0]);
            run(s, words);
            const fs::path file = dir / "edge.patchwork";
            saveDocument(s.doc, file);
            const Document back = loadDocument(file);
            EXPECT_EQ(row.get(back), row.get(s.doc)) << row.key << " = " << edge;
        }
        if (row.key == "tess.level") continue;  // written as tess.outer and tess.inner
        // One past the range in the file: refused, naming the field.
        EditSession s;
        const fs::path file = dir / "bad.patchwork";
        saveDocument(s.doc, file);
        nlohmann::json j = nlohmann::json::parse(test::readBytes(file));
        const std::string section(row.key.substr(0, row.key.find('.'))), field(row.key.substr(row.key.find('.') + 1));
        nlohmann::json bad = row.max + 1.0;
        if (row.count > 1) bad = std::vector<double>(size_t(row.count), row.max + 1.0);
        j[section][field] = bad;
        std::ofstream(file, std::ios::binary | std::ios::trunc) << j.dump();
        try {
            loadDocument(file);
            ADD_FAILURE() << row.key << " = " << bad << " was accepted";
        } catch (const std::exception& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
    }
}

// CAD files that are never silently wrong (issue 73): a STEP file without a valid length unit is
// refused, or read in the unit --unit gives with a note; names of any length or script are written
// so that the file reads back (IGES's writer crashed on a long one, in the process); every STEP and
// IGES export is read back by OpenCASCADE with all its faces before it replaces anything.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/base/errors.hpp"
#include "core/construct/model_builders.hpp"
#include "core/io/cad_labels.hpp"
#include "core/io/step_export.hpp"
#include "core/io/step_import.hpp"
#include "support.hpp"

using namespace pw;

namespace {

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
    return s;
}

}  // namespace

TEST(CadSafety, AStepFileWithoutAValidLengthUnitIsRefusedOrReadInTheUnitGiven) {
    const auto dir = test::freshTempDir("cad-unit");
    Document doc = makePatchGrid(2, 2);
    doc.unit = LengthUnit::Millimetre;
    exportStep(doc, dir / "plate.step");
    const std::string text = test::readBytes(dir / "plate.step");
    ASSERT_NE(text.find("SI_UNIT(.MILLI.,.METRE.)"), std::string::npos);
    // The unit replaced by one no CAD system writes for lengths (a length in seconds).
    const std::string bad = replaceAll(text, "SI_UNIT(.MILLI.,.METRE.)", "SI_UNIT($,.SECOND.)");
    ASSERT_NE(bad, text);
    std::ofstream(dir / "unitless.step", std::ios::binary) << bad;
    try {
        (void)importCadSurfaces(dir / "unitless.step");
        FAIL() << "a STEP file without a length unit was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--unit"), std::string::npos) << e.what();
    }
    assumeCadUnit(LengthUnit::Inch);
    CadImportReport report;
    const Document back = importCadSurfaces(dir / "unitless.step", &report);
    assumeCadUnit(std::nullopt);
    EXPECT_EQ(back.unit, LengthUnit::Inch);
    EXPECT_EQ(back.patches.size(), 4u);
    ASSERT_FALSE(report.notes.empty());
    EXPECT_NE(report.notes.back().find("as --unit says"), std::string::npos) << report.notes.back();
    // The file with its unit is read in it, with no note.
    CadImportReport clean;
    EXPECT_EQ(importCadSurfaces(dir / "plate.step", &clean).unit, LengthUnit::Millimetre);
    EXPECT_TRUE(clean.notes.empty());
}

TEST(CadSafety, NamesOfAnyLengthOrScriptGiveFilesThatReadBack) {
    const auto dir = test::freshTempDir("cad-names");
    std::string accents;
    for (int i = 0; i < 10000; ++i) accents += "é";
    for (const std::string& name : {std::string(1300, 'n'), std::string(30000, 'x'), accents, std::string("two\nlines\tand\x01")}) {
        Document doc = makePatchGrid(2, 1);
        doc.name = name;
        doc.patches[0].name = name;
        for (const char* file : {"named.step", "named.igs"}) {
            SCOPED_TRACE(std::string(file) + " with a name of " + std::to_string(name.size()) + " bytes");
            const StepExportStats stats = exportStep(doc, dir / file);
            EXPECT_EQ(stats.faces, 2u);
            EXPECT_EQ(importCadSurfaces(dir / file).patches.size(), 2u);
        }
    }
    EXPECT_EQ(cadSafeName("a\nb", 10, false), "a b");
    EXPECT_EQ(cadSafeName("éé", 3, false), "é");  // cut between characters, never inside one
    EXPECT_EQ(cadSafeName("éa", 10, true), "_a");
}

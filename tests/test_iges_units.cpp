// IGES at the right size in every unit, both ways (issue 66); a unit Patchwork does not have (feet)
// comes in converted to the nearest one it has, with a note. OpenCASCADE 7.6 takes the shape's
// unit from the IGES model's global section, not from the session's unit: a metre document was
// written 1 000× too small and a metre file read 1 000× too large, and Patchwork's own round trip
// hid it (both directions off by the same factor). So each direction is checked against
// OpenCASCADE used directly, in millimetres, as another program would.
#include <gtest/gtest.h>

#include <BRepBndLib.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <Bnd_Box.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>

#include <array>
#include <filesystem>

#include "core/io/document_io.hpp"
#include "core/io/occt_support.hpp"
#include "core/io/step_export.hpp"
#include "core/io/step_import.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using namespace pw;

namespace {

// A 2 000 × 1 000 × 500 mm box written by OpenCASCADE's IGES writer in `unit` ("M", "IN", "MM").
void writeBox(const fs::path& file, const char* unit) {
    const auto held = occt::lock();
    IGESControl_Controller::Init();
    Interface_Static::SetIVal("write.iges.brep.mode", 1);
    IGESControl_Writer writer(unit, 1);
    writer.Model()->ChangeGlobalSection().SetCascadeUnit(1.0);  // the shape is in millimetres
    ASSERT_TRUE(writer.AddShape(BRepPrimAPI_MakeBox(2000.0, 1000.0, 500.0).Shape()));
    writer.ComputeModel();
    ASSERT_TRUE(writer.Write(file.c_str()));
}

// The bounds of an IGES file's shape in millimetres, as OpenCASCADE reads it for a program in mm.
std::array<double, 6> boundsInMm(const fs::path& file) {
    const auto held = occt::lock();
    IGESControl_Controller::Init();
    IGESControl_Reader reader;
    EXPECT_EQ(reader.ReadFile(file.c_str()), IFSelect_RetDone);
    reader.IGESModel()->ChangeGlobalSection().SetCascadeUnit(1.0);
    EXPECT_GT(reader.TransferRoots(), 0);
    Bnd_Box box;
    BRepBndLib::Add(reader.OneShape(), box);
    std::array<double, 6> b{};
    box.Get(b[0], b[1], b[2], b[3], b[4], b[5]);
    return b;
}

}  // namespace

TEST(IgesUnits, FilesInMetresAndInchesComeInAtTheirSize) {
    const fs::path dir = test::freshTempDir("iges-units");
    struct Case {
        const char* flag;
        LengthUnit unit;
        double perMm;  // the file's unit per millimetre
    };
    // Feet are not a unit Patchwork has: they come in as inches, at the same size, with a note.
    for (const Case& c :
         {Case{"M", LengthUnit::Metre, 1e-3}, Case{"IN", LengthUnit::Inch, 1 / 25.4}, Case{"MM", LengthUnit::Millimetre, 1.0},
          Case{"CM", LengthUnit::Centimetre, 0.1}, Case{"FT", LengthUnit::Inch, 1 / 25.4}}) {
        SCOPED_TRACE(c.flag);
        const fs::path file = dir / (std::string("box-") + c.flag + ".igs");
        writeBox(file, c.flag);
        CadImportReport report;
        const Document d = importCadSurfaces(file, &report);
        EXPECT_EQ(d.unit, c.unit);
        bool noted = false;  // feet come in as inches, at their size
        for (const std::string& n : report.notes) noted = noted || n.find("not one Patchwork has; read in in") != std::string::npos;
        EXPECT_EQ(noted, std::string(c.flag) == "FT");
        Vec3 lo(1e300), hi(-1e300);
        for (const Vec3& p : d.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
        EXPECT_NEAR(hi.x - lo.x, 2000.0 * c.perMm, 1e-6 * 2000.0 * c.perMm);
        EXPECT_NEAR(hi.y - lo.y, 1000.0 * c.perMm, 1e-6 * 2000.0 * c.perMm);
        EXPECT_NEAR(hi.z - lo.z, 500.0 * c.perMm, 1e-6 * 2000.0 * c.perMm);
    }
    fs::remove_all(dir);
}

TEST(IgesUnits, ExportsInMetresAndInchesAreWrittenAtTheirSize) {
    const fs::path dir = test::freshTempDir("iges-units-out");
    // The vase is 3 m tall (z from -0.049 to 3 on its surface); the same in inches.
    Document vase = loadDocument(test::dataDir() / "vase.patchwork");
    ASSERT_EQ(vase.unit, LengthUnit::Metre);
    exportStep(vase, dir / "vase-m.igs");
    const std::array<double, 6> m = boundsInMm(dir / "vase-m.igs");
    EXPECT_NEAR(m[5], 3000.0, 1.0);
    EXPECT_GE(m[2], -98.0);  // the foot: -49 mm on the surface, -98 on its control points
    EXPECT_LE(m[2], -48.0);
    vase.unit = LengthUnit::Inch;
    exportStep(vase, dir / "vase-in.igs");
    const std::array<double, 6> in = boundsInMm(dir / "vase-in.igs");
    EXPECT_NEAR(in[5], 3 * 25.4, 0.05);
    // And Patchwork reads both back in their own unit at the same numbers.
    const Document back = importCadSurfaces(dir / "vase-m.igs");
    EXPECT_EQ(back.unit, LengthUnit::Metre);
    double top = -1e300;
    for (const Vec3& p : back.points) top = std::max(top, p.z);
    EXPECT_NEAR(top, 3.0, 1e-6);
    fs::remove_all(dir);
}

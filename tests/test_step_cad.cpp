// CAD-grade STEP interchange (issue 42), read back by OpenCASCADE itself: closed models are solids
// with their volume, a Y-up document stands upright (STEP is Z-up), the document's unit is the
// file's length unit both ways, patch names are face names and the document's name the product's;
// CAD parts made of planes, cylinders, cones, spheres, tori and swept surfaces import exactly, and
// what cannot be imported is reported with its share of the area; IGES is written like STEP.
#include <gtest/gtest.h>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BezierCurve.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <StepData_StepModel.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "core/base/errors.hpp"
#include "core/base/up_axis.hpp"
#include "core/construct/primitives.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/io/bpt_format.hpp"
#include "core/io/cad_labels.hpp"
#include "core/io/occt_support.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/io/step_export.hpp"
#include "core/io/step_import.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/ops/net_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

constexpr double kPi = std::numbers::pi;

// The shape OpenCASCADE reads from `text`, in `unit` (its default is millimetres).
TopoDS_Shape readStepText(const std::string& text, pw::LengthUnit unit = pw::LengthUnit::Metre) {
    STEPControl_Reader reader;
    std::istringstream in(text);
    EXPECT_EQ(reader.ReadStream("doc.step", in), IFSelect_RetDone);
    reader.StepModel()->SetLocalLengthUnit(pw::occt::useLengthUnit(unit));
    reader.TransferRoots();
    return reader.OneShape();
}

int count(const TopoDS_Shape& s, TopAbs_ShapeEnum type) {
    TopTools_IndexedMapOfShape m;
    TopExp::MapShapes(s, type, m);
    return m.Extent();
}

double volume(const TopoDS_Shape& s) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(s, props);
    return props.Mass();
}

double area(const TopoDS_Shape& s) {  // adaptive integration to a relative error of 1e-10
    GProp_GProps props;
    BRepGProp::SurfaceProperties(s, props, 1e-10);
    return props.Mass();
}

void writeStep(const TopoDS_Shape& shape, const fs::path& path, pw::LengthUnit unit = pw::LengthUnit::Millimetre) {
    STEPControl_Writer w;  // in `unit`, the numbers as they are
    Interface_Static::SetCVal("write.step.unit", pw::occt::unitName(unit));
    const double mm = pw::occt::useLengthUnit(unit);
    w.Model()->SetLocalLengthUnit(mm);
    w.Model()->SetWriteLengthUnit(mm);
    ASSERT_EQ(w.Transfer(shape, STEPControl_AsIs), IFSelect_RetDone);
    ASSERT_EQ(w.Write(path.string().c_str()), IFSelect_RetDone);
}

// Largest distance from 5 x 5 points of every imported patch to the nearest face of `shape`
// (OpenCASCADE's projection onto each face's own surface), relative to nothing: in file units.
double worstDistanceToShape(const pw::Document& doc, const TopoDS_Shape& shape) {
    // One projector per face, over the surface's whole range: its search grid is built once, not
    // once per point (which made this a 20-second test on a rational sphere).
    std::deque<GeomAPI_ProjectPointOnSurf> projectors;  // not movable: a deque constructs them in place
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
        const Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(e.Current()));
        double u0, u1, v0, v1;
        s->Bounds(u0, u1, v0, v1);
        projectors.emplace_back().Init(s, u0, u1, v0, v1);
    }
    double worst = 0.0;
    for (uint32_t p = 0; p < doc.patches.size(); ++p)
        for (int i = 0; i <= 4; ++i)
            for (int j = 0; j <= 4; ++j) {
                const pw::Vec3 q = pw::test::patchPointAt(doc, p, j / 4.0, i / 4.0);
                double best = 1e300;
                for (auto& proj : projectors) {
                    proj.Perform(gp_Pnt(q.x, q.y, q.z));
                    if (proj.NbPoints() > 0) best = std::min(best, proj.LowerDistance());
                }
                worst = std::max(worst, best);
            }
    return worst;
}

}  // namespace

// Closed documents are solids (MANIFOLD_SOLID_BREP of a CLOSED_SHELL), faces outwards: FreeCAD and
// every CAD reader get a volume; open ones stay shells.
TEST(StepSolids, ClosedModelsAreSolidsWithTheirVolume) {
    struct Case {
        const char* what;
        pw::Document doc;
        double volume;
    };
    std::vector<Case> cases;
    {
        pw::Document d;
        pw::addSphere(d, {0.5, 1.0, -2.0}, 2.0, true);
        cases.push_back({"sphere", d, 4.0 / 3.0 * kPi * 8.0});
    }
    {
        pw::Document d;
        pw::addTorus(d, {0, 0, 0}, 3.0, 1.0, true);
        cases.push_back({"torus", d, 2.0 * kPi * kPi * 3.0 * 1.0});
    }
    {
        pw::Document d;
        pw::addCylinder(d, {0, 0, 0}, 1.0, 2.0, true);
        cases.push_back({"cylinder", d, kPi * 1.0 * 2.0});
    }
    {
        pw::Document d;
        pw::addCone(d, {0, 0, 0}, 1.0, 3.0, true);
        cases.push_back({"cone", d, kPi * 1.0 * 3.0 / 3.0});
    }
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        pw::StepExportStats stats;
        const std::string text = pw::exportStepText(c.doc, {}, &stats);
        EXPECT_EQ(stats.solids, 1u);
        EXPECT_NE(text.find("MANIFOLD_SOLID_BREP"), std::string::npos);
        EXPECT_NE(text.find("CLOSED_SHELL"), std::string::npos);
        EXPECT_EQ(text.find("OPEN_SHELL"), std::string::npos);
        const TopoDS_Shape shape = readStepText(text);
        EXPECT_EQ(count(shape, TopAbs_SOLID), 1);
        // Positive and right: the faces point outwards.
        EXPECT_NEAR(volume(shape), c.volume, 1e-6 * c.volume);
    }
    // The teapot's pieces are open (its spout and handle only touch the body): shells, no solid.
    pw::StepExportStats stats;
    const std::string text = pw::exportStepText(pw::loadBpt(pw::test::dataDir() / "teapot.bpt"), {}, &stats);
    EXPECT_EQ(stats.solids, 0u);
    EXPECT_EQ(text.find("MANIFOLD_SOLID_BREP"), std::string::npos);
}

// STEP is +Z up: a Y-up document is turned a quarter about X on the way out, exactly, and comes
// back a Z-up document standing the same way.
TEST(StepUpAxis, AYUpDocumentStandsUprightAndComesBackZUp) {
    const fs::path dir = pw::test::freshTempDir("step-up");
    pw::Document doc;
    pw::addCylinder(doc, {0, 0, 0}, 1.0, 4.0, false);  // standing along +Y
    doc.camera.zUp = false;
    pw::exportStep(doc, dir / "tall.step");
    Bnd_Box box;
    BRepBndLib::AddOptimal(readStepText(pw::test::readBytes(dir / "tall.step")), box, false, false);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    EXPECT_NEAR(z1 - z0, 4.0, 1e-6);  // its height is along +Z
    EXPECT_NEAR(y1 - y0, 2.0, 1e-6);
    EXPECT_NEAR(z0, 0.0, 1e-6);
    const pw::Document back = pw::importCadSurfaces(dir / "tall.step");
    EXPECT_TRUE(back.camera.zUp);
    // Every imported control point is a turned control point of the document.
    for (const pw::Vec3& p : back.points) {
        double best = 1e300;
        for (const pw::Vec3& q : doc.points) best = std::min(best, glm::length(pw::yUpToZUp(q) - p));
        EXPECT_LT(best, 1e-12);
    }
    fs::remove_all(dir);
}

// The document's unit is the STEP file's length unit, written and read; a CAD file's own unit
// becomes the document's (millimetres from OpenCASCADE's writer, inches), the numbers unchanged.
TEST(StepUnits, TheDocumentsUnitIsTheFilesUnit) {
    const fs::path dir = pw::test::freshTempDir("step-units");
    pw::Document doc = pw::loadBpt(pw::test::dataDir() / "teapot.bpt");
    EXPECT_NE(pw::exportStepText(doc, {}).find("SI_UNIT($,.METRE.)"), std::string::npos);
    for (pw::LengthUnit unit : {pw::LengthUnit::Millimetre, pw::LengthUnit::Centimetre, pw::LengthUnit::Metre, pw::LengthUnit::Inch}) {
        SCOPED_TRACE(std::string(pw::lengthUnitName(unit)));
        doc.unit = unit;
        pw::exportStep(doc, dir / "pot.step");
        const pw::Document back = pw::importCadSurfaces(dir / "pot.step");
        EXPECT_EQ(back.unit, unit);
        ASSERT_EQ(back.points.size(), doc.points.size());
        double worst = 0.0;
        for (const pw::Vec3& p : back.points) {
            double best = 1e300;
            for (const pw::Vec3& q : doc.points) best = std::min(best, glm::length(q - p));
            worst = std::max(worst, best);
        }
        EXPECT_LT(worst, 1e-9);
        // The .patchwork file keeps it.
        EXPECT_EQ(pw::parseDocument(pw::serializeDocument(back), "x.patchwork").unit, unit);
    }
    // OpenCASCADE's own file of a 10 x 20 x 30 box in inches: 10, 20, 30 inches.
    writeStep(BRepPrimAPI_MakeBox(10, 20, 30).Shape(), dir / "box.step", pw::LengthUnit::Inch);
    const pw::Document box = pw::importCadSurfaces(dir / "box.step");
    EXPECT_EQ(box.unit, pw::LengthUnit::Inch);
    double top = 0.0;
    for (const pw::Vec3& p : box.points) top = std::max(top, p.z);
    EXPECT_NEAR(top, 30.0, 1e-9);
    // A .patchwork file with an unknown unit is refused naming the field.
    try {
        pw::parseDocument(R"({"format": "patchwork", "version": 1, "unit": "furlong", "points": []})", "u.patchwork");
        ADD_FAILURE() << "an unknown unit was accepted";
    } catch (const pw::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unit"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("furlong"), std::string::npos) << e.what();
    }
    fs::remove_all(dir);
}

// File ▸ Unit (`unit in`) relabels the document in one undo step; an unknown unit is refused.
TEST(StepUnits, TheUnitCommandIsOneUndoStep) {
    pw::EditSession session;
    session.reset(pw::loadBpt(pw::test::dataDir() / "teapot.bpt"), "");
    const pw::Document before = session.doc;
    pw::test::runEditScript(session, "unit in");
    EXPECT_EQ(session.doc.unit, pw::LengthUnit::Inch);
    EXPECT_EQ(session.doc.points, before.points);  // relabelled, not scaled
    EXPECT_TRUE(session.isModified());
    EXPECT_EQ(session.history().undoLabel(), "Unit in");
    ASSERT_TRUE(session.undo());
    EXPECT_TRUE(session.doc == before);
    EXPECT_THROW(pw::test::runEditScript(session, "unit furlong"), pw::InputError);
    EXPECT_TRUE(session.doc == before);
}

// Patch names are face names (ADVANCED_FACE('rim', ...)), the document's name the product's, and
// both come back on import.
TEST(StepNames, PatchNamesAreFaceNamesBothWays) {
    const fs::path dir = pw::test::freshTempDir("step-names");
    pw::Document doc = pw::loadBpt(pw::test::dataDir() / "teapot.bpt");
    doc.name = "Utah teapot";
    doc.patches[0].name = "rim front";
    doc.patches[5].name = "body";
    pw::exportStep(doc, dir / "pot.step");
    const std::string text = pw::test::readBytes(dir / "pot.step");
    EXPECT_NE(text.find("PRODUCT('Utah teapot'"), std::string::npos);
    EXPECT_NE(text.find("ADVANCED_FACE('rim front'"), std::string::npos);
    EXPECT_NE(text.find("ADVANCED_FACE('body'"), std::string::npos);
    const pw::Document back = pw::importCadSurfaces(dir / "pot.step");
    std::vector<std::string> names;
    for (const pw::Patch& p : back.patches)
        if (!p.name.empty()) names.push_back(p.name);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"body", "rim front"}));
    fs::remove_all(dir);
}

// Planes, cylinders, cones, spheres, tori and surfaces of revolution and extrusion, as OpenCASCADE
// makes them, come in exact: every imported patch lies on the file's faces.
TEST(CadImport, AnalyticAndSweptSurfacesComeInExact) {
    const fs::path dir = pw::test::freshTempDir("cad-analytic");
    TColgp_Array1OfPnt poles(1, 4);
    poles(1) = gp_Pnt(2, 0, 0), poles(2) = gp_Pnt(3, 0, 1), poles(3) = gp_Pnt(1.5, 0, 2), poles(4) = gp_Pnt(2, 0, 3);
    const TopoDS_Edge profile = BRepBuilderAPI_MakeEdge(new Geom_BezierCurve(poles)).Edge();
    const TopoDS_Edge circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1.5)).Edge();
    struct Case {
        const char* what;
        TopoDS_Shape shape;
    };
    const std::vector<Case> cases = {
        {"box", BRepPrimAPI_MakeBox(10, 20, 30).Shape()},
        {"cylinder", BRepPrimAPI_MakeCylinder(2, 5).Shape()},
        {"cone", BRepPrimAPI_MakeCone(2, 0.5, 4).Shape()},
        {"sphere", BRepPrimAPI_MakeSphere(3).Shape()},
        {"torus", BRepPrimAPI_MakeTorus(4, 1).Shape()},
        {"revolution", BRepPrimAPI_MakeRevol(profile, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1))).Shape()},
        {"extrusion", BRepPrimAPI_MakePrism(circle, gp_Vec(0, 0, 2)).Shape()},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        writeStep(c.shape, dir / "part.step");
        pw::CadImportReport report;
        const pw::Document doc = pw::importCadSurfaces(dir / "part.step", &report);
        EXPECT_EQ(report.importedFaces, report.faces);
        EXPECT_TRUE(report.notes.empty()) << (report.notes.empty() ? "" : report.notes[0]);
        EXPECT_EQ(doc.unit, pw::LengthUnit::Millimetre);
        EXPECT_FALSE(doc.patches.empty());
        // No sliver triangles: a rational pole row (weights 1, w, w, 1) is collapsed exactly.
        const pw::TriangleMesh mesh = pw::tessellateDocument(doc, 8);
        size_t slivers = 0;
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const auto& a = mesh.positions[mesh.indices[t]];
            const auto& b = mesh.positions[mesh.indices[t + 1]];
            const auto& d = mesh.positions[mesh.indices[t + 2]];
            const glm::dvec3 e1(b[0] - a[0], b[1] - a[1], b[2] - a[2]), e2(d[0] - a[0], d[1] - a[1], d[2] - a[2]);
            slivers += glm::length(glm::cross(e1, e2)) <= 1e-9 * glm::length(e1) * glm::length(e2) ? 1 : 0;
        }
        EXPECT_EQ(slivers, 0u);
        EXPECT_LT(worstDistanceToShape(doc, readStepText(pw::test::readBytes(dir / "part.step"), pw::LengthUnit::Millimetre)), 1e-7);
        // The same area (no face lost, none overlapping), and the closed parts come back closed:
        // written again, a solid of the part's volume.
        pw::StepExportStats stats;
        const TopoDS_Shape again = readStepText(pw::exportStepText(doc, {}, &stats), pw::LengthUnit::Millimetre);
        EXPECT_NEAR(area(again), area(c.shape), 1e-7 * area(c.shape));
        const bool closed = std::string(c.what) != "revolution" && std::string(c.what) != "extrusion";
        EXPECT_EQ(stats.solids, closed ? 1u : 0u);
        if (closed) {
            EXPECT_NEAR(volume(again), volume(c.shape), 1e-7 * volume(c.shape));
        }
    }
    fs::remove_all(dir);
}

// A box with every edge filleted (planes, cylinders and the spherical corners), as OpenCASCADE and
// FreeCAD make it: its planes and fillets come in exact, and whatever is skipped is named with its
// share of the area.
TEST(CadImport, AFilletedBoxImportsItsPlanesAndFillets) {
    const fs::path dir = pw::test::freshTempDir("cad-fillet");
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 20, 30).Shape();
    BRepFilletAPI_MakeFillet fillet(box);
    for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) fillet.Add(2.0, TopoDS::Edge(e.Current()));
    ASSERT_TRUE(fillet.IsDone() || (fillet.Build(), fillet.IsDone()));
    writeStep(fillet.Shape(), dir / "rounded.step");
    pw::CadImportReport report;
    const pw::Document doc = pw::importCadSurfaces(dir / "rounded.step", &report);
    EXPECT_EQ(report.faces, 26u);  // 6 planes, 12 fillets, 8 corners
    EXPECT_GE(report.importedFaces, 18u);
    EXPECT_LT(worstDistanceToShape(doc, readStepText(pw::test::readBytes(dir / "rounded.step"), pw::LengthUnit::Millimetre)), 1e-7);
    if (report.importedFaces < report.faces) {
        const std::string summary = report.skippedSummary();
        EXPECT_NE(summary.find("of 26 faces"), std::string::npos) << summary;
        EXPECT_NE(summary.find("% of the area"), std::string::npos) << summary;
        EXPECT_LT(report.skippedArea, 0.05 * report.area);
    }
    // The command line says so too.
    const auto r = pw::test::runCommand(pw::test::patchworkBinary().string() + " convert " + (dir / "rounded.step").string() + " " +
                                        (dir / "rounded.patchwork").string() + " 2>&1");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    if (report.importedFaces < report.faces) {
        EXPECT_NE(r.output.find("of the area"), std::string::npos) << r.output;
    }
    fs::remove_all(dir);
}

// IGES export: the same exact faces, shells and solids as STEP, in the document's unit (the global
// section's unit flag), read back by OpenCASCADE's IGES reader and by our import.
TEST(IgesExport, TheSameSolidsInTheDocumentsUnit) {
    const fs::path dir = pw::test::freshTempDir("iges-export");
    pw::Document doc;
    pw::addSphere(doc, {0, 0, 0}, 2.0, true);
    doc.name = "ball";
    doc.unit = pw::LengthUnit::Millimetre;
    pw::StepExportStats stats;
    const std::string text = pw::exportIgesText(doc, &stats);
    EXPECT_EQ(stats.solids, 1u);
    EXPECT_NE(text.find("4Hball"), std::string::npos);  // the sender's name, as an IGES string
    pw::exportStep(doc, dir / "ball.igs");
    EXPECT_EQ(pw::test::readBytes(dir / "ball.igs"), text);
    {
        IGESControl_Reader reader;
        ASSERT_EQ(reader.ReadFile((dir / "ball.igs").string().c_str()), IFSelect_RetDone);
        EXPECT_EQ(reader.IGESModel()->GlobalSection().UnitFlag(), 2);  // millimetres
        pw::occt::useLengthUnit(pw::LengthUnit::Millimetre);
        reader.TransferRoots();
        const TopoDS_Shape shape = reader.OneShape();
        EXPECT_EQ(count(shape, TopAbs_FACE), 8);
        EXPECT_NEAR(area(shape), 4.0 * kPi * 4.0, 1e-7 * 4.0 * kPi * 4.0);
    }
    pw::CadImportReport report;
    const pw::Document back = pw::importCadSurfaces(dir / "ball.igs", &report);
    EXPECT_EQ(back.unit, pw::LengthUnit::Millimetre);
    EXPECT_EQ(report.importedFaces, 8u);
    EXPECT_EQ(back.patches.size(), 8u);
    EXPECT_LT(worstDistanceToShape(back, readStepText(pw::exportStepText(doc, {}), pw::LengthUnit::Millimetre)), 1e-9);
    // The command line writes it by its extension and says what it wrote.
    const auto r =
        pw::test::runCommand(pw::test::patchworkBinary().string() + " export " + (pw::test::dataDir() / "exact_sphere.patchwork").string() +
                             " -o " + (dir / "sphere.iges").string() + " 2>&1");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("(1 closed: a solid)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("IGES"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

namespace {
double worstPointDistance(const pw::Document& a, const std::vector<uint32_t>& ia, const pw::Document& b, const std::vector<uint32_t>& ib) {
    EXPECT_EQ(ia.size(), ib.size());
    double worst = 0.0;
    for (size_t k = 0; k < std::min(ia.size(), ib.size()); ++k) worst = std::max(worst, glm::length(a.points[ia[k]] - b.points[ib[k]]));
    return worst;
}
template <class Idx>
std::vector<uint32_t> ids(const Idx& idx) {
    return std::vector<uint32_t>(idx.begin(), idx.end());
}
}  // namespace

// A STEP round trip gives back the same items in the same places: patches keep their numbers even
// where the sewn shells interleave them (the teapot's bottom is sewn to its body), a C2 B-spline
// net comes back one net with its layout, closed where it was, even a flat one (a Catmull-Rom net
// as a Bézier net keeping C1), Bézier triangles
// come back triangles, and names stay names while unnamed items stay unnamed.
TEST(StepRoundTrip, ItemsComeBackInTheirPlacesAsTheyWere) {
    const fs::path dir = pw::test::freshTempDir("step-round-trip");
    pw::Document doc = pw::loadBpt(pw::test::dataDir() / "teapot.bpt");
    doc.patches[3].name = "rim 3";
    pw::addNetSurface(doc, 8, 10, pw::NetShape::Tube, pw::Basis::BSpline, pw::Vec3(10.0, 0.0, 0.0), 4.0);
    pw::addNetSurface(doc, 5, 6, pw::NetShape::Flat, pw::Basis::BSpline, pw::Vec3(-10.0, 0.0, 0.0), 4.0);
    doc.surfaces[0].name = "tube";
    doc.surfaces[1].name.clear();
    pw::addTriangle(doc, pw::Vec3(0.0, 10.0, 0.0), 2.0);
    pw::addTriangle(doc, pw::Vec3(0.0, -10.0, 0.0), 2.0);
    doc.points[doc.triangles[0].idx[4]].z += 0.6;  // a dome
    doc.triangles[1].name = "lid";
    ASSERT_EQ(doc.triangles[0].name, "triangle 0");
    pw::exportStep(doc, dir / "all.step");
    const std::string text = pw::test::readBytes(dir / "all.step");
    EXPECT_NE(text.find("ADVANCED_FACE('patch 30'"), std::string::npos) << "unnamed items are labelled with their place";
    EXPECT_NE(text.find("ADVANCED_FACE('rim 3'"), std::string::npos);
    const pw::Document back = pw::importCadSurfaces(dir / "all.step");
    ASSERT_EQ(back.patches.size(), doc.patches.size());
    ASSERT_EQ(back.surfaces.size(), doc.surfaces.size());
    ASSERT_EQ(back.triangles.size(), doc.triangles.size());
    const double size = pw::modelSize(doc);
    for (size_t p = 0; p < doc.patches.size(); ++p) {
        SCOPED_TRACE("patch " + std::to_string(p));
        EXPECT_EQ(back.patches[p].name, doc.patches[p].name);
        EXPECT_LT(worstPointDistance(doc, ids(doc.patches[p].idx), back, ids(back.patches[p].idx)), 1e-9 * size);
    }
    for (size_t s = 0; s < doc.surfaces.size(); ++s) {
        SCOPED_TRACE("net " + std::to_string(s));
        const pw::Surface &a = doc.surfaces[s], &b = back.surfaces[s];
        EXPECT_EQ(b.name, a.name);
        EXPECT_EQ(b.basis, pw::Basis::BSpline);
        EXPECT_EQ(std::tie(b.rows, b.cols, b.closedU, b.closedV), std::tie(a.rows, a.cols, a.closedU, a.closedV));
        EXPECT_LT(worstPointDistance(doc, a.idx, back, b.idx), 1e-9 * size);
    }
    for (size_t t = 0; t < doc.triangles.size(); ++t) {
        SCOPED_TRACE("triangle " + std::to_string(t));
        // "triangle 0" on triangle 0 (the name add-triangle gives) reads as its place: unnamed.
        const std::string& name = doc.triangles[t].name;
        EXPECT_EQ(back.triangles[t].name, name == pw::cadFaceName("triangle", t, "") ? "" : name);
        EXPECT_LT(worstPointDistance(doc, ids(doc.triangles[t].idx), back, ids(back.triangles[t].idx)), 1e-9 * size);
    }
    // A Catmull-Rom net is C1 only (double knots): it comes back one Bézier net that keeps C1, the
    // same surface (its Bézier grid).
    pw::Document cr;
    pw::addNetSurface(cr, 5, 5, pw::NetShape::Flat, pw::Basis::CatmullRom, pw::Vec3(0.0), 4.0);
    for (size_t k = 0; k < cr.surfaces[0].idx.size(); ++k) cr.points[cr.surfaces[0].idx[k]].z += 0.3 * std::sin(1.7 * double(k * k));
    pw::exportStep(cr, dir / "cr.step");
    const pw::Document crBack = pw::importCadSurfaces(dir / "cr.step");
    EXPECT_TRUE(crBack.patches.empty());
    ASSERT_EQ(crBack.surfaces.size(), 1u);
    const pw::Surface& bez = crBack.surfaces[0];
    EXPECT_EQ(bez.basis, pw::Basis::Bezier);
    EXPECT_TRUE(bez.keepC1);
    const pw::BezierGrid grid = pw::netToBezierGrid(cr, cr.surfaces[0]);
    ASSERT_EQ(std::tie(bez.rows, bez.cols), std::tie(grid.rows, grid.cols));
    double worst = 0.0;
    for (size_t k = 0; k < grid.points.size(); ++k) worst = std::max(worst, glm::length(crBack.points[bez.idx[k]] - grid.points[k]));
    EXPECT_LT(worst, 1e-9 * pw::modelSize(cr));
    fs::remove_all(dir);
}

TEST(CadLabels, PlacesAreReadOnlyFromExactLabels) {
    EXPECT_EQ(pw::cadFaceLabelIndex("patch 12", "patch"), 12u);
    EXPECT_EQ(pw::cadFaceLabelIndex("net 0", "net"), 0u);
    for (const char* name : {"patch", "patch ", "patch 012", "patch 1a", "patch -1", "patches 1", "net 1", "Patch 1"})
        EXPECT_FALSE(pw::cadFaceLabelIndex(name, "patch")) << name;
    std::vector<std::string> items{"a", "b", "c", "d"};
    pw::placeByLabel(items, {std::nullopt, 0, std::nullopt, 1});  // b goes first, d second
    EXPECT_EQ(items, (std::vector<std::string>{"b", "d", "a", "c"}));
    pw::placeByLabel(items, {0, 0, std::nullopt, std::nullopt});  // not distinct: left alone
    EXPECT_EQ(items, (std::vector<std::string>{"b", "d", "a", "c"}));
    pw::placeByLabel(items, {7, std::nullopt, std::nullopt, std::nullopt});  // out of range: left alone
    EXPECT_EQ(items, (std::vector<std::string>{"b", "d", "a", "c"}));
}

// The inverse of triangleAsCollapsedQuad finds the triangle and nothing else.
TEST(CadLabels, ACollapsedQuadIsATriangleOnlyWhenItIsOne) {
    pw::Net10 tri;
    for (size_t k = 0; k < 10; ++k) tri[k] = pw::Vec3(std::cos(double(k)), std::sin(2.0 * double(k)), 0.1 * double(k));
    const pw::Net16 quad = pw::triangleAsCollapsedQuad(tri);
    const auto back = pw::collapsedQuadAsTriangle(quad, 1e-9);
    ASSERT_TRUE(back);
    for (size_t k = 0; k < 10; ++k) EXPECT_LT(glm::length((*back)[k] - tri[k]), 1e-9) << k;
    pw::Net16 other = quad;
    other[10].z += 1e-3;  // still collapsed at s = 0, no longer a cubic triangle
    EXPECT_FALSE(pw::collapsedQuadAsTriangle(other, 1e-9));
}

// Parts: when the user named one (a sewn piece whose items share a name), the file is an assembly
// of one product per piece under the document's product, read so by OpenCASCADE's XCAF reader;
// unnamed pieces are numbered. A round trip keeps the face names and places.
TEST(StepParts, NamedPartsAreProductsOfAnAssembly) {
    EXPECT_EQ(pw::cadPartName({"lid 0", "lid 1", ""}), "lid");
    EXPECT_EQ(pw::cadPartName({"rim front", "rim back"}), "rim");
    EXPECT_EQ(pw::cadPartName({"rim", "body"}), "");
    EXPECT_EQ(pw::cadPartName({"", ""}), "");
    EXPECT_EQ(pw::cadPartName({"M8"}), "M8");  // digits of the name stay
    EXPECT_EQ(pw::cadPartName({"bolt M8 0", "bolt M8 1"}), "bolt M8");
    EXPECT_EQ(pw::cadPartName({"patch10", "patch11"}), "patch");
    EXPECT_EQ(pw::cadPartName({"lid 0"}), "lid");
    const fs::path dir = pw::test::freshTempDir("step-parts");
    pw::Document doc = pw::loadBpt(pw::test::dataDir() / "teapot.bpt");
    doc.name = "Utah teapot";
    for (size_t p = 12; p < 16; ++p) doc.patches[p].name = "handle " + std::to_string(p - 12);
    for (size_t p = 20; p < 28; ++p) doc.patches[p].name = "lid";
    pw::StepExportStats stats;
    const std::string text = pw::exportStepText(doc, {}, &stats);
    EXPECT_EQ(stats.parts, 4u);  // body with its bottom, handle, spout, lid
    std::ofstream(dir / "parts.step") << text;

    Handle(TDocStd_Document) xdoc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", xdoc);
    STEPCAFControl_Reader reader;
    reader.SetNameMode(true);
    ASSERT_EQ(reader.ReadFile((dir / "parts.step").string().c_str()), IFSelect_RetDone);
    ASSERT_TRUE(reader.Transfer(xdoc));
    const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(xdoc->Main());
    auto nameOf = [](const TDF_Label& l) {
        Handle(TDataStd_Name) n;
        return l.FindAttribute(TDataStd_Name::GetID(), n) ? TCollection_AsciiString(n->Get()).ToCString() : std::string();
    };
    TDF_LabelSequence roots, components;
    tool->GetFreeShapes(roots);
    ASSERT_EQ(roots.Length(), 1);
    EXPECT_EQ(nameOf(roots(1)), "Utah teapot");
    ASSERT_TRUE(tool->IsAssembly(roots(1)));
    tool->GetComponents(roots(1), components);
    std::vector<std::string> parts;
    for (int i = 1; i <= components.Length(); ++i) {
        TDF_Label part;
        ASSERT_TRUE(tool->GetReferredShape(components(i), part));
        parts.push_back(nameOf(part));
    }
    EXPECT_EQ(parts, (std::vector<std::string>{"Utah teapot 1", "handle", "Utah teapot 3", "lid"}));
    XCAFApp_Application::GetApplication()->Close(xdoc);  // the application keeps its documents open

    const pw::Document back = pw::importCadSurfaces(dir / "parts.step");
    ASSERT_EQ(back.patches.size(), doc.patches.size());
    for (size_t p = 0; p < doc.patches.size(); ++p) {
        EXPECT_EQ(back.patches[p].name, doc.patches[p].name) << p;
        EXPECT_LT(worstPointDistance(doc, ids(doc.patches[p].idx), back, ids(back.patches[p].idx)), 1e-9) << p;
    }
    // Without a named part: one product.
    for (size_t p = 12; p < 28; ++p) doc.patches[p].name.clear();
    pw::exportStepText(doc, {}, &stats);
    EXPECT_EQ(stats.parts, 1u);
    fs::remove_all(dir);
}

// A stale automatic name ("patch 1" on patch 0, as add-patch left it after a delete) is not taken
// for a place: the patches come back in their own places (the stale name dropped).
TEST(StepRoundTrip, AStaleAutomaticNameIsNoPlace) {
    const fs::path dir = pw::test::freshTempDir("step-stale-name");
    pw::Document doc;
    pw::addFlatPatch(doc, pw::Vec3(0.0), 1.0);
    pw::addFlatPatch(doc, pw::Vec3(5.0, 0.0, 0.0), 1.0);
    doc.patches[0].name = "patch 1";
    doc.patches[1].name = "lid";  // read as an unplaced face, it would fill place 0
    pw::exportStep(doc, dir / "stale.step");
    const pw::Document back = pw::importCadSurfaces(dir / "stale.step");
    ASSERT_EQ(back.patches.size(), 2u);
    for (size_t p = 0; p < 2; ++p) {
        EXPECT_EQ(back.patches[p].name, p == 0 ? "" : "lid") << p;
        EXPECT_LT(worstPointDistance(doc, ids(doc.patches[p].idx), back, ids(back.patches[p].idx)), 1e-9) << p;
    }
    fs::remove_all(dir);
}

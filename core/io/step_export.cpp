// STEP export through OpenCASCADE (step_export.hpp): faces from exact B-spline surfaces, sewn,
// transferred as they are (STEPControl_AsIs) and written to a string, then atomically to the file.
#include "core/io/step_export.hpp"

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Interface_Static.hxx>
#include <Precision.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepWriter.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/io/occt_support.hpp"
#include "core/ops/net_ops.hpp"

namespace pw {

namespace {

// One B-spline surface for a whole net: its Bézier grid as poles with interior knots of
// multiplicity 3 (exact), then each interior knot lowered as far as the surface allows within
// `tol` (a uniform B-spline net ends with simple knots: C2, as it was drawn).
Handle(Geom_BSplineSurface) netSurface(const Document& doc, const Surface& s, double tol) {
    const BezierGrid g = netToBezierGrid(doc, s);
    const int cols = int(g.cols) + (g.closedU ? 1 : 0), rows = int(g.rows) + (g.closedV ? 1 : 0);
    TColgp_Array2OfPnt poles(1, cols, 1, rows);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j) {
            const Vec3& p = g.points[size_t(i % int(g.rows)) * g.cols + size_t(j % int(g.cols))];
            poles.SetValue(j + 1, i + 1, gp_Pnt(p.x, p.y, p.z));
        }
    auto knots = [](int spans, TColStd_Array1OfReal& k, TColStd_Array1OfInteger& m) {
        for (int i = 0; i <= spans; ++i) {
            k(i + 1) = i;
            m(i + 1) = (i == 0 || i == spans) ? 4 : 3;
        }
    };
    const int su = (cols - 1) / 3, sv = (rows - 1) / 3;
    TColStd_Array1OfReal uk(1, su + 1), vk(1, sv + 1);
    TColStd_Array1OfInteger um(1, su + 1), vm(1, sv + 1);
    knots(su, uk, um);
    knots(sv, vk, vm);
    Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, uk, vk, um, vm, 3, 3);
    for (int k = su; k >= 2; --k)
        for (int m = 0; m < 3; ++m)
            if (surface->RemoveUKnot(k, m, tol)) break;
    for (int k = sv; k >= 2; --k)
        for (int m = 0; m < 3; ++m)
            if (surface->RemoveVKnot(k, m, tol)) break;
    return surface;
}

Net16 patchNet(const Document& doc, const std::array<uint32_t, 16>& idx) {
    Net16 net;
    for (size_t k = 0; k < 16; ++k) net[k] = doc.points[idx[k]];
    return net;
}

// A shell stays a shell; anything else becomes a compound of shells (a lone face gets its own).
TopoDS_Shape shellsOf(const TopoDS_Shape& sewed) {
    if (sewed.ShapeType() == TopAbs_SHELL) return sewed;
    BRep_Builder b;
    TopoDS_Compound compound;
    b.MakeCompound(compound);
    for (TopExp_Explorer e(sewed, TopAbs_SHELL); e.More(); e.Next()) b.Add(compound, e.Current());
    for (TopExp_Explorer e(sewed, TopAbs_FACE, TopAbs_SHELL); e.More(); e.Next()) {
        TopoDS_Shell shell;
        b.MakeShell(shell);
        b.Add(shell, e.Current());
        b.Add(compound, shell);
    }
    return compound;
}

}  // namespace

std::string exportStepText(const Document& doc, const StepExportOptions& options, StepExportStats* stats) {
    if (doc.patches.empty() && doc.surfaces.empty() && doc.triangles.empty())
        throw std::runtime_error("the document has no surfaces to write as STEP");
    for (size_t s = 0; s < doc.surfaces.size(); ++s)
        if (auto why = netLayoutProblem(doc.surfaces[s])) throw std::runtime_error("surface " + std::to_string(s) + ": " + *why);
    for (size_t s = 0; s < doc.surfaces.size(); ++s)
        for (uint32_t i : doc.surfaces[s].idx)
            if (pointWeight(doc, i) != 1.0)
                throw std::runtime_error("surface " + std::to_string(s) +
                                         ": a net with weights is not written to STEP yet (convert it to patches first)");
    const auto held = occt::lock();
    try {
        const double size = std::max(1.0, modelSize(doc));
        const double tol = std::max(Precision::Confusion(), 1e-9 * size);
        BRepBuilderAPI_Sewing sewing(std::max(Precision::Confusion(), 1e-7 * size));
        auto addFace = [&](const Handle(Geom_Surface) & surface, const std::string& what) {
            BRepBuilderAPI_MakeFace face(surface, Precision::Confusion());
            if (!face.IsDone())
                throw std::runtime_error(what + ": OpenCASCADE could not make a face of it (error " + std::to_string(int(face.Error())) +
                                         ")");
            sewing.Add(face.Face());
        };
        for (size_t p = 0; p < doc.patches.size(); ++p) {
            const std::optional<Weights16> w = gatherWeights(doc, doc.patches[p].idx);  // rational: exact, weights and all
            addFace(occt::bezierSurface(patchNet(doc, doc.patches[p].idx), w ? &*w : nullptr), "patch " + std::to_string(p));
        }
        for (size_t s = 0; s < doc.surfaces.size(); ++s) addFace(netSurface(doc, doc.surfaces[s], tol), "surface " + std::to_string(s));
        for (size_t t = 0; t < doc.triangles.size(); ++t)
            addFace(occt::bezierSurface(triangleAsCollapsedQuad(gatherTriangleNet(doc, doc.triangles[t].idx))),
                    "triangle " + std::to_string(t));
        sewing.Perform();
        const TopoDS_Shape shape = shellsOf(sewing.SewedShape());

        // The schema is read when the writer's model is made: set it first.
        Interface_Static::SetCVal("write.step.schema", options.schema == StepSchema::AP242 ? "AP242DIS" : "AP214IS");
        Interface_Static::SetCVal("write.step.unit", "MM");
        STEPControl_Writer writer;
        if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone)
            throw std::runtime_error("OpenCASCADE could not transfer the shape to STEP");
        {
            APIHeaderSection_MakeHeader header(writer.Model());
            header.SetName(new TCollection_HAsciiString(doc.name.empty() ? "Patchwork" : doc.name.c_str()));
            header.SetOriginatingSystem(new TCollection_HAsciiString("Patchwork"));
        }
        StepData_StepWriter out(writer.Model());
        out.SendModel(Handle(StepData_Protocol)::DownCast(writer.WS()->Protocol()));
        std::ostringstream text;
        if (!out.Print(text)) throw std::runtime_error("OpenCASCADE could not print the STEP model");

        if (stats) {
            TopTools_IndexedMapOfShape faces, shells, edges;
            TopExp::MapShapes(shape, TopAbs_FACE, faces);
            TopExp::MapShapes(shape, TopAbs_SHELL, shells);
            TopExp::MapShapes(shape, TopAbs_EDGE, edges);
            stats->faces = size_t(faces.Extent());
            stats->shells = size_t(shells.Extent());
            stats->sharedEdges = size_t(sewing.NbContigousEdges());
            stats->freeEdges = size_t(sewing.NbFreeEdges());
            stats->degenerateEdges = 0;
            for (int i = 1; i <= edges.Extent(); ++i) stats->degenerateEdges += BRep_Tool::Degenerated(TopoDS::Edge(edges(i))) ? 1 : 0;
            stats->bytes = text.str().size();
        }
        return std::move(text).str();
    } catch (const Standard_Failure& e) {
        throw std::runtime_error(std::string("OpenCASCADE failed: ") + e.GetMessageString());
    }
}

StepExportStats exportStep(const Document& doc, const std::filesystem::path& path, const StepExportOptions& options) {
    const std::string ext = lowerExtension(path);
    if (ext != ".step" && ext != ".stp") throw OutputError(path.string(), "unknown STEP extension '" + ext + "' (use .step or .stp)");
    StepExportStats stats;
    std::string text;
    try {
        text = exportStepText(doc, options, &stats);
    } catch (const std::runtime_error& e) {
        throw OutputError(path.string(), e.what());
    }
    writeFileAtomic(path, text);
    return stats;
}

}  // namespace pw

// STEP export through OpenCASCADE (step_export.hpp): faces from exact B-spline surfaces, sewn,
// transferred as they are (STEPControl_AsIs) and written to a string, then atomically to the file.
#include "core/io/step_export.hpp"

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <NCollection_DataMap.hxx>
#include <Precision.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPConstruct.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <StepBasic_Product.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepWriter.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <Transfer_FinderProcess.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_TransferWriter.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/limits.hpp"
#include "core/base/up_axis.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/io/bounded_child.hpp"
#include "core/io/cad_labels.hpp"
#include "core/io/cad_trim_face.hpp"
#include "core/io/occt_support.hpp"
#include "core/io/step_import.hpp"
#include "core/ops/net_ops.hpp"

namespace pw {
inline namespace io {

namespace {

// One B-spline surface for a whole net: its Bézier grid as poles with interior knots of
// multiplicity 3 (exact), then each interior knot lowered as far as the surface allows within
// `tol`, but kept: a uniform B-spline net ends with simple knots (C2, as it was drawn), one knot
// between each two windows even where the surface is flat, so that an import finds its windows.
Handle(Geom_BSplineSurface) netSurface(const Document& doc, const Surface& s, double tol) {
    Handle(Geom_BSplineSurface) surface = occt::netBezierSurface(netToBezierGrid(doc, s));
    const int su = surface->NbUKnots() - 1, sv = surface->NbVKnots() - 1;
    for (int k = su; k >= 2; --k)
        for (int m = 1; m < 3; ++m)
            if (surface->RemoveUKnot(k, m, tol)) break;
    for (int k = sv; k >= 2; --k)
        for (int m = 1; m < 3; ++m)
            if (surface->RemoveVKnot(k, m, tol)) break;
    return surface;
}

// Whether two surfaces are trimmed by one curve (an intersection cut into both).
bool sharesTrimCurves(const Document& doc) {
    std::vector<int> uses(doc.curves.size(), 0);
    auto count = [&](const std::vector<TrimLoop>& trims) {
        std::vector<int32_t> seen;
        for (const TrimLoop& l : trims)
            if (l.curve >= 0 && size_t(l.curve) < uses.size() && std::find(seen.begin(), seen.end(), l.curve) == seen.end())
                seen.push_back(l.curve), ++uses[size_t(l.curve)];
    };
    for (const Patch& p : doc.patches) count(p.trims);
    for (const Surface& s : doc.surfaces) count(s.trims);
    return std::any_of(uses.begin(), uses.end(), [](int n) { return n > 1; });
}

Net16 patchNet(const Document& doc, const std::array<uint32_t, 16>& idx) {
    Net16 net;
    for (size_t k = 0; k < 16; ++k) net[k] = doc.points[idx[k]];
    return net;
}

// A closed shell (every edge between two faces, or a seam or a pole) as a solid, its faces turned
// outwards: what CAD systems expect of a closed model (a MANIFOLD_SOLID_BREP of a CLOSED_SHELL in
// STEP, so that volumes and booleans work). An open shell stays a shell; null when it is open.
TopoDS_Solid solidOf(TopoDS_Shell shell) {
    if (!BRep_Tool::IsClosed(shell)) return {};
    shell.Closed(true);
    BRepBuilderAPI_MakeSolid make(shell);
    if (!make.IsDone()) return {};
    TopoDS_Solid solid = make.Solid();
    if (!BRepLib::OrientClosedSolid(solid)) return {};
    return solid;
}

// Each sewn face's place in the document: patches, then nets, then triangles.
using FaceOrder = NCollection_DataMap<TopoDS_Shape, size_t, TopTools_ShapeMapHasher>;

// One connected piece of the sewn model: a solid or a shell, its faces' places in the document
// (ascending) and its name (cad_labels.hpp cadPartName; empty when its items have none in common).
struct Piece {
    TopoDS_Shape shape;
    std::vector<size_t> places;
    std::string name;
};

// The shell's faces in the document's order, so that the file lists them so and a round trip
// keeps their numbers; their places in `places`.
TopoDS_Shell orderedShell(const TopoDS_Shape& shell, const FaceOrder& order, std::vector<size_t>& places) {
    std::vector<std::pair<size_t, TopoDS_Shape>> faces;
    for (TopExp_Explorer e(shell, TopAbs_FACE); e.More(); e.Next()) {
        const size_t* at = order.Seek(e.Current());
        faces.emplace_back(at ? *at : SIZE_MAX, e.Current());
    }
    std::stable_sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    TopoDS_Shell out;
    BRep_Builder b;
    b.MakeShell(out);
    places.clear();
    for (const auto& face : faces) b.Add(out, face.second), places.push_back(face.first);
    return out;
}

// The sewn faces as pieces: each closed shell a solid, each open shell a shell, a lone face a
// shell of its own, in the order of their first faces.
std::vector<Piece> piecesOf(const TopoDS_Shape& sewed, const FaceOrder& order, size_t& solids) {
    std::vector<Piece> pieces;
    for (TopExp_Explorer e(sewed, TopAbs_SHELL); e.More(); e.Next()) {
        Piece piece;
        const TopoDS_Shell shell = orderedShell(e.Current(), order, piece.places);
        const TopoDS_Solid solid = solidOf(shell);
        piece.shape = solid.IsNull() ? TopoDS_Shape(shell) : TopoDS_Shape(solid);
        solids += solid.IsNull() ? 0 : 1;
        pieces.push_back(std::move(piece));
    }
    for (TopExp_Explorer e(sewed, TopAbs_FACE, TopAbs_SHELL); e.More(); e.Next()) {
        Piece piece;
        piece.shape = orderedShell(e.Current(), order, piece.places);
        pieces.push_back(std::move(piece));
    }
    const auto first = [](const Piece& p) { return p.places.empty() ? SIZE_MAX : p.places.front(); };
    std::stable_sort(pieces.begin(), pieces.end(), [&](const Piece& a, const Piece& b) { return first(a) < first(b); });
    return pieces;
}

// The pieces as one shape: one alone, several in a compound.
TopoDS_Shape oneShape(const std::vector<Piece>& pieces) {
    if (pieces.size() == 1) return pieces.front().shape;
    TopoDS_Compound compound;
    BRep_Builder b;
    b.MakeCompound(compound);
    for (const Piece& piece : pieces) b.Add(compound, piece.shape);
    return compound;
}

// The document as OpenCASCADE shapes, for any CAD writer: exact faces, sewn, closed shells as
// solids, +Z up (a Y-up document turned), the named faces with their names, and the counts.
struct CadShape {
    TopoDS_Shape shape;
    std::vector<Piece> pieces;                                     // what `shape` is made of, named
    std::vector<std::pair<TopoDS_Shape, std::string>> namedFaces;  // the sewn faces
    StepExportStats stats;
};

CadShape cadShape(const Document& doc, const char* format) {
    if (doc.patches.empty() && doc.surfaces.empty() && doc.triangles.empty())
        throw std::runtime_error(std::string("the document has no surfaces to write as ") + format);
    for (size_t s = 0; s < doc.surfaces.size(); ++s)
        if (auto why = netLayoutProblem(doc.surfaces[s])) throw std::runtime_error("surface " + std::to_string(s) + ": " + *why);
    for (size_t s = 0; s < doc.surfaces.size(); ++s)
        for (uint32_t i : doc.surfaces[s].idx)
            if (pointWeight(doc, i) != 1.0)
                throw std::runtime_error("surface " + std::to_string(s) + ": a net with weights is not written to " + format +
                                         " yet (convert it to patches first)");
    // STEP and IGES are +Z up: a Y-up document is turned a quarter about X (exact) so that it stands upright.
    Document turned;
    if (!doc.camera.zUp) {
        turned = doc;
        for (Vec3& p : turned.points) p = yUpToZUp(p);
    }
    const Document& src = doc.camera.zUp ? doc : turned;
    const double size = std::max(1.0, modelSize(doc));
    const double tol = std::max(Precision::Confusion(), 1e-9 * size);
    // Surfaces cut by one curve meet along it only as closely as each one's loop follows the curve
    // (a few millionths of the model, `info` measures it): sewn within 1e-5 of it, as the editor
    // holds those edges; everything else within 1e-7.
    BRepBuilderAPI_Sewing sewing(std::max(Precision::Confusion(), (sharesTrimCurves(doc) ? 1e-5 : 1e-7) * size));
    // Every face in the document's order, with its name or place (cad_labels.hpp).
    std::vector<std::pair<TopoDS_Face, std::string>> made;
    std::vector<std::string> userNames;  // the items' own names (empty where unnamed)
    auto addFace = [&](const Handle(Geom_Surface) & surface, const char* kind, size_t index, const std::string& name,
                       const std::vector<TrimLoop>& trims = {}) {
        const std::string what = std::string(std::string_view(kind) == "net" ? "surface" : kind) + " " + std::to_string(index);
        // A trimmed surface is a face per outer loop, with its holes (cad_trim_face.hpp).
        for (const TopoDS_Face& face : trimmedFaces(surface, trims, tol, what)) {
            sewing.Add(face);
            // A name that reads as a place ("patch 5": what add-patch names the patch it makes, stale
            // once an earlier item goes) is written as the item's own place, never as another's.
            const bool placeLike =
                cadFaceLabelIndex(name, "patch") || cadFaceLabelIndex(name, "net") || cadFaceLabelIndex(name, "triangle");
            made.emplace_back(face, cadFaceName(kind, index, placeLike ? std::string() : name));
            userNames.push_back(placeLike ? std::string() : name);
        }
    };
    for (size_t p = 0; p < src.patches.size(); ++p) {
        const std::optional<Weights16> w = gatherWeights(src, src.patches[p].idx);  // rational: exact, weights and all
        addFace(occt::bezierSurface(patchNet(src, src.patches[p].idx), w ? &*w : nullptr), "patch", p, src.patches[p].name,
                src.patches[p].trims);
    }
    for (size_t s = 0; s < src.surfaces.size(); ++s)
        addFace(netSurface(src, src.surfaces[s], tol), "net", s, src.surfaces[s].name, src.surfaces[s].trims);
    for (size_t t = 0; t < src.triangles.size(); ++t)
        addFace(occt::bezierSurface(triangleAsCollapsedQuad(gatherTriangleNet(src, src.triangles[t].idx))), "triangle", t,
                src.triangles[t].name);
    sewing.Perform();
    CadShape out;
    // The sewn face is the one its original became (sewing may replace a face when it merges its edges).
    FaceOrder order;
    for (size_t k = 0; k < made.size(); ++k) {
        const TopoDS_Shape sewn = sewing.IsModified(made[k].first) ? sewing.Modified(made[k].first) : made[k].first;
        order.Bind(sewn, k);
        if (!made[k].second.empty()) out.namedFaces.emplace_back(sewn, made[k].second);
    }
    out.pieces = piecesOf(sewing.SewedShape(), order, out.stats.solids);
    out.shape = oneShape(out.pieces);
    for (Piece& piece : out.pieces) {
        std::vector<std::string> names;
        for (size_t k : piece.places)
            if (k < userNames.size()) names.push_back(userNames[k]);
        piece.name = cadPartName(names);
    }
    TopTools_IndexedMapOfShape faces, shells, edges;
    TopExp::MapShapes(out.shape, TopAbs_FACE, faces);
    TopExp::MapShapes(out.shape, TopAbs_SHELL, shells);
    TopExp::MapShapes(out.shape, TopAbs_EDGE, edges);
    out.stats.faces = size_t(faces.Extent());
    out.stats.shells = size_t(shells.Extent());
    out.stats.sharedEdges = size_t(sewing.NbContigousEdges());
    out.stats.freeEdges = size_t(sewing.NbFreeEdges());
    for (int i = 1; i <= edges.Extent(); ++i) out.stats.degenerateEdges += BRep_Tool::Degenerated(TopoDS::Edge(edges(i))) ? 1 : 0;
    return out;
}

// An XCAF document of one assembly named `product` with a component product per piece, named
// after the piece or, unnamed, "`product` k" (k counting from 1 in the pieces' order).
Handle(TDocStd_Document) partsDocument(const std::string& product, const std::vector<Piece>& pieces) {
    Handle(TDocStd_Document) xdoc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", xdoc);
    const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(xdoc->Main());
    const TDF_Label root = tool->NewShape();
    TDataStd_Name::Set(root, TCollection_ExtendedString(product.c_str(), true));
    for (size_t k = 0; k < pieces.size(); ++k) {
        const std::string name = pieces[k].name.empty() ? product + " " + std::to_string(k + 1) : pieces[k].name;
        const TDF_Label part = tool->AddShape(pieces[k].shape, false);
        TDataStd_Name::Set(part, TCollection_ExtendedString(cadSafeName(name, kMaxStepNameBytes, false).c_str(), true));
        tool->AddComponent(root, part, TopLoc_Location());
    }
    tool->UpdateAssemblies();
    return xdoc;
}

std::string productName(const Document& doc, const std::string& given) {
    return !given.empty() ? given : doc.name.empty() ? "Patchwork" : doc.name;
}

}  // namespace

namespace {

// The STEP text, with OCCT's lock held by the caller (in a child process of exportStep, or in
// exportStepText).
std::string stepTextHeld(const Document& doc, const StepExportOptions& options, StepExportStats* stats) {
    try {
        CadShape cad = cadShape(doc, "STEP");
        // The schema is read when the writer's model is made: set it first. Lengths are in the
        // document's unit, with no conversion. One product named after the document; when the
        // user named a part (a sewn piece whose items share a name), an assembly of one product per
        // piece under it, through an XCAF document as CAD tools expect (unnamed pieces numbered).
        const std::string product = cadSafeName(productName(doc, options.product), kMaxStepNameBytes, false);
        Interface_Static::SetCVal("write.step.schema", options.schema == StepSchema::AP242 ? "AP242DIS" : "AP214IS");
        Interface_Static::SetCVal("write.step.unit", occt::unitName(doc.unit));
        Interface_Static::SetIVal("write.step.assembly", 0);
        const double unitInMm = occt::useLengthUnit(doc.unit);
        const bool parts =
            cad.pieces.size() > 1 && std::any_of(cad.pieces.begin(), cad.pieces.end(), [](const Piece& p) { return !p.name.empty(); });
        // The XCAF writer and document only for parts (made otherwise, they hold the shapes in the
        // writer's session past the export); the document is closed again when done.
        std::optional<STEPCAFControl_Writer> cafWriter;
        STEPControl_Writer plainWriter;
        if (parts) cafWriter.emplace();
        STEPControl_Writer& writer = parts ? cafWriter->ChangeWriter() : plainWriter;
        writer.Model()->SetLocalLengthUnit(unitInMm);
        writer.Model()->SetWriteLengthUnit(unitInMm);
        Handle(TDocStd_Document) xdoc;
        struct CloseDocument {
            Handle(TDocStd_Document) & doc;
            ~CloseDocument() {
                if (!doc.IsNull()) XCAFApp_Application::GetApplication()->Close(doc);
            }
        } closeDocument{xdoc};
        if (parts) {
            cad.stats.parts = cad.pieces.size();
            xdoc = partsDocument(product, cad.pieces);
            if (!cafWriter->Transfer(xdoc, STEPControl_AsIs)) throw std::runtime_error("OpenCASCADE could not transfer the parts to STEP");
        } else {
            cad.stats.parts = 1;
            if (writer.Transfer(cad.shape, STEPControl_AsIs) != IFSelect_RetDone)
                throw std::runtime_error("OpenCASCADE could not transfer the shape to STEP");
            for (int i = 1; i <= writer.Model()->NbEntities(); ++i)
                if (const auto p = Handle(StepBasic_Product)::DownCast(writer.Model()->Value(i)); !p.IsNull()) {
                    p->SetId(new TCollection_HAsciiString(product.c_str()));
                    p->SetName(new TCollection_HAsciiString(product.c_str()));
                }
        }
        // Names on the faces: ADVANCED_FACE('name', ...).
        const Handle(Transfer_FinderProcess) finder = writer.WS()->TransferWriter()->FinderProcess();
        for (const auto& [face, name] : cad.namedFaces)
            if (Handle(StepRepr_RepresentationItem) item = STEPConstruct::FindEntity(finder, face); !item.IsNull())
                item->SetName(new TCollection_HAsciiString(cadSafeName(name, kMaxStepNameBytes, false).c_str()));
        {
            APIHeaderSection_MakeHeader header(writer.Model());
            header.SetName(new TCollection_HAsciiString(product.c_str()));
            header.SetOriginatingSystem(new TCollection_HAsciiString("Patchwork"));
        }
        StepData_StepWriter out(writer.Model());
        out.SendModel(Handle(StepData_Protocol)::DownCast(writer.WS()->Protocol()));
        std::ostringstream text;
        if (!out.Print(text)) throw std::runtime_error("OpenCASCADE could not print the STEP model");
        cad.stats.bytes = text.str().size();
        if (stats) *stats = cad.stats;
        return std::move(text).str();
    } catch (const Standard_Failure& e) {
        throw std::runtime_error(std::string("OpenCASCADE failed: ") + e.GetMessageString());
    }
}

std::string igesTextHeld(const Document& doc, StepExportStats* stats, const std::string& product) {
    try {
        CadShape cad = cadShape(doc, "IGES");
        // Faces as B-spline surfaces in a manifold solid B-rep (IGES 5.3 BRep mode), in the
        // document's unit with no conversion.
        IGESControl_Controller::Init();
        Interface_Static::SetIVal("write.iges.brep.mode", 1);
        // OCCT 7.6 takes the shape's unit from the model's global section, not from the session's
        // unit (issue 66: a metre document came out 1 000× too small): set it on the model.
        const double unitInMm = occt::useLengthUnit(doc.unit);
        IGESControl_Writer writer(occt::unitName(doc.unit), 1);
        writer.Model()->ChangeGlobalSection().SetCascadeUnit(unitInMm);
        writer.Model()->ChangeGlobalSection().SetSendName(
            new TCollection_HAsciiString(cadSafeName(productName(doc, product), kMaxIgesNameBytes, true).c_str()));
        if (!writer.AddShape(cad.shape)) throw std::runtime_error("OpenCASCADE could not transfer the shape to IGES");
        writer.ComputeModel();
        std::ostringstream text;
        if (!writer.Write(text)) throw std::runtime_error("OpenCASCADE could not print the IGES model");
        cad.stats.bytes = text.str().size();
        if (stats) *stats = cad.stats;
        return std::move(text).str();
    } catch (const Standard_Failure& e) {
        throw std::runtime_error(std::string("OpenCASCADE failed: ") + e.GetMessageString());
    }
}

// How many faces the file at `path` holds as OpenCASCADE reads it (OCCT's lock held by the caller).
std::string countFacesHeld(const std::filesystem::path& path, bool iges) {
    try {
        TopoDS_Shape shape;
        if (iges) {
            IGESControl_Reader reader;
            if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return "Eit is not a readable IGES file";
            if (reader.TransferRoots() == 0) return "Ethe IGES file holds no shape";
            shape = reader.OneShape();
        } else {
            STEPControl_Reader reader;
            if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return "Eit is not a readable STEP file";
            if (reader.TransferRoots() == 0) return "Ethe STEP file holds no shape";
            shape = reader.OneShape();
        }
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(shape, TopAbs_FACE, faces);
        return "F" + std::to_string(faces.Extent());
    } catch (const Standard_Failure& e) {
        return std::string("EOpenCASCADE failed reading it: ") + e.GetMessageString();
    }
}

}  // namespace

std::string exportStepText(const Document& doc, const StepExportOptions& options, StepExportStats* stats) {
    const auto held = occt::lock();
    return stepTextHeld(doc, options, stats);
}

std::string exportIgesText(const Document& doc, StepExportStats* stats, const std::string& product) {
    const auto held = occt::lock();
    return igesTextHeld(doc, stats, product);
}

// OpenCASCADE's writer runs in a child process (a crash there, as its IGES writer's on a long name,
// cannot take the program down), and the file it wrote is read back by OpenCASCADE's reader, in
// another child, with every face, before it replaces anything (issue 73).
StepExportStats exportStep(const Document& doc, const std::filesystem::path& path, const StepExportOptions& options) {
    const std::string ext = lowerExtension(path);
    const bool iges = ext == ".iges" || ext == ".igs";
    if (!iges && ext != ".step" && ext != ".stp")
        throw OutputError(path.string(), "unknown CAD extension '" + ext + "' (use .step, .stp, .iges or .igs)");
    checkOutputPath(path);  // a path that cannot be written is refused before the work
    StepExportOptions named = options;
    if (named.product.empty() && (doc.name.empty() || doc.name == "untitled")) named.product = path.stem().string();
    const double seconds = cadSecondsLimit(120.0);
    const auto held = occt::lock();
    const BoundedResult written = runBounded(
        [&]() -> std::string {
            try {
                StepExportStats st;
                std::string text = iges ? igesTextHeld(doc, &st, named.product) : stepTextHeld(doc, named, &st);
                char head[200];
                std::snprintf(head, sizeof head, "T%zu %zu %zu %zu %zu %zu %zu %zu\n", st.faces, st.shells, st.solids, st.sharedEdges,
                              st.freeEdges, st.degenerateEdges, st.bytes, st.parts);
                return head + text;
            } catch (const std::exception& e) {
                return std::string("E") + e.what();
            }
        },
        seconds, limits::kMaxCadImportBytes);
    if (written.kind != BoundedResult::Kind::Done)
        throw OutputError(path.string(),
                          cadChildFailure(written, "writing it", seconds, limits::kMaxCadImportBytes) + "; nothing was written");
    const std::string& out = written.output;
    if (out.empty() || out[0] != 'T')
        throw OutputError(path.string(), out.empty() ? std::string("OpenCASCADE wrote nothing") : out.substr(1));
    StepExportStats stats;
    const size_t eol = out.find('\n');
    std::sscanf(out.c_str() + 1, "%zu %zu %zu %zu %zu %zu %zu %zu", &stats.faces, &stats.shells, &stats.solids, &stats.sharedEdges,
                &stats.freeEdges, &stats.degenerateEdges, &stats.bytes, &stats.parts);
    const std::string_view text = std::string_view(out).substr(eol == std::string::npos ? out.size() : eol + 1);
    writeFileAtomic(path, text, [&](const std::filesystem::path& staged) {
        const BoundedResult read = runBounded([&] { return countFacesHeld(staged, iges); }, seconds, limits::kMaxCadImportBytes);
        if (read.kind != BoundedResult::Kind::Done)
            throw InputError(path.string(),
                             cadChildFailure(read, "reading it back", seconds, limits::kMaxCadImportBytes) + "; nothing was written");
        if (read.output.empty() || read.output[0] != 'F')
            throw InputError(path.string(), read.output.empty() ? "no answer" : read.output.substr(1));
        const size_t faces = size_t(std::atoll(read.output.c_str() + 1));
        if (faces != stats.faces)
            throw InputError(path.string(),
                             "OpenCASCADE reads " + std::to_string(faces) + " of its " + std::to_string(stats.faces) + " faces");
    });
    return stats;
}

}  // namespace io
}  // namespace pw

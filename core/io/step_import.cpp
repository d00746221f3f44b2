// STEP/IGES surfaces to Bézier patches (step_import.hpp).
#include "core/io/step_import.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_BSplineSurfaceToBezierSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <StepShape_AdvancedFace.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <sstream>
#include <unordered_map>
#include <variant>
#include <vector>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/limits.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/io/bounded_child.hpp"
#include "core/io/cad_labels.hpp"
#include "core/io/cad_plane_fan.hpp"
#include "core/io/cad_trim_import.hpp"
#include "core/io/cad_values.hpp"
#include "core/io/occt_support.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/model/camera_math.hpp"
#include "core/model/join_detect.hpp"
#include "core/ops/net_ops.hpp"
#include "core/ops/patch_ops.hpp"

namespace pw {
inline namespace io {

namespace {

// When the 2-D curve is a line of constant u or constant v (an edge of the parameter rectangle),
// possibly trimmed, or a B-spline whose poles all share u or v: records that value in `us` or `vs`
// and returns true.
bool isoCurve(const Handle(Geom2d_Curve) & c, std::vector<double>& us, std::vector<double>& vs, double tol) {
    Handle(Geom2d_Curve) curve = c;
    if (auto t = Handle(Geom2d_TrimmedCurve)::DownCast(curve)) curve = t->BasisCurve();
    if (auto l = Handle(Geom2d_Line)::DownCast(curve)) {
        const gp_Dir2d d = l->Direction();
        if (std::abs(d.X()) < 1e-12)
            us.push_back(l->Location().X());
        else if (std::abs(d.Y()) < 1e-12)
            vs.push_back(l->Location().Y());
        else
            return false;
        return true;
    }
    if (auto b = Handle(Geom2d_BSplineCurve)::DownCast(curve)) {
        bool sameU = true, sameV = true;
        const gp_Pnt2d p0 = b->Pole(1);
        for (int i = 2; i <= b->NbPoles(); ++i) {
            sameU = sameU && std::abs(b->Pole(i).X() - p0.X()) < tol;
            sameV = sameV && std::abs(b->Pole(i).Y() - p0.Y()) < tol;
        }
        if (sameU)
            us.push_back(p0.X());
        else if (sameV)
            vs.push_back(p0.Y());
        return sameU || sameV;
    }
    return false;
}

// The face's surface as a (possibly rational) B-spline of degree <= 3 over exactly the face's parameter
// rectangle, oriented like the face; or the reason it cannot be. Planes, cylinders, cones, spheres,
// tori, surfaces of revolution and extrusion and offsets are first converted by OpenCASCADE, face
// and boundary curves together, to B-splines (exact for the analytic and swept surfaces: conics are
// rational quadratics); `converted` names the surface the face had.
// A face whose outline is not its rectangle says "trimmed: …" (cad_trim_import.hpp takes it then).
std::variant<Handle(Geom_BSplineSurface), std::string> faceSurface(const FaceBSpline& fb) {
    const TopoDS_Face& face = fb.face;
    Handle(Geom_BSplineSurface) bs = Handle(Geom_BSplineSurface)::DownCast(fb.surface->Copy());
    double su0, su1, sv0, sv1;
    bs->Bounds(su0, su1, sv0, sv1);
    const double isoTol = 1e-9 * std::max(su1 - su0, sv1 - sv0);  // p-curves written as iso lines to rounding

    int wires = 0;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
    if (wires != 1) return "trimmed: " + std::to_string(wires) + " boundary loops (holes)";
    // The boundary must be the parameter rectangle; its exact sides are the iso lines' values
    // (BRepTools::UVBounds is a box grown by tolerances).
    std::vector<double> us, vs;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        double f = 0, l = 0;
        const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, face, f, l);
        if (pc.IsNull() || !isoCurve(pc, us, vs, isoTol)) {
            if (BRep_Tool::Degenerated(edge)) continue;
            return std::string("trimmed by a curve that is not a parameter line");
        }
    }
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    if (us.size() >= 2) {
        u0 = *std::min_element(us.begin(), us.end());
        u1 = *std::max_element(us.begin(), us.end());
    }
    if (vs.size() >= 2) {
        v0 = *std::min_element(vs.begin(), vs.end());
        v1 = *std::max_element(vs.begin(), vs.end());
    }
    const double eu = 1e-9 * (su1 - su0), ev = 1e-9 * (sv1 - sv0);
    if (u0 < su0 - eu || u1 > su1 + eu || v0 < sv0 - ev || v1 > sv1 + ev) return std::string("its boundary leaves the surface");
    // Every side on the rectangle's own sides: an L of iso lines is not its bounding rectangle.
    for (double u : us)
        if (std::min(std::abs(u - u0), std::abs(u - u1)) > eu) return std::string("trimmed: its outline is not its parameter rectangle");
    for (double v : vs)
        if (std::min(std::abs(v - v0), std::abs(v - v1)) > ev) return std::string("trimmed: its outline is not its parameter rectangle");
    if (u0 > su0 + eu || u1 < su1 - eu || v0 > sv0 + ev || v1 < sv1 - ev) bs->Segment(u0, u1, v0, v1);  // exact
    if (face.Orientation() == TopAbs_REVERSED) bs->UReverse();
    return bs;
}

// A length in a note: three significant digits ("2.5e-06", "0.000448").
std::string threeDigits(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

std::optional<LengthUnit> g_assumedUnit;  // assumeCadUnit
std::optional<double> g_cadTolerance;     // setCadTolerance

// The file's length unit where it is one of a document's (millimetre, centimetre, metre, inch);
// otherwise the unit assumed by `--unit` (with a note), or refused naming what the file says.
LengthUnit fileUnit(STEPControl_Reader& reader, const std::filesystem::path& path, std::string& note) {
    TColStd_SequenceOfAsciiString lengths, angles, solidAngles;
    reader.FileUnits(lengths, angles, solidAngles);
    std::string problem;
    std::optional<LengthUnit> unit;
    for (int i = 1; i <= lengths.Length(); ++i) {
        TCollection_AsciiString name = lengths.Value(i);
        name.LowerCase();
        std::optional<LengthUnit> u;
        if (name == "millimetre" || name == "millimeter") u = LengthUnit::Millimetre;
        if (name == "centimetre" || name == "centimeter") u = LengthUnit::Centimetre;
        if (name == "metre" || name == "meter") u = LengthUnit::Metre;
        if (name.Search("inch") == 1) u = LengthUnit::Inch;
        if (!u) {
            problem = "its length unit '" + std::string(lengths.Value(i).ToCString()) + "' is not one Patchwork reads (mm, cm, m, in)";
            break;
        }
        if (unit && *unit != *u) {
            problem = "it names different length units in different parts";
            break;
        }
        unit = u;
    }
    if (!unit && problem.empty()) problem = "it names no length unit";
    if (problem.empty()) return *unit;
    if (!g_assumedUnit)
        throw InputError(path.string(), problem + ", so millimetres cannot be told from metres; give the unit with --unit mm|cm|m|in");
    note = "read in " + std::string(lengthUnitName(*g_assumedUnit)) + " as --unit says: " + problem;
    return *g_assumedUnit;
}

// The unit an IGES file's global section declares (its unit flag, or for flag 3 its unit name),
// as the document's: the same where Patchwork has it (in, mm, m, cm); else, with a note, the one
// nearest in size (microns come in as millimetres, kilometres as metres), inches for the imperial
// ones (feet, miles, mils): OpenCASCADE converts the coordinates. A file without a usable unit is
// refused.
LengthUnit igesFileUnit(const IGESData_GlobalSection& g, const std::filesystem::path& path, std::string& note) {
    // Metres per file unit, by the flag (IGES 5.3, global parameter 14), or for flag 3 by the name
    // (parameter 15). OpenCASCADE's own UnitValue() answers 1 for feet.
    static const std::pair<const char*, double> kIgesUnits[] = {{"IN", 0.0254},   {"MM", 0.001}, {"", 0.0},       {"FT", 0.3048},
                                                                {"MI", 1609.344}, {"M", 1.0},    {"KM", 1000.0},  {"MIL", 2.54e-5},
                                                                {"UM", 1e-6},     {"CM", 0.01},  {"UIN", 2.54e-8}};
    const std::string name = g.UnitName().IsNull() ? std::string() : std::string(g.UnitName()->ToCString());
    double metres = 0.0;
    if (g.UnitFlag() >= 1 && g.UnitFlag() <= 11) metres = kIgesUnits[g.UnitFlag() - 1].second;
    if (g.UnitFlag() == 3) {
        std::string upper = name;
        for (char& ch : upper) ch = char(std::toupper(static_cast<unsigned char>(ch)));
        if (upper == "INCH") upper = "IN";
        for (const auto& [n, m] : kIgesUnits)
            if (*n && upper == n) metres = m;
    }
    if (!std::isfinite(metres) || !(metres > 0.0))
        throw InputError(path.string(), "its global section declares no length unit Patchwork can read (unit flag " +
                                            std::to_string(g.UnitFlag()) + (name.empty() ? "" : ", unit name '" + name + "'") + ")");
    constexpr LengthUnit kUnits[] = {LengthUnit::Millimetre, LengthUnit::Centimetre, LengthUnit::Metre, LengthUnit::Inch};
    LengthUnit best = LengthUnit::Millimetre;
    for (LengthUnit u : kUnits) {
        if (std::abs(metresPer(u) - metres) <= 1e-9 * metres) return u;
        if (std::abs(std::log(metresPer(u) / metres)) < std::abs(std::log(metresPer(best) / metres))) best = u;
    }
    // Feet, miles, mils and microinches stay imperial.
    const int flag = g.UnitFlag();
    if (flag == 4 || flag == 5 || flag == 8 || flag == 11) best = LengthUnit::Inch;
    char text[200];
    std::snprintf(text, sizeof text, "its unit%s%s (%g m) is not one Patchwork has; read in %s, the nearest in size",
                  name.empty() ? "" : " ", name.c_str(), metres, std::string(lengthUnitName(best)).c_str());
    note = text;
    return best;
}

// The names of the file's faces (ADVANCED_FACE('lid', ...)), by the shape each became, whatever
// its placement (a part of an assembly comes back located); unnamed faces are left out.
struct FaceNames {
    std::unordered_map<const TopoDS_TShape*, std::string> byShape;
    void Bind(const TopoDS_Shape& s, const std::string& name) { byShape[s.TShape().get()] = name; }
    const std::string* Seek(const TopoDS_Shape& s) const {
        const auto it = byShape.find(s.TShape().get());
        return it == byShape.end() ? nullptr : &it->second;
    }
};

FaceNames stepFaceNames(STEPControl_Reader& reader) {
    FaceNames names;
    const Handle(Interface_InterfaceModel) model = reader.Model();
    const Handle(Transfer_TransientProcess) process = reader.WS()->TransferReader()->TransientProcess();
    for (int i = 1; i <= model->NbEntities(); ++i) {
        const auto face = Handle(StepShape_AdvancedFace)::DownCast(model->Value(i));
        if (face.IsNull() || face->Name().IsNull() || face->Name()->Length() == 0) continue;
        const TopoDS_Shape shape = TransferBRep::ShapeResult(process, face);
        if (!shape.IsNull()) names.Bind(shape, face->Name()->ToCString());
    }
    return names;
}

// A polynomial face cut into several Bézier patches may be a uniform B-spline net (a net
// Patchwork wrote comes back one); rebuildNets decides from the patches themselves, since
// OpenCASCADE reads a closed face as periodic and its knots then run past the face.
bool mayBeNet(const Handle(Geom_BSplineSurface) & bs) { return !bs->IsURational() && !bs->IsVRational(); }
int spanCount(const Handle(Geom_BSplineSurface) & bs) {
    return (bs->LastUKnotIndex() - bs->FirstUKnotIndex()) * (bs->LastVKnotIndex() - bs->FirstVKnotIndex());
}

// Whether the first column of poles (s = 0) is one point, as in a triangle's collapsed quad.
bool collapsedColumn(const Handle(Geom_BezierSurface) & z) {
    for (int r = 2; r <= 4; ++r)
        if (z->Pole(1, r).Distance(z->Pole(1, 1)) > 0.0) return false;
    return true;
}

// The patches one such face made: doc.patches[first, first + count).
struct NetFace {
    uint32_t first = 0, count = 0;
    std::string name;
    std::optional<size_t> place;  // "net N" (cad_labels.hpp)
    std::vector<TrimLoop> trims;  // a trimmed face: its loops in the spans' grid, the net's domain
    int face = 0;                 // its number in the file
};

// Each C2 face's patches (their shared points merged) as one uniform B-spline net, closed where
// the face closes on itself, in the faces' order and under the face's name. A face whose knots
// are not uniform (not C2 in the net's uniform parameters) keeps its patches.
// `patchPlaces` (one per patch) loses the entries of the patches that became nets; the nets are
// put in their places.
// A trimmed face whose patches make no net is dropped (its loops span them): its number goes into
// `dropped` and a note into `notes`.
void rebuildNets(Document& doc, const std::vector<NetFace>& netFaces, std::vector<std::optional<size_t>>& patchPlaces,
                 std::vector<std::string>& notes, std::vector<int>& dropped) {
    std::vector<std::optional<size_t>> netPlaces;
    std::vector<bool> converted(doc.patches.size(), false);
    for (auto f = netFaces.begin(); f != netFaces.end(); ++f) {
        std::vector<uint32_t> patches(f->count);
        for (uint32_t k = 0; k < f->count; ++k) patches[k] = f->first + k;
        // 1e-8 × size: above the 1e-9 × size the export's knot removal may move a pole by.
        std::optional<uint32_t> net;
        try {
            net = convertPatchesToNet(doc, patches, 1e-8, /*keepPatches=*/true);
        } catch (const EditError&) {  // not a uniform C2 grid: a C1 one is a Bézier net keeping C1
            try {
                net = convertPatchesToBezierNet(doc, patches, 1e-8, /*keepPatches=*/true);
            } catch (const EditError&) {  // G1 or C0 seams: the face stays patches, joined
            }
        }
        // A trimmed face's loops span its patches, so it must be one net: where the seams are not
        // C1 in the net's even windows (a fit's uneven knots), a Bézier net that keeps them as they are.
        if (!net && !f->trims.empty()) try {
                net = convertPatchesToBezierNet(doc, patches, 1e-8, /*keepPatches=*/true, /*keepC1=*/false);
            } catch (const EditError&) {
            }
        if (!net && !f->trims.empty()) {
            notes.push_back("face " + std::to_string(f->face) + " skipped: trimmed across " + std::to_string(f->count) +
                            " patches that make no net (they do not share whole edges)");
            dropped.push_back(f->face);
            for (uint32_t k = 0; k < f->count; ++k) converted[f->first + k] = true;
            continue;
        }
        if (!net) continue;
        doc.surfaces[*net].name = f->name;
        doc.surfaces[*net].trims = f->trims;
        netPlaces.push_back(f->place);
        for (uint32_t k = 0; k < f->count; ++k) converted[f->first + k] = true;
    }
    // The converted patches go in one pass and the pool is compacted once (a conversion that
    // removed its own patches would renumber the whole pool per patch: quadratic on big files).
    size_t kept = 0;
    for (size_t p = 0; p < doc.patches.size(); ++p)
        if (!converted[p]) {
            if (kept != p) {  // no self-move: it would empty the patch's name
                doc.patches[kept] = std::move(doc.patches[p]);
                patchPlaces[kept] = patchPlaces[p];
            }
            ++kept;
        }
    doc.patches.resize(kept);
    patchPlaces.resize(kept);
    compactPool(doc);
    placeByLabel(doc.surfaces, netPlaces);
}

// The import itself, in whatever process runs it (the caller holds OCCT's lock).
Document importInProcess(const std::filesystem::path& path, bool step, const std::string& bytes, CadImportReport* report) {
    CadImportReport rep;
    Document doc;
    TopTools_IndexedMapOfShape faces;                // the file's faces, numbered from 1
    std::vector<int> skipped;                        // the faces left out
    std::vector<NetFace> netFaces;                   // faces that may come back as nets
    std::vector<std::optional<size_t>> patchPlaces;  // a patch's place when its face is labelled "patch N"
    std::vector<std::optional<size_t>> trianglePlaces;
    std::string unitNote;  // the unit came from --unit, or is the nearest to an IGES file's own
    try {
        TopoDS_Shape shape;
        FaceNames faceNames;
        if (step) {
            STEPControl_Reader reader;
            std::istringstream in(bytes);
            if (reader.ReadStream(path.filename().string().c_str(), in) != IFSelect_RetDone)
                throw InputError(path.string(), "not a readable STEP file (OpenCASCADE could not parse it)");
            // Coordinates come in the file's own length unit, which becomes the document's.
            doc.unit = fileUnit(reader, path, unitNote);
            reader.StepModel()->SetLocalLengthUnit(occt::useLengthUnit(doc.unit));
            if (reader.TransferRoots() == 0) throw InputError(path.string(), "the STEP file holds no shape");
            shape = reader.OneShape();
            faceNames = stepFaceNames(reader);
        } else {
            IGESControl_Reader reader;  // IGES reads only from a path in OCCT 7.6
            if (reader.ReadFile(path.string().c_str()) != IFSelect_RetDone)
                throw InputError(path.string(), "not a readable IGES file (OpenCASCADE could not parse it)");
            doc.unit = igesFileUnit(reader.IGESModel()->GlobalSection(), path, unitNote);
            // As for STEP, the shape comes in the file's unit: OCCT 7.6 reads the target unit from
            // the model's global section (issue 66: a metre file came in 1 000× too large).
            reader.IGESModel()->ChangeGlobalSection().SetCascadeUnit(occt::useLengthUnit(doc.unit));
            if (reader.TransferRoots() == 0) throw InputError(path.string(), "the IGES file holds no shape");
            shape = reader.OneShape();
        }
        TopExp::MapShapes(shape, TopAbs_FACE, faces);
        rep.faces = size_t(faces.Extent());
        // Surfaces of degree above 3 are approximated within --tolerance, by default 1e-4 of the model's size.
        double tolerance = g_cadTolerance.value_or(0.0);
        if (!g_cadTolerance) {
            Bnd_Box box;
            BRepBndLib::Add(shape, box);
            if (!box.IsVoid()) tolerance = 1e-4 * std::sqrt(box.SquareExtent());
        }
        for (int f = 1; f <= faces.Extent(); ++f) {
            // The face's Bézier patches: its B-spline cut at its knots, or a planar face trimmed
            // by curves as a fan from its centre; or the reason it has none.
            occt::BezierPatches patches;
            bool netCandidate = false;
            std::vector<TrimLoop> trims;  // a trimmed face's loops in its spans' grid (cad_trim_import.hpp)
            const auto fb = faceBSpline(TopoDS::Face(faces(f)), tolerance);
            if (const auto* made = std::get_if<FaceBSpline>(&fb); made && !made->approximated.empty())
                rep.notes.push_back("face " + std::to_string(f) + ": a " + made->approximated +
                                    " surface approximated by bicubic patches within " + threeDigits(made->deviation) + " (--tolerance " +
                                    threeDigits(tolerance) + ")");
            std::variant<Handle(Geom_BSplineSurface), std::string> result =
                std::holds_alternative<FaceBSpline>(fb) ? faceSurface(std::get<FaceBSpline>(fb)) : std::get<std::string>(fb);
            // A face trimmed by its outline: a planar one fanned exactly where it can be, else its
            // surface with trim loops.
            std::variant<std::monostate, occt::BezierPatches, std::string> fan;
            if (auto* why = std::get_if<std::string>(&result); why && why->rfind("trimmed", 0) == 0) {
                fan = occt::planarFan(TopoDS::Face(faces(f)));
                if (!std::holds_alternative<occt::BezierPatches>(fan)) {
                    auto t = trimmedFace(std::get<FaceBSpline>(fb));
                    // A rational surface of several spans (a whole cylinder or cone with a hole) makes no
                    // net, which a trimmed face needs: its loops are read again on a polynomial fit.
                    if (auto* tf = std::get_if<TrimmedFace>(&t); tf && !mayBeNet(tf->surface) && spanCount(tf->surface) > 1) {
                        auto poly = polynomialFace(std::get<FaceBSpline>(fb), tolerance);
                        if (auto* p = std::get_if<FaceBSpline>(&poly)) {
                            rep.notes.push_back("face " + std::to_string(f) + ": a rational surface of " +
                                                std::to_string(spanCount(tf->surface)) +
                                                " spans approximated by polynomial bicubic patches within " + threeDigits(p->deviation) +
                                                " (--tolerance " + threeDigits(tolerance) + ")");
                            t = trimmedFace(*p);
                        }
                    }
                    if (auto* tf = std::get_if<TrimmedFace>(&t)) {
                        result = tf->surface;
                        trims = std::move(tf->loops);
                        if (tf->deviation > 0.0)
                            rep.notes.push_back("face " + std::to_string(f) + ": trim curves approximated by cubic segments within " +
                                                std::to_string(tf->deviation) + " (parameter units)");
                    } else {
                        *why += "; " + std::get<std::string>(t);
                    }
                }
            }
            if (auto* bs = std::get_if<Handle(Geom_BSplineSurface)>(&result)) {
                netCandidate = mayBeNet(*bs);
                GeomConvert_BSplineSurfaceToBezierSurface split(*bs);
                for (int i = 1; i <= split.NbUPatches(); ++i)
                    for (int j = 1; j <= split.NbVPatches(); ++j) patches.push_back(split.Patch(i, j));
            } else if (std::holds_alternative<std::monostate>(fan)) {
                fan = occt::planarFan(TopoDS::Face(faces(f)));  // not tried yet (a plane planarFan refuses says why)
            }
            if (auto* fanned = std::get_if<occt::BezierPatches>(&fan); fanned && patches.empty()) {
                patches = std::move(*fanned);
            } else if (patches.empty()) {
                // Why the trims could not be kept, else a plane's own reason, else why the surface itself could not be used.
                const std::string* tried = std::get_if<std::string>(&result);
                const std::string* why = tried && tried->rfind("trimmed", 0) == 0 ? tried : std::get_if<std::string>(&fan);
                rep.notes.push_back("face " + std::to_string(f) + " skipped: " + (why ? *why : std::get<std::string>(result)));
                skipped.push_back(f);
                continue;
            }
            // The face's name on its patches: "lid" for one patch, "lid 3" (in order) for several.
            // A label that is a place (a face Patchwork wrote for an unnamed item) is not a name.
            const std::string* found = faceNames.Seek(faces(f));
            std::string name = found ? *found : std::string();
            const std::optional<size_t> patchPlace = patches.size() == 1 ? cadFaceLabelIndex(name, "patch") : std::nullopt;
            const std::optional<size_t> netPlace = cadFaceLabelIndex(name, "net");
            const std::optional<size_t> trianglePlace = patches.size() == 1 ? cadFaceLabelIndex(name, "triangle") : std::nullopt;
            const bool mayBeTriangle = patches.size() == 1 && !netPlace && !patchPlace && trims.empty();
            if (!trims.empty() && patches.size() > 1 && !netCandidate) {  // its loops would span patches, not one net
                rep.notes.push_back("face " + std::to_string(f) + " skipped: trimmed across " + std::to_string(patches.size()) +
                                    " rational spans (a trimmed face comes in as one patch or one polynomial net)");
                skipped.push_back(f);
                continue;
            }
            if (patchPlace || netPlace || trianglePlace) name.clear();
            if (netCandidate && (patches.size() > 1 || netPlace))
                netFaces.push_back({uint32_t(doc.patches.size()), uint32_t(patches.size()), name, netPlace, trims, f});

            for (size_t k = 0; k < patches.size(); ++k) {
                // Raised to bicubic per Bézier patch: BSplSLib's degree elevation of a whole
                // rational B-spline fails in OCCT 7.6 (an out-of-range index on a converted sphere).
                const Handle(Geom_BezierSurface)& z = patches[k];
                z->Increase(3, 3);
                // A Bézier triangle written as a collapsed quad (by Patchwork, or exactly one by
                // another system) comes back a triangle.
                Net16 poles;  // row-major like Patch::idx
                double extent = 1.0;
                for (int r = 0; r < 4; ++r)
                    for (int c = 0; c < 4; ++c) {
                        const gp_Pnt p = z->Pole(c + 1, r + 1);
                        poles[size_t(r * 4 + c)] = Vec3(p.X(), p.Y(), p.Z());
                        extent = std::max({extent, std::abs(p.X()), std::abs(p.Y()), std::abs(p.Z())});
                    }
                if (mayBeTriangle && !z->IsURational() && !z->IsVRational() && collapsedColumn(z)) {
                    if (const std::optional<Net10> net = collapsedQuadAsTriangle(poles, 1e-9 * extent)) {
                        TrianglePatch tri;
                        tri.name = name;
                        for (size_t c = 0; c < 10; ++c) {
                            tri.idx[c] = uint32_t(doc.points.size());
                            doc.points.push_back((*net)[c]);
                        }
                        doc.triangles.push_back(tri);
                        trianglePlaces.push_back(trianglePlace);
                        continue;
                    }
                }
                Patch patch;
                if (patches.size() == 1) patch.trims = trims;
                if (!name.empty()) patch.name = patches.size() > 1 ? name + " " + std::to_string(k) : name;
                if (trianglePlace) patch.name = "triangle " + std::to_string(*trianglePlace);  // a quad after all: keep its label
                for (int r = 0; r < 4; ++r)
                    for (int c = 0; c < 4; ++c) {
                        patch.idx[size_t(r * 4 + c)] = uint32_t(doc.points.size());
                        doc.points.push_back(poles[size_t(r * 4 + c)]);
                        if (z->IsURational() || z->IsVRational())
                            setPointWeight(doc, uint32_t(doc.points.size() - 1), z->Weight(c + 1, r + 1));
                    }
                doc.patches.push_back(patch);
                patchPlaces.push_back(patchPlace);
                if (doc.patches.size() > limits::kMaxPatches)
                    throw InputError(path.string(), "more than " + std::to_string(limits::kMaxPatches) + " patches");
            }
            ++rep.importedFaces;
        }
    } catch (const Standard_Failure& e) {
        const std::string why = *e.GetMessageString() ? e.GetMessageString() : e.DynamicType()->Name();  // some say nothing
        throw InputError(path.string(), "OpenCASCADE stopped reading it: " + why);
    }
    const size_t skippedBeforeNets = skipped.size();
    if (doc.patches.empty()) {
        std::string why = rep.faces == 0 ? "it has no faces" : rep.notes.empty() ? "its faces are all triangles" : rep.notes.front();
        throw InputError(path.string(), "no surface Patchwork can edit (" + why + ")");
    }
    for (const Vec3& p : doc.points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
            std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > limits::kMaxCoordinate)
            throw InputError(path.string(), "a control point is not finite or too large");
    const Bounds box = computeBounds(doc.points);
    mergeCoincidentPoints(doc, 1e-9 * modelSize(doc));
    rebuildNets(doc, netFaces, patchPlaces, rep.notes, skipped);
    rep.importedFaces -= std::min(rep.importedFaces, skipped.size() - skippedBeforeNets);
    if (doc.patches.empty() && doc.surfaces.empty() && doc.triangles.empty())
        throw InputError(path.string(), "no surface Patchwork can edit (" + rep.notes.back() + ")");
    // The share of the area skipped: measured only when a face was (an integral per face).
    if (!skipped.empty()) {
        std::sort(skipped.begin(), skipped.end());
        try {
            for (int f = 1; f <= faces.Extent(); ++f) {
                GProp_GProps props;
                BRepGProp::SurfaceProperties(faces(f), props);
                rep.area += std::abs(props.Mass());
                if (std::binary_search(skipped.begin(), skipped.end(), f)) rep.skippedArea += std::abs(props.Mass());
            }
        } catch (const Standard_Failure& e) {
            throw InputError(path.string(), std::string("OpenCASCADE stopped measuring it: ") + e.GetMessageString());
        }
    }
    placeByLabel(doc.patches, patchPlaces);
    placeByLabel(doc.triangles, trianglePlaces);
    doc.joins = detectJoins(doc);
    doc.name = path.stem().string();
    doc.camera.zUp = true;  // CAD systems are Z-up
    doc.camera = frameBounds(doc.camera, box, 1.0);
    if (!unitNote.empty()) rep.notes.push_back(unitNote);
    if (report) *report = rep;
    return doc;
}

// What the child sends back: "E" and the reason, or "D", the report's counts and notes (one a line,
// then an empty line) and the document as a .patchwork text.
std::string encodeResult(const std::filesystem::path& path, bool step, const std::string& bytes) {
    try {
        CadImportReport rep;
        const Document doc = importInProcess(path, step, bytes, &rep);
        char counts[96];
        std::snprintf(counts, sizeof counts, "D%zu %zu %.17g %.17g\n", rep.faces, rep.importedFaces, rep.area, rep.skippedArea);
        std::string out = counts;
        for (std::string note : rep.notes) {
            std::replace(note.begin(), note.end(), '\n', ' ');
            out += note + "\n";
        }
        return out + "\n" + serializeDocument(doc);
    } catch (const InputError& e) {
        return "E" + e.reason();
    }
}

}  // namespace

void assumeCadUnit(std::optional<LengthUnit> unit) { g_assumedUnit = unit; }
void setCadTolerance(std::optional<double> tolerance) { g_cadTolerance = tolerance; }

double cadSecondsLimit(double fallback) {
    if (const char* s = std::getenv("PATCHWORK_CAD_SECONDS"); s && *s) return std::max(0.001, std::atof(s));
    return fallback;
}

std::string CadImportReport::skippedSummary() const {
    if (importedFaces >= faces) return {};
    char share[64] = "";
    if (area > 0) std::snprintf(share, sizeof share, ", %.3g %% of the area", 100.0 * skippedArea / area);
    return "skipped " + std::to_string(faces - importedFaces) + " of " + std::to_string(faces) + " faces" + share;
}

Document importCadSurfaces(const std::filesystem::path& path, CadImportReport* report) {
    const std::string ext = lowerExtension(path);
    const bool step = ext == ".step" || ext == ".stp";
    if (!step && ext != ".iges" && ext != ".igs") throw InputError(path.string(), "not a STEP (.step, .stp) or IGES (.iges, .igs) file");
    const std::string bytes = readFileLimited(path);  // size limit and a clear error for a missing file
    checkCadValues(path.string(), bytes, step);       // non-finite, huge and overlong values, before OpenCASCADE
    const double seconds = cadSecondsLimit(limits::kMaxCadImportSeconds);
    const auto held = occt::lock();
    const BoundedResult r = runBounded([&] { return encodeResult(path, step, bytes); }, seconds, limits::kMaxCadImportBytes);
    if (r.kind != BoundedResult::Kind::Done)
        throw InputError(path.string(), cadChildFailure(r, "reading it", seconds, limits::kMaxCadImportBytes));
    const std::string& out = r.output;
    if (!out.empty() && out[0] == 'E') throw InputError(path.string(), out.substr(1));
    std::istringstream in(out.substr(1));
    CadImportReport rep;
    std::string line;
    std::getline(in, line);
    std::sscanf(line.c_str(), "%zu %zu %lg %lg", &rep.faces, &rep.importedFaces, &rep.area, &rep.skippedArea);
    while (std::getline(in, line) && !line.empty()) rep.notes.push_back(line);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Document doc = parseDocument(text, path.string());
    if (report) *report = std::move(rep);
    return doc;
}

}  // namespace io
}  // namespace pw

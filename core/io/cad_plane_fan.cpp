// Planar CAD faces as fans of ruled Bézier patches (cad_plane_fan.hpp).
#include "core/io/cad_plane_fan.hpp"

#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_BSplineCurveToBezierCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>

namespace pw {
inline namespace io {
namespace occt {

std::variant<std::monostate, BezierPatches, std::string> planarFan(const TopoDS_Face& face) {
    Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)) surface = t->BasisSurface();
    const auto plane = Handle(Geom_Plane)::DownCast(surface);
    if (plane.IsNull()) return std::monostate{};
    int wires = 0;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
    if (wires != 1) return "trimmed: " + std::to_string(wires) + " boundary loops (holes)";
    gp_Vec normal(plane->Position().Direction());
    if (face.Orientation() == TopAbs_REVERSED) normal.Reverse();
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props);
    const gp_Pnt centre = props.CentreOfMass();

    // The boundary as cubic Bézier segments, in the wire's order and direction.
    std::vector<Handle(Geom_BezierCurve)> segments;
    for (BRepTools_WireExplorer e(BRepTools::OuterWire(face), face); e.More(); e.Next()) {
        const TopoDS_Edge& edge = e.Current();
        if (BRep_Tool::Degenerated(edge)) continue;
        double a = 0, b = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, a, b);
        if (curve.IsNull()) return std::string("an edge of its boundary has no 3-D curve");
        Handle(Geom_BSplineCurve) spline = GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(curve, a, b));
        if (spline->Degree() > 3) return "bounded by a curve of degree " + std::to_string(spline->Degree()) + " (3 at most)";
        if (spline->IsPeriodic()) spline->SetNotPeriodic();
        GeomConvert_BSplineCurveToBezierCurve split(spline);
        std::vector<Handle(Geom_BezierCurve)> pieces;
        for (int i = 1; i <= split.NbArcs(); ++i) {
            Handle(Geom_BezierCurve) z = split.Arc(i);
            z->Increase(3);
            pieces.push_back(z);
        }
        if (e.Orientation() == TopAbs_REVERSED) {
            std::reverse(pieces.begin(), pieces.end());
            for (auto& z : pieces) z->Reverse();
        }
        segments.insert(segments.end(), pieces.begin(), pieces.end());
    }
    if (segments.empty()) return std::string("its boundary has no edges");

    // Star-shaped about the centre: (C - O) x C' points the same way along the whole boundary (the
    // patches' normals, with v towards the centre); that way must be the face's normal.
    double lo = 1e300, hi = -1e300, scale = 0.0;
    for (const auto& z : segments)
        for (int k = 0; k <= 8; ++k) {
            gp_Pnt p;
            gp_Vec d;
            z->D1(k / 8.0, p, d);
            const double turn = gp_Vec(centre, p).Crossed(d).Dot(normal);
            lo = std::min(lo, turn), hi = std::max(hi, turn);
            scale = std::max(scale, gp_Vec(centre, p).Magnitude() * d.Magnitude());
        }
    const bool reversed = hi <= 0.0;
    if ((reversed ? -hi : lo) <= 1e-9 * scale)
        return std::string("trimmed by curves round a face that is not star-shaped about its centre");
    if (reversed) {
        std::reverse(segments.begin(), segments.end());
        for (auto& z : segments) z->Reverse();
    }

    // Each segment ruled to the centre: S(u, v) = (1 - v) C(u) + v O, exactly, with C's weights
    // down every column.
    BezierPatches patches;
    for (const auto& z : segments) {
        TColgp_Array2OfPnt poles(1, 4, 1, 4);
        TColStd_Array2OfReal weights(1, 4, 1, 4);
        for (int j = 1; j <= 4; ++j)
            for (int i = 1; i <= 4; ++i) {
                const gp_Pnt p = z->Pole(j);
                poles(j, i) = p.Translated(gp_Vec(p, centre) * ((i - 1) / 3.0));
                weights(j, i) = z->Weight(j);
            }
        patches.push_back(z->IsRational() ? new Geom_BezierSurface(poles, weights) : new Geom_BezierSurface(poles));
    }
    return patches;
}

}  // namespace occt
}  // namespace io
}  // namespace pw

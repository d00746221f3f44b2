#include "core/io/cad_trim_import.hpp"

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2dConvert_ApproxCurve.hxx>
#include <Geom2dConvert_BSplineCurveToBezierCurve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_ApproxSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/trim/trim_loops.hpp"

namespace pw {
inline namespace io {

namespace {

using P2 = glm::dvec2;

std::string typeName(const Handle(Standard_Transient) & s) {
    std::string n = s->DynamicType()->Name();
    if (n.rfind("Geom_", 0) == 0) n = n.substr(5);
    return n;
}

// The edge's p-curve over [first, last] as cubic Bézier segments (3n + 1 points), exact where it
// is a polynomial B-spline of degree <= 3, else approximated within tol2d (the error into `dev`).
std::variant<std::vector<P2>, std::string> cubicChain(const Handle(Geom2d_Curve) & pc, double first, double last, double tol2d,
                                                      double& dev) {
    Handle(Geom2d_TrimmedCurve) tc = new Geom2d_TrimmedCurve(pc, first, last);
    Handle(Geom2d_BSplineCurve) b = Geom2dConvert::CurveToBSplineCurve(tc);
    if (b.IsNull()) return std::string("a trim curve OpenCASCADE could not convert to a B-spline");
    if (b->IsRational() || b->Degree() > 3) {
        Geom2dConvert_ApproxCurve approx(tc, tol2d, GeomAbs_C1, 1000, 3);
        if (!approx.IsDone() || !approx.HasResult())
            return std::string("a trim curve that cubic segments do not follow within the tolerance");
        b = approx.Curve();
        dev = std::max(dev, approx.MaxError());
    }
    if (b->Degree() < 3) b->IncreaseDegree(3);
    Geom2dConvert_BSplineCurveToBezierCurve split(b);
    std::vector<P2> out;
    for (int i = 1; i <= split.NbArcs(); ++i) {
        Handle(Geom2d_BezierCurve) arc = split.Arc(i);
        if (arc->Degree() < 3) arc->Increase(3);
        for (int k = out.empty() ? 1 : 2; k <= 4; ++k) out.emplace_back(arc->Pole(k).X(), arc->Pole(k).Y());
    }
    return out;
}

double coord(const std::array<P2, 4>& b, int axis, double t) {
    const double s = 1.0 - t;
    return s * s * s * b[0][axis] + 3 * s * s * t * b[1][axis] + 3 * s * t * t * b[2][axis] + t * t * t * b[3][axis];
}

// The parameters where the segment crosses the interior knots (sign changes on a fine sample, then bisection).
std::vector<double> knotCrossings(const std::array<P2, 4>& b, int axis, const std::vector<double>& knots) {
    std::vector<double> ts;
    for (size_t k = 1; k + 1 < knots.size(); ++k) {
        const double x = knots[k];
        const int n = 64;
        double prev = coord(b, axis, 0.0) - x;
        for (int i = 1; i <= n; ++i) {
            const double t1 = double(i) / n, cur = coord(b, axis, t1) - x;
            if ((prev < 0.0) != (cur < 0.0) && prev != 0.0) {
                double lo = double(i - 1) / n, hi = t1;
                for (int it = 0; it < 60; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    ((coord(b, axis, mid) - x < 0.0) == (prev < 0.0) ? lo : hi) = mid;
                }
                const double t = 0.5 * (lo + hi);
                if (t > 1e-12 && t < 1.0 - 1e-12) ts.push_back(t);
            }
            prev = cur;
        }
    }
    return ts;
}

// The spans' grid coordinate of parameter x within knots k (span i: [i, i+1] / spans), for a point of span `span`.
double gridCoord(double x, const std::vector<double>& k, size_t span) {
    const double spans = double(k.size() - 1);
    return (double(span) + (x - k[span]) / (k[span + 1] - k[span])) / spans;
}
size_t spanOf(double x, const std::vector<double>& k) {
    size_t i = size_t(std::upper_bound(k.begin(), k.end(), x) - k.begin());
    return std::clamp<size_t>(i == 0 ? 0 : i - 1, 0, k.size() - 2);
}

// A bicubic C1 B-spline over the same parameters (C2 would need degree 5 in
// OCCT's approximation) within `tolerance` of `s`, and the largest
// distance between the two on a grid of 3 to 24 points per span each way (OCCT's own estimate when larger).
std::variant<std::pair<Handle(Geom_BSplineSurface), double>, std::string> bicubicApproximation(const Handle(Geom_BSplineSurface) & s,
                                                                                               double tolerance) {
    try {
        // C1 where that keeps within the tolerance, else C0 (OCCT's C1 fit of FreeCAD's rational
        // sweeps stays millimetres out however many segments it takes): the closer of the two.
        Handle(Geom_BSplineSurface) made;
        double deviation = 0.0;
        for (GeomAbs_Shape continuity : {GeomAbs_C1, GeomAbs_C0}) {
            // Up to 1 000 segments: with 20, a 2 mm sweep came back 7 mm out.
            GeomConvert_ApproxSurface approx(s, 0.5 * tolerance, continuity, continuity, 3, 3, 1000, 0);
            if (!approx.HasResult() || (!made.IsNull() && approx.MaxError() >= deviation)) continue;
            made = approx.Surface();
            deviation = approx.MaxError();
            if (approx.IsDone()) break;  // within the tolerance
        }
        if (made.IsNull()) return std::string("which OpenCASCADE could not approximate by bicubic patches");
        std::vector<double> us, vs;
        auto samples = [](const Handle(Geom_BSplineSurface) & b, bool u, std::vector<double>& out) {
            const int first = u ? b->FirstUKnotIndex() : b->FirstVKnotIndex(), last = u ? b->LastUKnotIndex() : b->LastVKnotIndex();
            for (int k = first; k < last; ++k) {
                const double a = u ? b->UKnot(k) : b->VKnot(k), c = u ? b->UKnot(k + 1) : b->VKnot(k + 1);
                const int n = std::clamp(256 / std::max(1, last - first), 3, 24);  // at most ~256 each way
                for (int i = 0; i < n; ++i) out.push_back(a + (c - a) * (i + 0.5) / n);
            }
        };
        samples(made, true, us);
        samples(made, false, vs);
        for (double u : us)
            for (double v : vs) deviation = std::max(deviation, s->Value(u, v).Distance(made->Value(u, v)));
        if (!(deviation <= tolerance))
            return "which bicubic patches follow only within " + std::to_string(deviation) + " (--tolerance " + std::to_string(tolerance) +
                   ")";
        return std::make_pair(made, deviation);
    } catch (const Standard_Failure& e) {
        return std::string("which OpenCASCADE failed to approximate (") + e.GetMessageString() + ")";
    }
}

}  // namespace

std::variant<FaceBSpline, std::string> faceBSpline(const TopoDS_Face& face, double tolerance) {
    FaceBSpline out;
    out.face = face;
    Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    if (surface.IsNull()) return std::string("it has no surface");
    if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)) surface = t->BasisSurface();
    if (auto b = Handle(Geom_BSplineSurface)::DownCast(surface)) {
        out.surface = Handle(Geom_BSplineSurface)::DownCast(b->Copy());
    } else if (auto z = Handle(Geom_BezierSurface)::DownCast(surface)) {
        out.surface = GeomConvert::SurfaceToBSplineSurface(z);
    } else {
        BRepBuilderAPI_NurbsConvert convert(face, true);
        if (!convert.IsDone() || convert.Shape().ShapeType() != TopAbs_FACE)
            return "a " + typeName(surface) + " surface OpenCASCADE could not convert to a B-spline";
        out.face = TopoDS::Face(convert.Shape());
        out.converted = typeName(surface);
        Handle(Geom_Surface) made = BRep_Tool::Surface(out.face);
        if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(made)) made = t->BasisSurface();
        out.surface = Handle(Geom_BSplineSurface)::DownCast(made);
        if (out.surface.IsNull())
            return "a " + out.converted + " surface OpenCASCADE converted to a " + typeName(made) + " (not a B-spline)";
        out.surface = Handle(Geom_BSplineSurface)::DownCast(out.surface->Copy());
    }
    const std::string what = out.converted.empty() ? std::string() : "a " + out.converted + " surface as a B-spline of ";
    // A periodic surface (a whole cylinder or sphere) is the same surface with clamped knots.
    if (out.surface->IsUPeriodic()) out.surface->SetUNotPeriodic();
    if (out.surface->IsVPeriodic()) out.surface->SetVNotPeriodic();
    if (out.surface->UDegree() > 3 || out.surface->VDegree() > 3) {
        const std::string degree = "degree " + std::to_string(out.surface->UDegree()) + " x " + std::to_string(out.surface->VDegree());
        if (!(tolerance > 0.0)) return what + degree + " (3 at most)";
        auto approx = bicubicApproximation(out.surface, tolerance);
        if (auto* why = std::get_if<std::string>(&approx)) return what + degree + ", " + *why;
        out.deviation = std::get<1>(std::get<std::pair<Handle(Geom_BSplineSurface), double>>(approx));
        out.surface = std::get<0>(std::get<std::pair<Handle(Geom_BSplineSurface), double>>(approx));
        out.approximated = degree;
    }
    return out;
}

std::variant<FaceBSpline, std::string> polynomialFace(const FaceBSpline& face, double tolerance) {
    auto approx = bicubicApproximation(face.surface, tolerance);
    if (auto* why = std::get_if<std::string>(&approx)) return "a rational surface " + *why;
    FaceBSpline out = face;
    std::tie(out.surface, out.deviation) = std::get<std::pair<Handle(Geom_BSplineSurface), double>>(approx);
    out.approximated = "rational";
    return out;
}

std::variant<TrimmedFace, std::string> trimmedFace(const FaceBSpline& f) {
    TrimmedFace out;
    out.surface = Handle(Geom_BSplineSurface)::DownCast(f.surface->Copy());
    // The whole surface, as the file has it, the loops inside it (a face written by Patchwork comes
    // back with the same patch and the same loops); an analytic surface was converted over the face's box.
    double u0, u1, v0, v1;
    out.surface->Bounds(u0, u1, v0, v1);
    if (!(u1 > u0 && v1 > v0)) return std::string("its surface has an empty parameter range");
    std::vector<double> ku, kv;
    // The knots of the surface's range only: an unclamped B-spline (a uniform net as one C2 surface)
    // has knots beyond it, and its windows are the spans inside.
    for (int i = out.surface->FirstUKnotIndex(); i <= out.surface->LastUKnotIndex(); ++i) ku.push_back(out.surface->UKnot(i));
    for (int i = out.surface->FirstVKnotIndex(); i <= out.surface->LastVKnotIndex(); ++i) kv.push_back(out.surface->VKnot(i));
    const double tol2d = 1e-7 * std::max(u1 - u0, v1 - v0);
    // The loops as the surface's parameters run: read from the face turned forward (a reversed
    // face turns its wires and edges too, and a seam edge's two p-curves with them), the face's
    // own turn applied below.
    const TopoDS_Face face = TopoDS::Face(f.face.Oriented(TopAbs_FORWARD));
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
        const TopoDS_Wire& wire = TopoDS::Wire(w.Current());
        std::vector<P2> chain;  // the whole loop in the surface's parameters
        for (BRepTools_WireExplorer e(wire, face); e.More(); e.Next()) {
            const TopoDS_Edge& edge = e.Current();
            double first = 0, last = 0;
            const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, face, first, last);
            if (pc.IsNull()) return std::string("an edge of its boundary has no curve on the surface");
            auto made = cubicChain(pc, first, last, tol2d, out.deviation);
            if (auto* why = std::get_if<std::string>(&made)) return *why;
            std::vector<P2> pts = std::get<std::vector<P2>>(made);
            // The edge's own turn in the wire: the explorer's Orientation() reads it from the vertex it
            // came in by, which a closed edge (a tube's rim) has at both ends.
            if (edge.Orientation() == TopAbs_REVERSED) std::reverse(pts.begin(), pts.end());
            if (chain.empty()) {
                chain = pts;
                continue;
            }
            if (glm::length(pts.front() - chain.back()) > 1e-5 * std::max(u1 - u0, v1 - v0))
                return std::string("its boundary's edges do not follow on from each other in the surface's parameters");
            chain.insert(chain.end(), pts.begin() + 1, pts.end());
        }
        if (chain.size() < 4) continue;
        chain.back() = chain.front();
        // Split at the knot lines, each piece mapped into its span of the grid (exact: affine per span).
        TrimLoop loop;
        for (size_t s = 0; s + 3 < chain.size(); s += 3) {
            const std::array<P2, 4> b{chain[s], chain[s + 1], chain[s + 2], chain[s + 3]};
            std::vector<double> ts = knotCrossings(b, 0, ku);
            const std::vector<double> tv = knotCrossings(b, 1, kv);
            ts.insert(ts.end(), tv.begin(), tv.end());
            ts.push_back(0.0);
            ts.push_back(1.0);
            std::sort(ts.begin(), ts.end());
            for (size_t k = 0; k + 1 < ts.size(); ++k) {
                if (ts[k + 1] - ts[k] < 1e-12) continue;
                const std::array<P2, 4> piece = cubicPiece(b, ts[k], ts[k + 1]);
                const double mt = 0.5 * (ts[k] + ts[k + 1]);
                const size_t si = spanOf(coord(b, 0, mt), ku), sj = spanOf(coord(b, 1, mt), kv);
                for (int q = loop.uv.empty() ? 0 : 1; q < 4; ++q) {
                    const P2 p = piece[size_t(q)];
                    loop.uv.push_back({gridCoord(p.x, ku, si), gridCoord(p.y, kv, sj)});
                }
            }
        }
        loop.uv.back() = loop.uv.front();
        if (f.face.Orientation() == TopAbs_REVERSED)
            for (UV& p : loop.uv) p[0] = 1.0 - p[0];
        for (UV& p : loop.uv) p = {std::clamp(p[0], 0.0, 1.0), std::clamp(p[1], 0.0, 1.0)};
        orientLoop(loop, !wire.IsSame(outer));
        // An outer loop round the whole domain says nothing: the untrimmed surface keeps it all.
        const bool whole =
            !loop.hole && std::abs(signedUvArea(loop) - 1.0) < 1e-9 && std::all_of(loop.uv.begin(), loop.uv.end(), [](const UV& p) {
                return std::min({p[0], 1.0 - p[0], p[1], 1.0 - p[1]}) < 1e-9;
            });
        if (!whole) out.loops.push_back(std::move(loop));
    }
    if (f.face.Orientation() == TopAbs_REVERSED) out.surface->UReverse();
    if (out.loops.empty()) return std::string("its boundary is its parameter rectangle after all");
    if (const std::string why = trimLoopsProblem(out.loops); !why.empty()) return "its boundary as trim loops: " + why;
    return out;
}

}  // namespace io
}  // namespace pw

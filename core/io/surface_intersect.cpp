#include "core/io/surface_intersect.hpp"

#include <GeomAPI_IntSS.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/io/occt_support.hpp"
#include "core/ops/net_ops.hpp"
#include "core/trim/surface_domain.hpp"

namespace pw {
inline namespace io {

namespace {

// The exact surface of a patch or a net, with its parameter ranges (1 a window).
Handle(Geom_BSplineSurface) exactSurface(const Document& doc, const SurfaceRef& r) {
    if (!r.net) {
        const Patch& p = doc.patches[r.index];
        const Net16 net = gatherNet(doc, p.idx);
        const std::optional<Weights16> w = gatherWeights(doc, p.idx);
        if (p.basis != Basis::Bezier) {
            // A single spline window: its Bézier form (the same surface).
            Surface s;
            s.rows = s.cols = 4;
            s.idx.assign(p.idx.begin(), p.idx.end());
            s.basis = p.basis;
            s.tension = p.tension;
            const BezierGrid g = netToBezierGrid(doc, s);
            Net16 bz;
            for (size_t k = 0; k < 16; ++k) bz[k] = g.points[k];
            return occt::bezierSurface(bz);
        }
        return occt::bezierSurface(net, w ? &*w : nullptr);
    }
    return occt::netBezierSurface(netToBezierGrid(doc, doc.surfaces[r.index]));
}

}  // namespace

std::vector<IntersectionBranch> intersectSurfaces(const Document& doc, const SurfaceRef& a, const SurfaceRef& b, size_t samples) {
    if (a == b) throw EditError("a surface does not intersect itself here: name two surfaces");
    const DomainSurface da(doc, a), db(doc, b);
    const double tol = 1e-7 * std::max(da.size(), db.size());
    std::vector<IntersectionBranch> out;
    try {
        const auto guard = occt::lock();
        const Handle(Geom_BSplineSurface) sa = exactSurface(doc, a), sb = exactSurface(doc, b);
        GeomAPI_IntSS inter(sa, sb, tol);
        if (!inter.IsDone()) throw EditError("OpenCASCADE could not intersect " + surfaceRefName(a) + " and " + surfaceRefName(b));
        for (int i = 1; i <= inter.NbLines(); ++i) {
            const Handle(Geom_Curve) c = inter.Line(i);
            if (c.IsNull()) continue;
            const double t0 = c->FirstParameter(), t1 = c->LastParameter();
            if (!std::isfinite(t0) || !std::isfinite(t1) || t1 <= t0) continue;
            IntersectionBranch br;
            const gp_Pnt first = c->Value(t0), last = c->Value(t1);
            br.closed = first.Distance(last) < 1e-6 * std::max(da.size(), db.size());
            const size_t n = std::max<size_t>(samples, 16);
            for (size_t k = 0; k < (br.closed ? n : n + 1); ++k) {
                const gp_Pnt p = c->Value(t0 + (t1 - t0) * double(k) / double(n));
                br.points.emplace_back(p.X(), p.Y(), p.Z());
            }
            out.push_back(std::move(br));
        }
    } catch (const Standard_Failure& e) {
        throw EditError("OpenCASCADE could not intersect " + surfaceRefName(a) + " and " + surfaceRefName(b) + ": " +
                        (e.GetMessageString() ? e.GetMessageString() : "no reason given"));
    }
    // Each sample's place on both surfaces (closest points, each from the last).
    for (IntersectionBranch& br : out) {
        std::optional<UV> ga, gb;
        for (const Vec3& p : br.points) {
            ga = da.closest(p, ga);
            gb = db.closest(p, gb);
            br.onA.push_back(*ga);
            br.onB.push_back(*gb);
        }
    }
    auto length = [](const IntersectionBranch& br) {
        double l = 0.0;
        for (size_t k = 1; k < br.points.size(); ++k) l += glm::length(br.points[k] - br.points[k - 1]);
        return l;
    };
    std::stable_sort(out.begin(), out.end(), [&](const auto& x, const auto& y) { return length(x) > length(y); });
    return out;
}

}  // namespace io
}  // namespace pw

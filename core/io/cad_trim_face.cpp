#include "core/io/cad_trim_face.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <Precision.hxx>
#include <ShapeFix_Face.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <stdexcept>

#include "core/trim/trim_loops.hpp"

namespace pw {
inline namespace io {

namespace {

TopoDS_Wire loopWire(const Handle(Geom_Surface) & surface, const TrimLoop& loop, double tol, const std::string& what) {
    double u0, u1, v0, v1;
    surface->Bounds(u0, u1, v0, v1);
    auto param = [&](const UV& p) { return gp_Pnt2d(u0 + p[0] * (u1 - u0), v0 + p[1] * (v1 - v0)); };
    const size_t n = (loop.uv.size() - 1) / 3;
    // One vertex per place: on a closed surface two corners of the domain can be one point (a
    // tube's seam), and an edge round the seam then starts and ends on the same vertex.
    std::vector<TopoDS_Vertex> joints;
    std::vector<gp_Pnt> at;
    for (size_t s = 0; s < n; ++s) {
        const gp_Pnt2d q = param(loop.uv[3 * s]);
        const gp_Pnt p = surface->Value(q.X(), q.Y());
        size_t same = at.size();
        for (size_t k = 0; k < at.size(); ++k)
            if (at[k].Distance(p) <= tol) same = k;
        joints.push_back(same < at.size() ? joints[same] : TopoDS_Vertex(BRepBuilderAPI_MakeVertex(p)));
        at.push_back(p);
    }
    BRepBuilderAPI_MakeWire wire;
    for (size_t s = 0; s < n; ++s) {
        TColgp_Array1OfPnt2d poles(1, 4);
        for (int k = 0; k < 4; ++k) poles.SetValue(k + 1, param(loop.uv[3 * s + size_t(k)]));
        Handle(Geom2d_BezierCurve) pc = new Geom2d_BezierCurve(poles);
        BRepBuilderAPI_MakeEdge edge(pc, surface, joints[s], joints[(s + 1) % n]);
        if (!edge.IsDone())
            throw std::runtime_error(what + ": OpenCASCADE could not make an edge of trim segment " + std::to_string(s) + " (error " +
                                     std::to_string(int(edge.Error())) + ")");
        wire.Add(edge.Edge());
    }
    if (!wire.IsDone()) throw std::runtime_error(what + ": OpenCASCADE could not join a trim loop's edges into a wire");
    return wire.Wire();
}

TopoDS_Face finish(TopoDS_Face face, double tol) {
    BRepLib::BuildCurves3d(face, tol, GeomAbs_C1, 14, 0);
    ShapeFix_Face fix(face);
    fix.Perform();
    return fix.Face();
}

}  // namespace

std::vector<TopoDS_Face> trimmedFaces(const Handle(Geom_Surface) & surface, const std::vector<TrimLoop>& loops, double tol,
                                      const std::string& what) {
    auto check = [&](const BRepBuilderAPI_MakeFace& f) {
        if (!f.IsDone())
            throw std::runtime_error(what + ": OpenCASCADE could not make a face of it (error " + std::to_string(int(f.Error())) + ")");
    };
    if (loops.empty()) {
        BRepBuilderAPI_MakeFace f(surface, Precision::Confusion());
        check(f);
        return {f.Face()};
    }
    std::vector<size_t> outers, holes;
    for (size_t i = 0; i < loops.size(); ++i) (signedUvArea(loops[i]) > 0.0 ? outers : holes).push_back(i);
    std::vector<TopoDS_Face> out;
    if (outers.empty()) {  // the whole domain less the holes
        BRepBuilderAPI_MakeFace f(surface, Precision::Confusion());
        check(f);
        for (size_t h : holes) f.Add(loopWire(surface, loops[h], tol, what));
        check(f);
        out.push_back(finish(f.Face(), tol));
        return out;
    }
    for (size_t o : outers) {
        BRepBuilderAPI_MakeFace f(surface, loopWire(surface, loops[o], tol, what), true);
        check(f);
        // The holes this outer loop encloses (the innermost outer loop round each hole).
        const std::vector<TrimLoop> just{loops[o]};
        for (size_t h : holes) {
            const glm::dvec2 p(loops[h].uv[0][0], loops[h].uv[0][1]);
            if (!trimKeeps(just, p)) continue;
            bool inner = true;  // not inside another outer loop that lies inside this one
            for (size_t o2 : outers)
                if (o2 != o && trimKeeps(std::vector<TrimLoop>{loops[o2]}, p) &&
                    trimKeeps(just, glm::dvec2(loops[o2].uv[0][0], loops[o2].uv[0][1])))
                    inner = false;
            if (inner) f.Add(loopWire(surface, loops[h], tol, what));
        }
        check(f);
        out.push_back(finish(f.Face(), tol));
    }
    return out;
}

}  // namespace io
}  // namespace pw

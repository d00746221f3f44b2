#include "core/io/cad_trim_face.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <Precision.hxx>
#include <ShapeFix_Face.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <map>
#include <optional>
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

// A piece of a kept region's boundary: a cubic Bézier in the domain [0, 1]², and the domain side
// it runs along (-1 none; 0 u = 0, 1 u = 1, 2 v = 0, 3 v = 1).
struct Piece {
    std::array<glm::dvec2, 4> b{};
    int side = -1;
};

int sideOf(const std::array<glm::dvec2, 4>& b) {
    for (int s = 0; s < 4; ++s) {
        const int axis = s / 2;
        const double at = double(s % 2);
        if (std::all_of(b.begin(), b.end(), [&](const glm::dvec2& p) { return std::abs(p[axis] - at) <= 1e-12; })) return s;
    }
    return -1;
}

Piece straight(glm::dvec2 a, glm::dvec2 c, int side) { return {{a, a + (c - a) / 3.0, a + 2.0 * (c - a) / 3.0, c}, side}; }

// Which domain sides the loops run along, a bit per side.
unsigned sidesTouched(const std::vector<TrimLoop>& loops) {
    unsigned mask = 0;
    for (const TrimLoop& l : loops)
        for (size_t s = 0; s < segmentCount(l); ++s)
            if (const int side = sideOf(loopSegment(l, s)); side >= 0) mask |= 1u << side;
    return mask;
}

// The boundary of what the loops keep as closed chains of pieces, each turned so that the kept
// part lies on its left. Without an outer loop the domain's sides bound it, less the stretches
// that holes run along (a tube's end cut off: the hole runs round the rim and up and down the seam).
std::vector<std::vector<Piece>> regionChains(const std::vector<TrimLoop>& loops, const std::string& what) {
    const bool outer = hasOuterLoop(loops);
    std::array<std::vector<std::pair<double, double>>, 4> sides;  // what is left of each side
    if (!outer) sides.fill({{0.0, 1.0}});
    std::vector<Piece> pieces;
    for (const TrimLoop& l : loops)
        for (size_t s = 0; s < segmentCount(l); ++s) {
            const Piece p{loopSegment(l, s), sideOf(loopSegment(l, s))};
            if (outer || p.side < 0) {
                pieces.push_back(p);
                continue;
            }
            const int along = p.side < 2 ? 1 : 0;  // the coordinate that runs along the side
            const double lo = std::min(p.b[0][along], p.b[3][along]), hi = std::max(p.b[0][along], p.b[3][along]);
            std::vector<std::pair<double, double>> left;
            for (const auto& [a, c] : sides[size_t(p.side)]) {
                if (lo > a) left.emplace_back(a, std::min(c, lo));
                if (hi < c) left.emplace_back(std::max(a, hi), c);
            }
            sides[size_t(p.side)] = left;
        }
    for (int s = 0; s < 4; ++s)
        for (const auto& [a, c] : sides[size_t(s)]) {
            if (c - a < 1e-12) continue;
            // Counter-clockwise round the domain: along v = 0, up u = 1, back along v = 1, down u = 0.
            if (s == 2) pieces.push_back(straight({a, 0.0}, {c, 0.0}, s));
            if (s == 1) pieces.push_back(straight({1.0, a}, {1.0, c}, s));
            if (s == 3) pieces.push_back(straight({c, 1.0}, {a, 1.0}, s));
            if (s == 0) pieces.push_back(straight({0.0, c}, {0.0, a}, s));
        }
    std::vector<std::vector<Piece>> chains;
    std::vector<bool> used(pieces.size(), false);
    for (size_t i = 0; i < pieces.size(); ++i) {
        if (used[i]) continue;
        used[i] = true;
        std::vector<Piece> chain{pieces[i]};
        while (glm::length(chain.back().b[3] - chain.front().b[0]) > 1e-9) {
            size_t next = pieces.size();
            double best = 1e-9;
            for (size_t j = 0; j < pieces.size(); ++j)
                if (!used[j] && glm::length(pieces[j].b[0] - chain.back().b[3]) <= best)
                    next = j, best = glm::length(pieces[j].b[0] - chain.back().b[3]);
            if (next == pieces.size())
                throw std::runtime_error(what + ": its trim loops and the domain's sides do not close round what they keep");
            used[next] = true;
            chain.push_back(pieces[next]);
        }
        chains.push_back(std::move(chain));
    }
    return chains;
}

TrimLoop chainLoop(const std::vector<Piece>& chain) {
    TrimLoop loop;
    for (const Piece& p : chain)
        for (size_t k = loop.uv.empty() ? 0 : 1; k < 4; ++k) loop.uv.push_back({p.b[k].x, p.b[k].y});
    return loop;
}

// The faces of the kept region when a loop runs along the domain's sides: each outer chain a face
// with the hole chains inside it. A piece on u = 1 and one on u = 0 over the same stretch of a
// closed surface (or v = 1 and v = 0) are one seam edge with two p-curves, as a closed face needs;
// a side collapsed to a point (a pole) is a degenerated edge.
std::vector<TopoDS_Face> regionFaces(const Handle(Geom_Surface) & surface, const std::vector<TrimLoop>& loops, double tol,
                                     const std::string& what) {
    const std::vector<std::vector<Piece>> chains = regionChains(loops, what);
    std::vector<TrimLoop> asLoops;
    std::vector<size_t> outers, holes;
    for (size_t i = 0; i < chains.size(); ++i) {
        asLoops.push_back(chainLoop(chains[i]));
        (signedUvArea(asLoops[i]) > 0.0 ? outers : holes).push_back(i);
    }
    std::vector<std::vector<size_t>> groups;  // an outer chain, then its holes
    for (size_t o : outers) groups.push_back({o});
    for (size_t h : holes) {
        const std::array<glm::dvec2, 4> mid = cubicPiece(chains[h][0].b, 0.5, 1.0);
        size_t best = groups.size();
        for (size_t g = 0; g < groups.size(); ++g)
            if (trimKeeps(std::vector<TrimLoop>{asLoops[groups[g][0]]}, mid[0]) &&
                (best == groups.size() || signedUvArea(asLoops[groups[g][0]]) < signedUvArea(asLoops[groups[best][0]])))
                best = g;
        if (best == groups.size()) throw std::runtime_error(what + ": a hole of its trim lies outside everything it keeps");
        groups[best].push_back(h);
    }
    std::vector<TopoDS_Face> out;
    BRep_Builder b;
    for (size_t g = 0; g < groups.size(); ++g) {
        // Each face its own surface: two faces on one surface handle would share its p-curves' slot.
        const Handle(Geom_Surface) s = g == 0 ? surface : Handle(Geom_Surface)::DownCast(surface->Copy());
        double u0, u1, v0, v1;
        s->Bounds(u0, u1, v0, v1);
        auto param = [&](const glm::dvec2& p) { return gp_Pnt2d(u0 + p.x * (u1 - u0), v0 + p.y * (v1 - v0)); };
        auto at = [&](const glm::dvec2& p) { return s->Value(param(p).X(), param(p).Y()); };
        auto pcurve = [&](const std::array<glm::dvec2, 4>& c) {
            TColgp_Array1OfPnt2d poles(1, 4);
            for (int k = 0; k < 4; ++k) poles.SetValue(k + 1, param(c[size_t(k)]));
            return Handle(Geom2d_BezierCurve)(new Geom2d_BezierCurve(poles));
        };
        std::vector<std::pair<gp_Pnt, TopoDS_Vertex>> vertices;
        auto vertexAt = [&](const glm::dvec2& uv) {
            const gp_Pnt p = at(uv);
            for (const auto& [q, v] : vertices)
                if (q.Distance(p) <= tol) return v;
            vertices.emplace_back(p, BRepBuilderAPI_MakeVertex(p).Vertex());
            return vertices.back().second;
        };
        auto samePlace = [&](const std::array<glm::dvec2, 4>& c, const std::array<glm::dvec2, 4>& d) {
            for (double t : {0.0, 0.5, 1.0})
                if (at(cubicPiece(c, 0.0, t)[3]).Distance(at(cubicPiece(d, 0.0, t)[3])) > tol) return false;
            return true;
        };
        std::map<std::pair<size_t, size_t>, TopoDS_Edge> edges;  // (chain, piece) → its edge, turned for its use
        // The twin of a piece on u = 1 (v = 1): the piece on u = 0 (v = 0) over the same stretch, run the other way.
        auto twinOf = [&](const Piece& a, const std::array<glm::dvec2, 4>& twin) -> std::optional<std::pair<size_t, size_t>> {
            for (size_t c : groups[g])
                for (size_t j = 0; j < chains[c].size(); ++j) {
                    const Piece& o = chains[c][j];
                    if (o.side == a.side - 1 && !edges.count({c, j}) && glm::length(o.b[0] - twin[3]) <= 1e-9 &&
                        glm::length(o.b[3] - twin[0]) <= 1e-9 && samePlace(a.b, twin))
                        return std::make_pair(c, j);
                }
            return std::nullopt;
        };
        for (size_t c : groups[g])
            for (size_t i = 0; i < chains[c].size(); ++i) {
                const Piece& a = chains[c][i];
                if (a.side != 1 && a.side != 3) continue;
                const glm::dvec2 shift(a.side == 1 ? 1.0 : 0.0, a.side == 3 ? 1.0 : 0.0);
                const std::array<glm::dvec2, 4> twin = straight(a.b[0] - shift, a.b[3] - shift, a.side - 1).b;
                const auto o = twinOf(a, twin);
                if (!o) continue;
                BRepBuilderAPI_MakeEdge make(pcurve(a.b), s, vertexAt(a.b[0]), vertexAt(a.b[3]), 0.0, 1.0);
                if (!make.IsDone()) throw std::runtime_error(what + ": OpenCASCADE could not make the seam edge of a trim");
                TopoDS_Edge e = make.Edge();
                b.UpdateEdge(e, pcurve(a.b), pcurve(twin), s, TopLoc_Location(), tol);
                edges[{c, i}] = e;
                edges[*o] = TopoDS::Edge(e.Reversed());
            }
        TopoDS_Face face;
        b.MakeFace(face, s, tol);
        for (size_t c : groups[g]) {
            TopoDS_Wire wire;
            b.MakeWire(wire);
            for (size_t i = 0; i < chains[c].size(); ++i) {
                const Piece& p = chains[c][i];
                if (auto e = edges.find({c, i}); e != edges.end()) {
                    b.Add(wire, e->second);
                    continue;
                }
                const TopoDS_Vertex v0 = vertexAt(p.b[0]), v1 = vertexAt(p.b[3]);
                if (p.side >= 0 && v0.IsSame(v1) && samePlace(p.b, straight(p.b[0], p.b[0], p.side).b)) {  // a pole
                    TopoDS_Edge e;
                    b.MakeEdge(e);
                    b.UpdateEdge(e, pcurve(p.b), s, TopLoc_Location(), tol);
                    b.Add(e, v0.Oriented(TopAbs_FORWARD));
                    b.Add(e, v0.Oriented(TopAbs_REVERSED));
                    b.Range(e, 0.0, 1.0);
                    b.Degenerated(e, true);
                    b.Add(wire, e);
                    continue;
                }
                BRepBuilderAPI_MakeEdge make(pcurve(p.b), s, v0, v1, 0.0, 1.0);
                if (!make.IsDone())
                    throw std::runtime_error(what + ": OpenCASCADE could not make an edge of a trim (error " +
                                             std::to_string(int(make.Error())) + ")");
                b.Add(wire, make.Edge());
            }
            wire.Closed(true);
            b.Add(face, wire);
        }
        out.push_back(finish(face, tol));
    }
    return out;
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
    // A loop along the domain's sides (a tube's end cut off, a notch in an edge, a loop round a
    // closed surface's seam): the kept region's own boundary, sides and seam edges included.
    // An outer loop along the sides is the boundary as it is, unless it may meet itself across a seam.
    const unsigned sides = sidesTouched(loops);
    if (hasOuterLoop(loops) ? (sides & 3u) == 3u || (sides & 12u) == 12u : sides != 0) return regionFaces(surface, loops, tol, what);
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

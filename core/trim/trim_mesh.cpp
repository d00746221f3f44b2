#include "core/trim/trim_mesh.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <map>

#include "core/gpu/trim_math.h"
#include "core/trim/curve_on_surface.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"

namespace pw {
inline namespace trim {

namespace {

struct VertexId {
    uint32_t id = kNoVertex;  // the mesh vertex; none yet for points the triangulation made
};
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexId, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Every trim loop as a closed chain of points, each with its place on the surface and in space. A
// live loop's points are its curve's, so two surfaces cut by one curve share them (one chain); a
// chain also gets every point where any of its surfaces' window lines cross it, so that the cut
// edge is made of the same vertices on both sides and across every window seam: watertight.
struct Chain {
    std::vector<Vec3> at;        // the samples in space
    std::vector<double> params;  // the refined points: sample index + fraction, sorted
    std::vector<uint32_t> ids;   // their mesh vertices, made when first used
};
struct ChainUse {
    size_t chain = 0;
    // Per sample, in the surface's domain, unwrapped along its closed directions (a curve round a
    // tube runs on past 1), and the first sample again at the end where the chain closes.
    std::vector<glm::dvec2> uv;
};

glm::dvec2 lerpUv(const std::vector<glm::dvec2>& uv, double s) {
    const size_t k = std::min(size_t(s), uv.size() - 1);
    const double f = s - double(k);
    return f == 0.0 || k + 1 >= uv.size() ? uv[k] : uv[k] + f * (uv[k + 1] - uv[k]);
}
Vec3 lerpAt(const std::vector<Vec3>& at, double s) {
    const size_t n = at.size(), k = size_t(s) % n;
    const double f = s - std::floor(s);
    return f == 0.0 ? at[k] : at[k] + f * (at[(k + 1) % n] - at[k]);
}

// The uses of one surface's loops, adding chains (a live loop's curve once for all its surfaces).
std::vector<ChainUse> loopChains(const Document& doc, const SurfaceRef& ref, const DomainSurface& surface, std::vector<Chain>& chains,
                                 std::map<int32_t, size_t>& chainOfCurve) {
    std::vector<ChainUse> out;
    for (const TrimLoop& loop : trimsOf(doc, ref)) {
        ChainUse use;
        bool fromCurve = false;
        if (loop.curve >= 0 && size_t(loop.curve) < doc.curves.size() && loop.error.empty() &&
            curveClosed(doc.curves[size_t(loop.curve)])) {
            try {
                const std::vector<Vec3> pts = sampleCurve(doc, doc.curves[size_t(loop.curve)]);
                const std::vector<UV> uv =
                    pointsToDomain(surface, pts, Vec3(loop.direction[0], loop.direction[1], loop.direction[2]), "the trim curve");
                // Unwrapped along the closed directions; an open direction never jumps.
                for (size_t k = 0; k <= uv.size(); ++k) {
                    glm::dvec2 q(uv[k % uv.size()][0], uv[k % uv.size()][1]);
                    if (!use.uv.empty()) {
                        if (surface.closedU()) q.x += std::round(use.uv.back().x - q.x);
                        if (surface.closedV()) q.y += std::round(use.uv.back().y - q.y);
                    }
                    use.uv.push_back(q);
                }
                auto [it, made] = chainOfCurve.try_emplace(loop.curve, chains.size());
                if (made) chains.push_back({pts, {}, {}});
                use.chain = it->second;
                fromCurve = true;
            } catch (const std::exception&) {
                fromCurve = false;
            }
        }
        if (!fromCurve) {
            use.uv = loopPolyline(loop, 16);
            Chain c;
            for (const glm::dvec2& q : use.uv) c.at.push_back(surface.evaluate({q.x, q.y}).p);
            use.uv.push_back(use.uv.front());
            use.chain = chains.size();
            chains.push_back(std::move(c));
        }
        out.push_back(std::move(use));
    }
    return out;
}

// Where the chain crosses the surface's window lines (u = i/W, v = j/H, the seams of a closed
// direction included: the unwrapped coordinates run past them).
void addWindowCrossings(Chain& chain, const ChainUse& use, uint32_t wu, uint32_t wv) {
    for (size_t k = 0; k + 1 < use.uv.size(); ++k) {
        const glm::dvec2 a = use.uv[k], b = use.uv[k + 1];
        for (int axis = 0; axis < 2; ++axis) {
            const double lines = axis == 0 ? wu : wv;
            const double lo = std::min(a[axis], b[axis]) * lines, hi = std::max(a[axis], b[axis]) * lines;
            for (double i = std::floor(lo) + 1.0; i < hi; i += 1.0) {
                const double x = i / lines;
                const double t = (x - a[axis]) / (b[axis] - a[axis]);
                if ((a[axis] - x) * (b[axis] - x) < 0.0 && t > 1e-9 && t < 1.0 - 1e-9) chain.params.push_back(double(k) + t);
            }
        }
    }
}

// Liang–Barsky: the part [t0, t1] of a -> b inside the unit square, if any.
std::optional<std::pair<double, double>> clipToSquare(glm::dvec2 a, glm::dvec2 b) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 d = b - a;
    const double p[4] = {-d.x, d.x, -d.y, d.y}, q[4] = {a.x, 1.0 - a.x, a.y, 1.0 - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return std::nullopt;
            continue;
        }
        const double r = q[i] / p[i];
        if (p[i] < 0.0)
            t0 = std::max(t0, r);
        else
            t1 = std::min(t1, r);
        if (t0 > t1) return std::nullopt;
    }
    return std::make_pair(t0, t1);
}

}  // namespace

void trimMesh(const Document& doc, TriangleMesh& mesh) {
    if (mesh.trimmedGrids.empty()) return;
    const std::vector<PatchInstance> windows = expandPatches(doc);
    auto refOf = [&](const PatchInstance& pi) {
        return pi.patch >= 0 ? SurfaceRef{false, uint32_t(pi.patch)} : SurfaceRef{true, uint32_t(pi.surface)};
    };
    // The trimmed surfaces, their loops as chains, and every chain's points refined.
    struct TrimmedSurface {
        std::unique_ptr<DomainSurface> surface;
        std::vector<ChainUse> uses;
    };
    std::map<std::pair<bool, uint32_t>, TrimmedSurface> surfaces;
    std::vector<Chain> chains;
    std::map<int32_t, size_t> chainOfCurve;
    for (const TrimmedGrid& g : mesh.trimmedGrids) {
        const SurfaceRef ref = refOf(windows[g.window]);
        TrimmedSurface& t = surfaces[{ref.net, ref.index}];
        if (t.surface) continue;
        t.surface = std::make_unique<DomainSurface>(doc, ref);
        t.uses = loopChains(doc, ref, *t.surface, chains, chainOfCurve);
    }
    for (auto& [key, t] : surfaces)
        for (const ChainUse& use : t.uses) addWindowCrossings(chains[use.chain], use, t.surface->windowsU(), t.surface->windowsV());
    for (Chain& c : chains) {
        // The crossings so far, then the samples that are not (within 1e-7 of the chain's size) one
        // of them: a window line through a sample keeps the exact crossing, so both windows meet there.
        std::sort(c.params.begin(), c.params.end());
        Bounds box;
        for (const Vec3& p : c.at) box.add(p);
        const double near = 1e-7 * std::max(box.diagonal(), 1e-300);
        // Crossings of two surfaces' lines at one place (a seam in one plane with another's window
        // line) are one point.
        std::vector<double> crossings;
        for (double x : c.params)
            if (crossings.empty() || glm::length(lerpAt(c.at, x) - lerpAt(c.at, crossings.back())) >= near) crossings.push_back(x);
        c.params = crossings;
        std::vector<double> all = c.params;
        size_t next = 0;
        for (size_t k = 0; k < c.at.size(); ++k) {
            while (next < c.params.size() && c.params[next] < double(k) - 1.0) ++next;
            bool close = false;
            for (size_t j = next; j < c.params.size() && c.params[j] < double(k) + 1.0; ++j)
                close = close || glm::length(lerpAt(c.at, c.params[j]) - c.at[k]) < near;
            if (!close) all.push_back(double(k));
        }
        std::sort(all.begin(), all.end());
        all.erase(std::unique(all.begin(), all.end(), [](double a, double b) { return b - a < 1e-12; }), all.end());
        c.params = std::move(all);
        c.ids.assign(c.params.size(), kNoVertex);
    }
    auto addVertex = [&](const Vec3& p, const Vec3& n, glm::dvec2 w) {
        const uint32_t id = uint32_t(mesh.positions.size());
        mesh.positions.push_back({float(p.x), float(p.y), float(p.z)});
        mesh.normals.push_back({float(n.x), float(n.y), float(n.z)});
        mesh.uvs.push_back({float(w.x), float(w.y)});
        return id;
    };

    std::map<uint32_t, std::vector<uint32_t>> replaced;
    WindowTrims windowTrims(doc);
    for (const TrimmedGrid& g : mesh.trimmedGrids) {
        const PatchInstance& pi = windows[g.window];
        const SurfaceRef ref = refOf(pi);
        const TrimmedSurface& ts = surfaces[{ref.net, ref.index}];
        const DomainSurface& surface = *ts.surface;
        uint32_t r = 0, c = 0;
        const uint32_t wu = surface.windowsU(), wv = surface.windowsV();
        if (ref.net) {
            const uint32_t step = netStep(doc.surfaces[ref.index].basis);
            r = pi.windowRow / step;
            c = pi.windowCol / step;
        }
        const WindowTrim wt = *windowTrims.of(pi);  // a trimmed grid's window always has one
        std::vector<uint32_t>& tris = replaced[g.window];
        if (wt.flags & gpu::kTrimAllGone) continue;  // nothing of it is left
        const MeshRange range = mesh.perWindow[g.window];
        if (!(wt.flags & gpu::kTrimTest)) {  // wholly kept
            tris.assign(mesh.indices.begin() + range.firstIndex, mesh.indices.begin() + range.firstIndex + range.indexCount);
            continue;
        }
        const bool outer = (wt.flags & gpu::kTrimBaseKept) == 0;
        auto toWindow = [&](glm::dvec2 d) {  // the domain point in the window's square, its edges exact
            // On a lattice of 2^-40: one point reached along two paths of rounding is one vertex.
            glm::dvec2 w(std::round((d.x * wu - c) * 0x1p40) * 0x1p-40, std::round((d.y * wv - r) * 0x1p40) * 0x1p-40);
            for (int a = 0; a < 2; ++a) {
                if (std::abs(w[a]) < 1e-7) w[a] = 0.0;
                if (std::abs(w[a] - 1.0) < 1e-7) w[a] = 1.0;
            }
            return w;
        };
        auto onSurface = [&](glm::dvec2 w) {
            const SurfacePoint sp = surface.evaluate({(w.x + c) / wu, (w.y + r) / wv});
            return addVertex(sp.p, sp.n, w);
        };
        Cdt cdt;
        const int L = g.level, S = L + 1;
        for (int i = 0; i <= L; ++i)
            for (int j = 0; j <= L; ++j) {
                const uint32_t id = g.ids[size_t(i * S + j)];
                if (id == kNoVertex) continue;
                cdt.insert(K::Point_2(double(j) / L, double(i) / L))->info().id = id;
            }
        // The chains, clipped to the window's square, as constraints; their points shared. A chain
        // unwrapped past a seam is tried one turn on either side too.
        const std::vector<double> shiftsU = surface.closedU() ? std::vector<double>{-1.0, 0.0, 1.0} : std::vector<double>{0.0};
        const std::vector<double> shiftsV = surface.closedV() ? std::vector<double>{-1.0, 0.0, 1.0} : std::vector<double>{0.0};
        for (const ChainUse& use : ts.uses) {
            Chain& chain = chains[use.chain];
            const size_t n = chain.params.size();
            auto chainVertex = [&](size_t k, glm::dvec2 w) {
                if (chain.ids[k] == kNoVertex) {
                    const glm::dvec2 d = lerpUv(use.uv, chain.params[k]);
                    chain.ids[k] = addVertex(lerpAt(chain.at, chain.params[k]), surface.evaluate({d.x, d.y}).n, w);
                }
                return chain.ids[k];
            };
            for (size_t k = 0; k < n; ++k)
                for (double su : shiftsU)
                    for (double sv : shiftsV) {
                        const glm::dvec2 shift(su, sv);
                        const glm::dvec2 a = toWindow(lerpUv(use.uv, chain.params[k]) + shift);
                        // The closing point is the first chain point a whole turn on: the same bits as the first, shifted.
                        const glm::dvec2 b =
                            k + 1 < n ? toWindow(lerpUv(use.uv, chain.params[k + 1]) + shift)
                                      : toWindow(lerpUv(use.uv, chain.params[0]) + (glm::round(use.uv.back() - use.uv.front()) + shift));
                        const auto part = clipToSquare(a, b);
                        if (!part) continue;
                        const glm::dvec2 pa = a + part->first * (b - a), pb = a + part->second * (b - a);
                        if (part->first == part->second) continue;  // only touches the square
                        auto va = cdt.insert(K::Point_2(pa.x, pa.y));
                        if (va->info().id == kNoVertex) va->info().id = part->first == 0.0 ? chainVertex(k, pa) : onSurface(pa);
                        auto vb = cdt.insert(K::Point_2(pb.x, pb.y));
                        if (vb->info().id == kNoVertex) vb->info().id = part->second == 1.0 ? chainVertex((k + 1) % n, pb) : onSurface(pb);
                        if (va != vb) cdt.insert_constraint(va, vb);  // however short: a gap would let a region leak
                    }
        }
        // Vertices the triangulation made itself (constraints crossing): on the surface.
        for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
            if (v->info().id == kNoVertex) v->info().id = onSurface({v->point().x(), v->point().y()});
        // The regions the constraints cut the square into, each kept or not as most of its area
        // says by the exact test (a sliver between the curve and its chord cannot outvote it).
        std::map<Cdt::Face_handle, int> region;
        std::vector<double> keptArea, goneArea;
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            if (region.count(f)) continue;
            const int id = int(keptArea.size());
            keptArea.push_back(0.0);
            goneArea.push_back(0.0);
            std::vector<Cdt::Face_handle> todo{f};
            region[f] = id;
            while (!todo.empty()) {
                const Cdt::Face_handle h = todo.back();
                todo.pop_back();
                const auto p0 = h->vertex(0)->point(), p1 = h->vertex(1)->point(), p2 = h->vertex(2)->point();
                const double area = 0.5 * std::abs((p1.x() - p0.x()) * (p2.y() - p0.y()) - (p1.y() - p0.y()) * (p2.x() - p0.x()));
                const glm::dvec2 centroid((p0.x() + p1.x() + p2.x()) / 3.0, (p0.y() + p1.y() + p2.y()) / 3.0);
                (trimKeeps(wt.segments, outer, centroid) ? keptArea : goneArea)[size_t(id)] += area;
                for (int e = 0; e < 3; ++e) {
                    const Cdt::Face_handle g = h->neighbor(e);
                    if (h->is_constrained(e) || cdt.is_infinite(g) || region.count(g)) continue;
                    region[g] = id;
                    todo.push_back(g);
                }
            }
        }
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            const size_t id = size_t(region[f]);
            if (keptArea[id] <= goneArea[id]) continue;
            tris.insert(tris.end(), {f->vertex(0)->info().id, f->vertex(1)->info().id, f->vertex(2)->info().id});
        }
    }
    // The index list again, window by window, with the cut windows' new triangles.
    std::vector<uint32_t> indices;
    indices.reserve(mesh.indices.size());
    for (size_t w = 0; w < mesh.perWindow.size(); ++w) {
        MeshRange& range = mesh.perWindow[w];
        const uint32_t first = uint32_t(indices.size());
        if (const auto it = replaced.find(uint32_t(w)); it != replaced.end()) {
            for (size_t t = 0; t + 2 < it->second.size(); t += 3) {
                const uint32_t a = it->second[t], b = it->second[t + 1], cc = it->second[t + 2];
                if (a == b || b == cc || a == cc) continue;
                indices.insert(indices.end(), {a, b, cc});
            }
        } else {
            indices.insert(indices.end(), mesh.indices.begin() + range.firstIndex,
                           mesh.indices.begin() + range.firstIndex + range.indexCount);
        }
        range = {first, uint32_t(indices.size()) - first};
    }
    for (MeshRange& range : mesh.perTriangle) {
        const uint32_t first = uint32_t(indices.size());
        indices.insert(indices.end(), mesh.indices.begin() + range.firstIndex, mesh.indices.begin() + range.firstIndex + range.indexCount);
        range = {first, uint32_t(indices.size()) - first};
    }
    mesh.indices = std::move(indices);
    mesh.trimmedGrids.clear();
    removeUnusedVertices(mesh);
}

TriangleMesh tessellateTrimmed(const Document& doc, int level) {
    TriangleMesh mesh = tessellateDocument(doc, level);
    trimMesh(doc, mesh);
    return mesh;
}

}  // namespace trim
}  // namespace pw

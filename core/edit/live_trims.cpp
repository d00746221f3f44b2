#include "core/edit/live_trims.hpp"

#include <algorithm>
#include <limits>

#include "core/base/errors.hpp"
#include "core/io/surface_intersect.hpp"
#include "core/trim/curve_fit.hpp"
#include "core/trim/curve_on_surface.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_edits.hpp"
#include "core/trim/trim_loops.hpp"

namespace pw {
inline namespace edit {

namespace {

// The curve's points as a chain (closed chains end on their first point).
std::vector<Vec3> chainPoints(const Document& doc, const BezierCurve& c) {
    std::vector<Vec3> out;
    for (uint32_t i : c.idx) out.push_back(doc.points[i]);
    return out;
}

// Writes a fit with the curve's own number of segments into its pool points.
void writeChain(Document& doc, BezierCurve& c, const std::vector<Vec3>& bezier) {
    for (size_t k = 0; k < c.idx.size() && k < bezier.size(); ++k) doc.points[c.idx[k]] = bezier[k];
}

// The samples that make curve `c` from its link now; throws EditError with why not.
std::pair<std::vector<Vec3>, bool> linkSamples(const Document& doc, const BezierCurve& c) {
    const CurveLink& l = *c.link;
    if (l.kind == CurveLinkKind::Intersect) {
        if (!surfaceExists(doc, l.a) || !surfaceExists(doc, l.b)) throw EditError("a surface it intersects is gone");
        const std::vector<IntersectionBranch> branches = intersectSurfaces(doc, l.a, l.b);
        if (branches.empty()) throw EditError(surfaceRefName(l.a) + " and " + surfaceRefName(l.b) + " no longer intersect");
        // The branch nearest the curve as it was.
        const std::vector<Vec3> was = chainPoints(doc, c);
        size_t best = 0;
        double bestD = std::numeric_limits<double>::infinity();
        for (size_t b = 0; b < branches.size(); ++b) {
            double d = 0.0;
            for (size_t k = 0; k < was.size(); k += 3) {
                double m = std::numeric_limits<double>::infinity();
                for (const Vec3& p : branches[b].points) m = std::min(m, glm::length(p - was[k]));
                d += m;
            }
            if (d < bestD) {
                bestD = d;
                best = b;
            }
        }
        return {branches[best].points, branches[best].closed};
    }
    if (l.source < 0 || size_t(l.source) >= doc.curves.size() || !surfaceExists(doc, l.a)) throw EditError("its input is gone");
    const BezierCurve& src = doc.curves[size_t(l.source)];
    const DomainSurface s(doc, l.a);
    const std::vector<UV> uv = pointsToDomain(s, sampleCurve(doc, src), Vec3(l.direction[0], l.direction[1], l.direction[2]),
                                              "curve c" + std::to_string(l.source));
    std::vector<Vec3> pts;
    for (const UV& p : uv) pts.push_back(s.evaluate(p).p);
    return {pts, curveClosed(src)};
}

}  // namespace

uint32_t appendCurve(Document& doc, const std::vector<Vec3>& bezier, bool closed, const std::string& name, std::optional<CurveLink> link) {
    BezierCurve c;
    const size_t n = closed ? bezier.size() - 1 : bezier.size();
    const uint32_t first = uint32_t(doc.points.size());
    for (size_t k = 0; k < n; ++k) {
        doc.points.push_back(bezier[k]);
        c.idx.push_back(first + uint32_t(k));
    }
    if (closed) c.idx.push_back(first);
    c.name = name;
    c.link = std::move(link);
    doc.curves.push_back(std::move(c));
    return uint32_t(doc.curves.size() - 1);
}

std::vector<std::string> refreshTrims(Document& doc) {
    std::vector<std::string> notes;
    if (!hasLiveTrims(doc)) return notes;
    for (size_t ci = 0; ci < doc.curves.size(); ++ci) {
        BezierCurve& c = doc.curves[ci];
        if (!c.link) continue;
        try {
            auto [samples, closed] = linkSamples(doc, c);
            if (closed != curveClosed(c)) throw EditError(closed ? "it has closed into a loop" : "it has opened");
            const size_t segments = curveSegmentCount(c);
            if (samples.size() < (closed ? segments : segments + 3)) throw EditError("too few points remain along it");
            const CurveFit fit = fitCubicChain(samples, closed, segments);
            writeChain(doc, c, fit.bezier);
            c.link->error.clear();
        } catch (const EditError& e) {
            c.link->error = e.what();
            notes.push_back("curve c" + std::to_string(ci) + " keeps its last shape: " + e.what());
        }
    }
    auto relay = [&](std::vector<TrimLoop>& loops, const SurfaceRef& ref) {
        bool any = false;
        for (const TrimLoop& l : loops) any = any || l.curve >= 0;
        if (!any) return;
        std::vector<TrimLoop> next = loops;
        for (TrimLoop& l : next) {
            if (l.curve < 0) continue;
            try {
                const TrimLoop made =
                    loopFromCurve(doc, ref, uint32_t(l.curve), Vec3(l.direction[0], l.direction[1], l.direction[2]), l.hole);
                l.uv = made.uv;
                l.error.clear();
            } catch (const EditError& e) {
                l.error = e.what();
                notes.push_back("the trim of " + surfaceRefName(ref) + " by c" + std::to_string(l.curve) +
                                " keeps its last shape: " + e.what());
            }
        }
        if (const std::string why = trimLoopsProblem(next); !why.empty()) {
            for (TrimLoop& l : loops)
                if (l.curve >= 0) l.error = why;
            notes.push_back("the trims of " + surfaceRefName(ref) + " keep their last shape: " + why);
            return;
        }
        loops = std::move(next);
    };
    for (uint32_t p = 0; p < doc.patches.size(); ++p) relay(doc.patches[p].trims, SurfaceRef{false, p});
    for (uint32_t s = 0; s < doc.surfaces.size(); ++s) relay(doc.surfaces[s].trims, SurfaceRef{true, s});
    return notes;
}

std::vector<TrimEdgeGap> trimEdgeGaps(const Document& doc) {
    // Loops by curve.
    std::vector<std::vector<std::pair<SurfaceRef, const TrimLoop*>>> byCurve(doc.curves.size());
    for (uint32_t p = 0; p < doc.patches.size(); ++p)
        for (const TrimLoop& l : doc.patches[p].trims)
            if (l.curve >= 0 && size_t(l.curve) < doc.curves.size()) byCurve[size_t(l.curve)].push_back({SurfaceRef{false, p}, &l});
    for (uint32_t s = 0; s < doc.surfaces.size(); ++s)
        for (const TrimLoop& l : doc.surfaces[s].trims)
            if (l.curve >= 0 && size_t(l.curve) < doc.curves.size()) byCurve[size_t(l.curve)].push_back({SurfaceRef{true, s}, &l});
    std::vector<TrimEdgeGap> out;
    for (uint32_t c = 0; c < byCurve.size(); ++c) {
        const auto& uses = byCurve[c];
        for (size_t i = 0; i < uses.size(); ++i)
            for (size_t j = i + 1; j < uses.size(); ++j) {
                if (uses[i].first == uses[j].first) continue;
                const DomainSurface sa(doc, uses[i].first), sb(doc, uses[j].first);
                const std::vector<Vec3> pts = sampleCurve(doc, doc.curves[c]);
                try {
                    const std::vector<UV> ua = pointsToDomain(sa, pts, Vec3(0.0), "c"), ub = pointsToDomain(sb, pts, Vec3(0.0), "c");
                    double gap = 0.0;
                    for (size_t k = 0; k < pts.size(); ++k) gap = std::max(gap, glm::length(sa.evaluate(ua[k]).p - sb.evaluate(ub[k]).p));
                    out.push_back({c, uses[i].first, uses[j].first, gap});
                } catch (const EditError&) {  // the curve left a surface: no edge to measure (the loop keeps its last shape)
                }
            }
    }
    return out;
}

}  // namespace edit
}  // namespace pw

// Trimmed surfaces (issue 64): `project C S [normal|view|X|Y|Z]`, `trim S C keep|remove`,
// `intersect A B`, `split-by S C`, `untrim S`. Every curve and loop they make is live
// (core/edit/live_trims.hpp) until `bake` detaches it.
#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/edit/live_trims.hpp"
#include "core/io/surface_intersect.hpp"
#include "core/model/camera_math.hpp"
#include "core/trim/curve_fit.hpp"
#include "core/trim/curve_on_surface.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"

namespace pw {
inline namespace commands {

namespace {

constexpr double kCurveFitTolerance = 1e-6;  // × the surfaces' size: how closely made curves follow the exact ones

uint32_t curveArg(const Document& doc, const std::string& word) {
    std::string w = word;
    if (!w.empty() && (w[0] == 'c' || w[0] == 'C')) w.erase(0, 1);
    return commandIndex(w, doc.curves.size(), "curve");
}

std::string curveName(uint32_t c) { return "c" + std::to_string(c); }

// The direction word of `project`: none (closest point) for "normal", the view's for "view".
Vec3 projectDirection(const EditSession& s, const std::string& mode) {
    if (mode == "normal" || mode.empty()) return Vec3(0.0);
    if (mode == "view") return glm::normalize(Vec3(s.camera.target[0], s.camera.target[1], s.camera.target[2]) - cameraEye(s.camera));
    if (mode == "X" || mode == "x") return Vec3(1, 0, 0);
    if (mode == "Y" || mode == "y") return Vec3(0, 1, 0);
    return Vec3(0, 0, 1);
}

// Adds `loop` to surface `s` of `d`, refusing loops that cross themselves, each other or leave the domain.
void addLoop(Document& d, const SurfaceRef& s, TrimLoop loop) {
    std::vector<TrimLoop>& loops = trimsOf(d, s);
    loops.push_back(std::move(loop));
    if (const std::string why = trimLoopsProblem(loops); !why.empty()) throw EditError("surface " + surfaceRefName(s) + ": " + why);
    if (trimmedArea(DomainSurface(d, s), loops) <= 0.0)
        throw EditError("surface " + surfaceRefName(s) + ": the trim would leave nothing of it");
}

void execProject(CommandContext& ctx) {
    EditSession& s = ctx.session;
    const uint32_t c = curveArg(s.doc, ctx.word(0));
    const SurfaceRef target = parseSurfaceRef(s.doc, ctx.word(1));
    const Vec3 dir = projectDirection(s, ctx.has(2) ? ctx.word(2) : "normal");
    uint32_t made = 0;
    s.apply("Project curve", [&](Document& d) {
        const DomainSurface surface(d, target);
        const BezierCurve& src = d.curves[c];
        const std::vector<UV> uv = pointsToDomain(surface, sampleCurve(d, src), dir, curveName(c));
        std::vector<Vec3> pts;
        for (const UV& p : uv) pts.push_back(surface.evaluate(p).p);
        const bool closed = curveClosed(src);
        const CurveFit fit =
            fitCubicChainWithin(pts, closed, kCurveFitTolerance * surface.size(), std::max<size_t>(curveSegmentCount(src), closed ? 3 : 1));
        CurveLink link;
        link.kind = CurveLinkKind::Project;
        link.a = target;
        link.source = int32_t(c);
        link.direction = {dir.x, dir.y, dir.z};
        made = appendCurve(d, fit.bezier, closed, curveName(c) + " on " + surfaceRefName(target), link);
    });
    ctx.host.status("made " + curveName(made) + ": " + curveName(c) + " on surface " + surfaceRefName(target));
}

void execTrim(CommandContext& ctx) {
    EditSession& s = ctx.session;
    const SurfaceRef target = parseSurfaceRef(s.doc, ctx.word(0));
    const uint32_t c = curveArg(s.doc, ctx.word(1));
    const bool hole = ctx.word(2) == "remove";
    s.apply(hole ? "Cut hole" : "Trim", [&](Document& d) { addLoop(d, target, loopFromCurve(d, target, c, Vec3(0.0), hole)); });
    ctx.host.status(std::string(hole ? "cut a hole in " : "trimmed ") + surfaceRefName(target) + " by " + curveName(c));
}

void execIntersect(CommandContext& ctx) {
    EditSession& s = ctx.session;
    const SurfaceRef a = parseSurfaceRef(s.doc, ctx.word(0)), b = parseSurfaceRef(s.doc, ctx.word(1));
    std::vector<uint32_t> made;
    s.apply("Intersect", [&](Document& d) {
        const std::vector<IntersectionBranch> branches = intersectSurfaces(d, a, b);
        if (branches.empty()) throw EditError("surfaces " + surfaceRefName(a) + " and " + surfaceRefName(b) + " do not intersect");
        const double tol = kCurveFitTolerance * std::max(DomainSurface(d, a).size(), DomainSurface(d, b).size());
        for (size_t i = 0; i < branches.size(); ++i) {
            const CurveFit fit = fitCubicChainWithin(branches[i].points, branches[i].closed, tol, branches[i].closed ? 4 : 2);
            CurveLink link;
            link.kind = CurveLinkKind::Intersect;
            link.a = a;
            link.b = b;
            link.branch = uint32_t(i);
            made.push_back(appendCurve(d, fit.bezier, branches[i].closed, surfaceRefName(a) + " x " + surfaceRefName(b), link));
        }
    });
    std::string list;
    for (uint32_t c : made) list += (list.empty() ? "" : ", ") + curveName(c);
    ctx.host.status("intersection of " + surfaceRefName(a) + " and " + surfaceRefName(b) + ": " + list);
}

void execSplitBy(CommandContext& ctx) {
    EditSession& s = ctx.session;
    const SurfaceRef target = parseSurfaceRef(s.doc, ctx.word(0));
    const uint32_t c = curveArg(s.doc, ctx.word(1));
    SurfaceRef other;
    s.apply("Split by curve", [&](Document& d) {
        // The copy shares the surface's points: both halves are one surface, cut along one curve.
        other = target;
        if (target.net) {
            Surface copy = d.surfaces[target.index];
            copy.name += " (cut)";
            d.surfaces.push_back(copy);
            other.index = uint32_t(d.surfaces.size() - 1);
        } else {
            Patch copy = d.patches[target.index];
            copy.name += " (cut)";
            d.patches.push_back(copy);
            other.index = uint32_t(d.patches.size() - 1);
        }
        addLoop(d, target, loopFromCurve(d, target, c, Vec3(0.0), true));
        addLoop(d, other, loopFromCurve(d, other, c, Vec3(0.0), false));
    });
    ctx.host.status("split " + surfaceRefName(target) + " by " + curveName(c) + ": the inside is " + surfaceRefName(other));
}

void execUntrim(CommandContext& ctx) {
    EditSession& s = ctx.session;
    const SurfaceRef target = parseSurfaceRef(s.doc, ctx.word(0));
    if (trimsOf(s.doc, target).empty()) throw EditError("surface " + surfaceRefName(target) + " is not trimmed");
    s.apply("Untrim", [&](Document& d) { trimsOf(d, target).clear(); });
}

}  // namespace

void addTrimCommands(CommandTable& t) {
    using namespace arg;
    t.add({.name = "project",
           .label = "Project Curve",
           .menu = "Surface",
           .forms = {{word("C"), word("S"), opt(choice("DIR", {"normal", "view", "X", "Y", "Z"}))}},
           .help = "Make a curve on surface S (a patch number or nN) from curve cN: each point's closest point (normal), or along the "
                   "view or an axis; it stays live, following the curve and the surface",
           .exec = execProject});
    t.add({.name = "trim",
           .label = "Trim",
           .menu = "Surface",
           .forms = {{word("S"), word("C"), choice("MODE", {"keep", "remove"})}},
           .help = "Trim surface S by the closed curve cN laid on it (closest points): keep its inside, or remove it as a hole; the "
                   "trim follows the curve and the surface live",
           .exec = execTrim});
    t.add({.name = "intersect",
           .label = "Intersect",
           .menu = "Surface",
           .forms = {{word("A"), word("B")}},
           .help = "Make the intersection curves of surfaces A and B (OpenCASCADE) as new live curves, on both surfaces",
           .exec = execIntersect});
    t.add({.name = "split-by",
           .label = "Split by Curve",
           .menu = "Surface",
           .forms = {{word("S"), word("C")}},
           .help = "Cut surface S along the closed curve cN into two trimmed surfaces that share the cut: S keeps the outside, a new "
                   "surface the inside",
           .exec = execSplitBy});
    t.add({.name = "untrim",
           .label = "Untrim",
           .menu = "Surface",
           .forms = {{word("S")}},
           .help = "Remove every trim loop of surface S",
           .exec = execUntrim});
}

}  // namespace commands
}  // namespace pw

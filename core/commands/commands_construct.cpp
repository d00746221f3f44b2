// Curves and the surfaces made from them (issue 39): curve-through, curve-control, add-circle,
// add-arc; revolve, extrude (of a curve), loft, edge-surface, sweep1, sweep2, network and bake. Inputs are curves `cN` or patch edges
// `P:u0|u1|v0|v1`; the surfaces stay live (core/construct/constructions.hpp).
#include <algorithm>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/construction_nets.hpp"
#include "core/construct/constructions.hpp"
#include "core/construct/curve_edit.hpp"
#include "core/construct/curves.hpp"
#include "core/model/construction_refs.hpp"
#include "core/ops/patch_ops.hpp"

namespace pw {
inline namespace commands {

namespace {

// "X,Y,Z" → a point.
Vec3 pointWord(const std::string& word) {
    Vec3 p(0.0);
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
        const size_t comma = k < 2 ? word.find(',', start) : word.size();
        if (comma == std::string::npos || (k == 2 && word.find(',', start) != std::string::npos))
            throw EditError("expected a point X,Y,Z, got '" + word + "'");
        p[k] = commandNumber(word.substr(start, comma - start), "a coordinate");
        start = comma + 1;
    }
    return p;
}

// Adds a curve and selects it.
void addShape(CommandContext& ctx, const std::string& undoLabel, const std::function<CurveShape()>& make) {
    EditSession& s = ctx.session;
    int made = -1;
    s.apply(undoLabel, [&](Document& d) { made = int(addCurveShape(d, make(), "")); });
    s.sel.clear();
    s.sel.curve = made;
}

// Makes a construction and selects its first patch.
void construct(CommandContext& ctx, Construction c, const std::string& undoLabel) {
    EditSession& s = ctx.session;
    size_t k = 0;
    const std::string name(constructionKindName(c.kind));
    const ConstructionKind kind = c.kind;
    s.apply(undoLabel, [&](Document& d) {
        k = addConstruction(d, std::move(c), name);
        if (kind == ConstructionKind::Network) compactPool(d);  // its meeting points were made one: the others are no one's now
    });
    s.sel.clear();
    const Construction& made = s.doc.constructions[k];
    if (!made.patches.empty()) s.sel.patch = int(made.patches.front());
    ctx.host.status("Made " + constructionLabel(s.doc, k) + ": " + std::to_string(made.patches.size()) + " patches");
}

std::vector<CurveInput> inputs(const CommandContext& ctx, size_t first, size_t last) {
    std::vector<CurveInput> out;
    for (size_t i = first; i < last; ++i) out.push_back(parseCurveInput(ctx.session.doc, ctx.word(i)));
    return out;
}

std::array<double, 3> arr(const Vec3& v) { return {v.x, v.y, v.z}; }

// Word 0 as a curve `cN` (not a patch edge).
uint32_t curveArg(const CommandContext& ctx) {
    const CurveInput in = parseCurveInput(ctx.session.doc, ctx.word(0));
    if (in.curve < 0) throw EditError("expected a curve (c0, c1, ...), got '" + ctx.word(0) + "'");
    return uint32_t(in.curve);
}

// The ground plane's axes: e1, then e2 counter-clockwise from it seen from above.
void groundAxes(const EditSession& s, Vec3& e1, Vec3& e2) {
    e1 = Vec3(1, 0, 0);
    e2 = s.camera.zUp ? Vec3(0, 1, 0) : Vec3(0, 0, -1);  // counter-clockwise seen from above
}

void execCurveThrough(CommandContext& ctx) {
    std::vector<std::string> words = ctx.rest(0);
    const bool closed = !words.empty() && words.back() == "closed";
    if (closed) words.pop_back();
    std::vector<Vec3> pts;
    for (const std::string& w : words) pts.push_back(pointWord(w));
    addShape(ctx, "Curve through points", [&] { return curveThrough(pts, closed); });
}

void execCurveControl(CommandContext& ctx) {
    std::vector<Vec3> pts;
    for (const std::string& w : ctx.rest(0)) pts.push_back(pointWord(w));
    addShape(ctx, "Curve from control points", [&] { return curveControl(pts); });
}

void execCurveInsert(CommandContext& ctx) {
    const uint32_t c = curveArg(ctx);
    const double tt = ctx.number(1);
    ctx.session.apply("Insert curve point", [&](Document& d) {
        insertCurvePoint(d, c, tt);
        compactPool(d);
    });
    ctx.session.sel.points.clear();  // the pool was renumbered
}

void execCurveRemove(CommandContext& ctx) {
    const uint32_t c = curveArg(ctx);
    const size_t k = ctx.index(1);
    ctx.session.apply("Remove curve point", [&](Document& d) {
        removeCurvePoint(d, c, k);
        compactPool(d);
    });
    ctx.session.sel.points.clear();  // the pool was renumbered
}

void execAddCircle(CommandContext& ctx) {
    const double r = ctx.number(0);
    Vec3 e1, e2;
    groundAxes(ctx.session, e1, e2);
    addShape(ctx, "Add circle", [&] { return arcCurve(ctx.session.cursor, e1, e2, r, 360.0); });
}

void execAddArc(CommandContext& ctx) {
    const double r = ctx.number(0), deg = ctx.number(1);
    Vec3 e1, e2;
    groundAxes(ctx.session, e1, e2);
    addShape(ctx, "Add arc", [&] { return arcCurve(ctx.session.cursor, e1, e2, r, deg); });
}

void execRevolve(CommandContext& ctx) {
    Construction c;
    c.kind = ConstructionKind::Revolve;
    c.inputs = inputs(ctx, 0, 1);
    Vec3 axis(0.0);
    axis[ctx.index(1)] = 1.0;
    c.vector = arr(axis);
    c.origin = arr(ctx.session.cursor);
    c.degrees = ctx.has(2) ? ctx.number(2) : 360.0;
    if (!(c.degrees > 0.0 && c.degrees <= 360.0)) throw EditError("DEG must be in (0, 360], got " + ctx.word(2));
    construct(ctx, std::move(c), "Revolve " + ctx.word(0));
}

void execLoft(CommandContext& ctx) {
    std::vector<std::string> words = ctx.rest(0);
    Construction c;
    c.kind = ConstructionKind::Loft;
    for (size_t e = 0; e < 2; ++e) {
        const std::string key = e == 0 ? "start=" : "end=";
        const auto it = std::find_if(words.begin(), words.end(), [&](const std::string& w) { return w.rfind(key, 0) == 0; });
        if (it == words.end()) continue;
        const std::string v = it->substr(key.size());
        if (v == "G0" || v == "C0")
            c.ends[e] = Continuity::C0;
        else if (v == "G1")
            c.ends[e] = Continuity::G1;
        else if (v == "G2")
            c.ends[e] = Continuity::G2;
        else
            throw EditError(key + " takes G0, G1 or G2, got '" + v + "'");
        words.erase(it);
    }
    c.closed = !words.empty() && words.back() == "closed";
    if (c.closed) words.pop_back();
    if (c.closed && (c.ends[0] != Continuity::C0 || c.ends[1] != Continuity::C0))
        throw EditError("a closed loft has no ends; start= and end= are for open lofts");
    for (const std::string& w : words) c.inputs.push_back(parseCurveInput(ctx.session.doc, w));
    // α: the G1 end's tangent as long as a third of the way to the next section.
    const Document& d = ctx.session.doc;
    for (size_t e = 0; e < 2 && c.inputs.size() >= 2; ++e) {
        if (c.ends[e] == Continuity::C0) continue;
        const size_t k = e == 0 ? 0 : c.inputs.size() - 1, next = e == 0 ? 1 : k - 1;
        const CurveShape a = inputShape(d, c.inputs[k]), b = inputShape(d, c.inputs[next]);
        const std::vector<HPoint> row = inputTangentRow(d, c.inputs[k]);
        if (row.empty() || a.points.size() != b.points.size()) continue;  // the construction says why
        double gap = 0.0, tangent = 0.0;
        for (size_t j = 0; j < a.points.size(); ++j) {
            gap += glm::length(euclidean(b.points[j]) - euclidean(a.points[j]));
            tangent += glm::length(euclidean(a.points[j]) - euclidean(row[j]));
        }
        if (!(tangent > 0.0)) throw EditError("patch edge " + curveInputName(c.inputs[k]) + " has no tangent row to continue");
        c.endAlpha[e] = std::clamp(gap / 3.0 / tangent, 1e-3, 1e3);
    }
    construct(ctx, std::move(c), "Loft");
}

void execEdgeSurface(CommandContext& ctx) {
    Construction c;
    c.kind = ConstructionKind::EdgeSurface;
    c.inputs = inputs(ctx, 0, ctx.args.size());
    construct(ctx, std::move(c), "Edge surface");
}

void execBlend(CommandContext& ctx) {
    Construction c;
    c.kind = ConstructionKind::Blend;
    c.inputs = inputs(ctx, 0, 2);
    for (const CurveInput& in : c.inputs)
        if (in.curve >= 0) throw EditError("a blend bridges patch edges (P:u0, P:v1 …), not curves");
    const Continuity cont = *parseContinuity(ctx.word(2));  // G1 or G2, as the form checked
    c.ends = {cont, cont};
    for (const CurveInput& in : c.inputs)
        if (findJoin(ctx.session.doc, in.patch, in.edge) >= 0)
            throw EditError("edge " + curveInputName(in) + " is joined already; a blend bridges two open edges");
    // Two edges of one patch that meet at its corner (u0 and v1, say): the bridge between them
    // would fold over that corner (issue 73's random edits made one). An edge and itself likewise.
    const CurveInput &a = c.inputs[0], &b = c.inputs[1];
    const auto across = [](Edge e) { return (static_cast<int>(e) & 1) == 0; };  // u0 and u1 face each other, v0 and v1
    if (a.patch == b.patch && (a.edge == b.edge || across(a.edge) != across(b.edge)))
        throw EditError("edges " + curveInputName(a) + " and " + curveInputName(b) +
                        (a.edge == b.edge ? " are the same edge" : " meet at a corner of their patch") +
                        "; a blend between them would fold over itself. Blend edges of two patches, or opposite edges of one");
    chooseBlendAlphas(ctx.session.doc, c);
    construct(ctx, std::move(c), "Blend");
}

void execSweep1(CommandContext& ctx) {
    Construction c;
    c.kind = ConstructionKind::Sweep1;
    c.inputs = inputs(ctx, 0, 2);
    const Document& d = ctx.session.doc;
    double tol = 0.0;
    if (ctx.has(2)) {
        tol = ctx.number(2);
        if (!(tol > 0.0)) throw EditError("TOL must be positive, got " + ctx.word(2));
    } else {  // 1e-4 of the profile's size about the rail's start
        const CurveShape rail = inputShape(d, c.inputs[0]), profile = inputShape(d, c.inputs[1]);
        double size = 0.0;
        for (const HPoint& h : profile.points) size = std::max(size, glm::length(euclidean(h) - euclidean(rail.points[0])));
        tol = 1e-4 * std::max(size, 1e-12);
    }
    c.split = sweep1Pieces(d, c, tol);
    construct(ctx, std::move(c), "Sweep " + ctx.word(1) + " along " + ctx.word(0));
}

void execSweep2(CommandContext& ctx) {
    Construction c;
    c.kind = ConstructionKind::Sweep2;
    c.inputs = inputs(ctx, 0, 3);
    construct(ctx, std::move(c), "Sweep " + ctx.word(2) + " along " + ctx.word(0) + " and " + ctx.word(1));
}

void execNetwork(CommandContext& ctx) {
    const std::vector<std::string> words = ctx.rest(0);
    const auto slash = std::find(words.begin(), words.end(), "/");
    if (slash == words.end() || std::count(words.begin(), words.end(), "/") != 1)
        throw EditError("usage: network U U ... / V V ... (one / between the U and the V curves)");
    Construction c;
    c.kind = ConstructionKind::Network;
    c.split = uint32_t(slash - words.begin());
    if (c.split < 2 || words.end() - slash - 1 < 2) throw EditError("a network needs at least 2 curves each way");
    for (const std::string& w : words)
        if (w != "/") c.inputs.push_back(parseCurveInput(ctx.session.doc, w));
    construct(ctx, std::move(c), "Network");
}

void execBake(CommandContext& ctx) {
    EditSession& s = ctx.session;
    int k = -1;
    if (!ctx.has(0)) {
        if (s.sel.patch >= 0) k = constructionOfPatch(s.doc, uint32_t(s.sel.patch));
        if (k < 0) throw EditError("select a patch of a surface made from curves, or name it (k0, k1, ...)");
    } else if (const std::string& c = ctx.word(0); !c.empty() && (c[0] == 'c' || c[0] == 'C')) {
        // A live curve (an intersection, a projection) and the trims made from it: fixed from now on.
        const uint32_t ci = commandIndex(c.substr(1), s.doc.curves.size(), "curve");
        s.apply("Bake", [ci](Document& d) {
            d.curves[ci].link.reset();
            auto detach = [ci](std::vector<TrimLoop>& loops) {
                for (TrimLoop& l : loops)
                    if (l.curve == int32_t(ci)) l.curve = -1, l.error.clear();
            };
            for (Patch& p : d.patches) detach(p.trims);
            for (Surface& n : d.surfaces) detach(n.trims);
        });
        ctx.host.status("c" + std::to_string(ci) + " and its trims are fixed now");
        return;
    } else {
        std::string w = ctx.word(0);
        if (!w.empty() && (w[0] == 'k' || w[0] == 'K')) w.erase(0, 1);
        k = int(commandIndex(w, s.doc.constructions.size(), "construction"));
    }
    const std::string label = constructionLabel(s.doc, size_t(k));
    s.apply("Bake", [k](Document& d) { bakeConstruction(d, size_t(k)); });
    ctx.host.status("Baked " + label);
}

}  // namespace

// Called by the `extrude` command's second form with the words C DX DY DZ; its numbers are read from
// the words, so that it does not depend on how that form declares them.
void runCurveExtrude(CommandContext& ctx) {
    Construction c;
    c.kind = ConstructionKind::Extrude;
    c.inputs = inputs(ctx, 0, 1);
    c.vector = {commandNumber(ctx.word(1), "DX"), commandNumber(ctx.word(2), "DY"), commandNumber(ctx.word(3), "DZ")};
    construct(ctx, std::move(c), "Extrude " + ctx.word(0));
}

void addConstructCommands(CommandTable& t) {
    using namespace arg;
    t.add({.name = "curve-through",
           .label = "Curve Through Points",
           .menu = "Add",
           .forms = {{many(shown(word("POINT"), "X,Y,Z X,Y,Z ... [closed]"))}},
           .help = "Add a C2 cubic spline through the points (2 or more; chord-length parameters, natural ends; `closed`: back to "
                   "the first, 3 or more), as Bézier segments you can edit like any control points",
           .exec = execCurveThrough});
    t.add({.name = "curve-control",
           .label = "Curve from Control Points",
           .menu = "Add",
           .forms = {{many(shown(word("POINT"), "X,Y,Z X,Y,Z X,Y,Z X,Y,Z ..."))}},
           .help = "Add the clamped uniform cubic B-spline with these control points (4 or more): it starts at the first, ends at "
                   "the last and follows the others, one Bézier segment per knot span",
           .exec = execCurveControl});
    t.add({.name = "curve-insert",
           .label = "Insert Curve Point",
           .menu = "Add",
           .forms = {{word("C"), number("T")}},
           .help = "Insert an on-curve point into curve C at parameter T (segment floor(T), at its fraction): the segment is "
                   "split in two and the curve keeps its shape exactly",
           .exec = execCurveInsert});
    t.add({.name = "curve-remove",
           .label = "Remove Curve Point",
           .menu = "Add",
           .forms = {{word("C"), count("K")}},
           .help = "Remove on-curve point K of curve C (the end of segment K-1): its two segments become one cubic with their "
                   "ends and end tangents (exactly the segment an insert split)",
           .exec = execCurveRemove});
    t.add({.name = "add-circle",
           .label = "Circle (exact)",
           .menu = "Add",
           .forms = {{number("R")}},
           .help = "Add an exact circle of radius R about the 3D cursor in the ground plane: four rational quarter arcs",
           .exec = execAddCircle});
    t.add({.name = "add-arc",
           .label = "Arc (exact)",
           .menu = "Add",
           .forms = {{number("R"), number("DEG")}},
           .help = "Add an exact arc of radius R about the 3D cursor in the ground plane, from +X counter-clockwise through DEG "
                   "degrees (0 < DEG <= 360): rational arcs of at most 90° each",
           .exec = execAddArc});
    t.add({.name = "revolve",
           .label = "Revolve",
           .menu = "Surface",
           .forms = {{word("C"), axis(), opt(number("DEG"))}},
           .help = "Revolve a curve or patch edge C about the X, Y or Z axis through the 3D cursor by DEG degrees (default 360): exact "
                   "rational patches, closed and joined at 360°, live while C is edited",
           .exec = execRevolve});
    t.add({.name = "loft",
           .label = "Loft",
           .menu = "Surface",
           .forms = {{many(shown(word("C"), "C C ... [closed] [start=G0|G1|G2] [end=G0|G1|G2]"))}},
           .help = "A surface through the sections C (curves or patch edges, 2 or more, each of the same number of segments), "
                   "passing exactly through every one and sharing their points: C2 between them; `closed` goes back to the first; "
                   "start=G1|G2 / end=G1|G2 leave a first or last section that is a patch edge along its patch's tangent (G1), and "
                   "with its curvature too (G2: the end span follows the edge, C1 at the next section); joined so. "
                   "Live while they are edited",
           .exec = execLoft});
    t.add({.name = "edge-surface",
           .label = "Edge Surface",
           .menu = "Surface",
           .forms = {{word("A"), word("B"), opt(word("C")), opt(word("D"))}},
           .help = "A surface from 2, 3 or 4 curves or patch edges (Coons; 2 make a ruled surface), reproducing each exactly and "
                   "sharing its points (an edge's patch is joined to it); 3 or 4 must form a closed loop end to end, opposite sides "
                   "of the same number of segments. Live while they are edited",
           .exec = execEdgeSurface});
    t.add({.name = "blend",
           .label = "Blend Edges",
           .menu = "Surface",
           .forms = {{word("A:EDGE"), word("B:EDGE"), choice("CONTINUITY", {"G1", "G2"})}},
           .help = "Bridge two open patch edges (Rhino's BlendSrf): G1 at both ends with one patch, or G2 with three spans joined "
                   "C2; the blend shares the edges' points, is joined to both patches and is made again whenever either changes, "
                   "so it stays G1 or G2 while you drag them. Bake it to edit its own points",
           .exec = execBlend});
    t.add({.name = "sweep1",
           .label = "Sweep Along One Rail",
           .menu = "Surface",
           .forms = {{word("RAIL"), word("PROFILE"), opt(number("TOL"))}},
           .help = "Carry the profile (a curve or patch edge) along the rail, turning with it (rotation-minimising frames; a closed "
                   "rail's twist taken back evenly): exactly the moved profile at every segment end of the rail, the exact "
                   "translational sweep on a straight rail, and within TOL of the exact sweep in between when made (default 1e-4 of "
                   "the profile's size; the rail's segments are split as often as that takes, up to 16 pieces, and keep that "
                   "count while the rail is edited). Live while either is edited",
           .exec = execSweep1});
    t.add({.name = "sweep2",
           .label = "Sweep Along Two Rails",
           .menu = "Surface",
           .forms = {{word("RAIL"), word("RAIL"), word("PROFILE")}},
           .help = "Carry the profile between two rails (curves or patch edges of the same number of segments), turned and scaled "
                   "so it spans them at every rail point: the surface holds both rails exactly (sharing their points) and is the "
                   "profile moved at every segment end. Live while any of them is edited",
           .exec = execSweep2});
    t.add({.name = "network",
           .label = "Curve Network",
           .menu = "Surface",
           .forms = {{many(shown(word("CURVE"), "U U ... / V V ..."))}},
           .help = "A surface through every curve of a network (Gordon): U curves, a `/`, then V curves, at least 2 each way; each "
                   "U curve has one segment between each two V curves and they meet at segment ends. Every cell becomes one patch; "
                   "the meeting points become one point each, so dragging one moves both curves. Live while they are edited",
           .exec = execNetwork});
    t.add({.name = "bake",
           .label = "Bake",
           .menu = "Surface",
           .forms = {{opt(word("K"))}},
           .help = "Detach a surface made from curves from its inputs (kN or N; default: the one of the selected patch): its patches "
                   "stay and become ordinary patches you can edit point by point; the curves stay too. `bake cN` fixes a live curve "
                   "(an intersection or projection) and the trims made from it",
           .exec = execBake});
}

}  // namespace commands
}  // namespace pw

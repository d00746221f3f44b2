// Modelling commands: add patches, triangles, curves and nets at the 3D cursor; delete, duplicate,
// flip, extrude, split, join and unjoin.
#include <algorithm>
#include <vector>

#include "core/commands/command_table.hpp"
#include "core/model/placement.hpp"
#include "core/ops/fill_hole.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/mirror.hpp"
#include "core/ops/net_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/ops/split_ops.hpp"
#include "core/select/symmetry.hpp"

namespace pw {
inline namespace commands {

namespace {

// The size of a new item: a fifth of the model's size (at least 1), but no larger than the median
// item there (a patch, net or triangle, by its widest side): items added one after another then
// keep one size, where a fifth of the model's size alone grew each new patch and its distance
// ×1.2 (99 of them passed 1e9, issue 73).
double newItemSize(const Document& d) {
    const double fifth = std::max(0.2 * modelSize(d), 1.0);
    std::vector<double> widths;
    auto add = [&](const auto& idx) {
        Bounds b;
        for (uint32_t i : idx)
            if (i < d.points.size()) b.add(d.points[i]);
        if (!b.empty) widths.push_back(std::max({b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z}));
    };
    for (const Patch& p : d.patches) add(p.idx);
    for (const Surface& s : d.surfaces) add(s.idx);
    for (const TrianglePatch& t : d.triangles) add(t.idx);
    if (widths.empty()) return fifth;
    std::nth_element(widths.begin(), widths.begin() + std::ptrdiff_t(widths.size() / 2), widths.end());
    return std::min(fifth, std::max(widths[widths.size() / 2], 1.0));
}

bool hasPatch(const EditSession& s) { return s.sel.patch >= 0 && size_t(s.sel.patch) < s.doc.patches.size(); }

// "2:u1" → patch 2, edge u1.
std::pair<uint32_t, Edge> patchEdge(const std::string& word, const Document& doc) {
    const size_t colon = word.find(':');
    if (colon == std::string::npos) throw EditError("expected PATCH:EDGE such as 0:u1, got '" + word + "'");
    const uint32_t p = commandIndex(word.substr(0, colon), doc.patches.size(), "patch");
    const auto e = parseEdge(word.substr(colon + 1));
    if (!e) throw EditError("expected an edge u0, v0, u1 or v1 in '" + word + "'");
    return {p, *e};
}

// "2:u1" → patch 2, edge u1; "t1:e2" → triangle 1, edge e2 (a join's side).
std::pair<uint32_t, Edge> joinSide(const std::string& word, const Document& doc) {
    if (word.empty() || word[0] != 't') return patchEdge(word, doc);
    const size_t colon = word.find(':');
    if (colon == std::string::npos) throw EditError("expected TRIANGLE:EDGE such as t0:e1, got '" + word + "'");
    const uint32_t t = commandIndex(word.substr(1, colon - 1), doc.triangles.size(), "triangle");
    const auto e = parseJoinEdge(word.substr(colon + 1));
    if (!e || !isTriangleEdge(*e)) throw EditError("expected a triangle edge e0, e1 or e2 in '" + word + "'");
    return {t, *e};
}

// Deletes what the selection names, or else every patch, net, triangle and curve whose points are
// all selected.
void deleteSelection(Document& d, const Selection& sel) {
    if (sel.patch >= 0) return deletePatch(d, uint32_t(sel.patch));
    if (sel.surface >= 0) return deleteNetSurface(d, uint32_t(sel.surface));
    if (sel.triangle >= 0) return deleteTriangle(d, uint32_t(sel.triangle));
    if (sel.curve >= 0) return deleteCurve(d, uint32_t(sel.curve));
    auto covered = [&](const auto& idx) { return std::all_of(idx.begin(), idx.end(), [&](uint32_t p) { return sel.contains(p); }); };
    bool any = false;
    for (size_t i = d.curves.size(); i-- > 0;)
        if (covered(d.curves[i].idx)) deleteCurve(d, uint32_t(i)), any = true;
    for (size_t i = d.triangles.size(); i-- > 0;)
        if (covered(d.triangles[i].idx)) deleteTriangle(d, uint32_t(i)), any = true;
    for (size_t i = d.surfaces.size(); i-- > 0;)
        if (covered(d.surfaces[i].idx)) deleteNetSurface(d, uint32_t(i)), any = true;
    for (size_t i = d.patches.size(); i-- > 0;)
        if (covered(d.patches[i].idx)) deletePatch(d, uint32_t(i)), any = true;
    if (!any) throw EditError("the selection covers no whole patch, net, triangle or curve");
}

// Every exec below sees words the table has checked against the command's forms.

// Adds one item of the model's scale at the 3D cursor (`add(doc, centre, size, zUp)` returns its
// index), beside the model where the cursor is inside it, and selects it as `field`.
void execAddAtCursor(CommandContext& ctx, const char* undoLabel, int Selection::*field,
                     uint32_t (*add)(Document&, const Vec3&, double, bool)) {
    EditSession& s = ctx.session;
    int created = -1;
    s.apply(undoLabel, [&](Document& d) {
        const size_t first = d.points.size();
        created = int(add(d, s.cursor, newItemSize(d), s.camera.zUp));
        moveClearOfExisting(d, first);
    });
    s.sel.clear();
    s.sel.*field = created;
}

// A command that adds one item at the 3D cursor (execAddAtCursor).
Command addAtCursor(const char* name, const char* label, const char* help, const char* undoLabel, int Selection::*field,
                    uint32_t (*add)(Document&, const Vec3&, double, bool)) {
    return {.name = name, .label = label, .menu = "Add", .help = help, .exec = [=](CommandContext& ctx) {
                execAddAtCursor(ctx, undoLabel, field, add);
            }};
}

// Makes one item from an edge of the selected patch (`make(doc, patch, edge)` returns its index;
// the edge is the argument or the highlighted one) and selects it as `field`.
void execFromEdge(CommandContext& ctx, const char* undoLabel, int Selection::*field, uint32_t (*make)(Document&, uint32_t, Edge)) {
    EditSession& s = ctx.session;
    const uint32_t p = uint32_t(s.sel.patch);
    const Edge e = ctx.has(0) ? ctx.edge(0) : s.activeEdge;
    int created = -1;
    s.apply(undoLabel, [&](Document& d) { created = int(make(d, p, e)); });
    s.sel.clear();
    s.sel.*field = created;
}

// A command that makes one item from an edge of the selected patch (execFromEdge).
Command fromEdge(const char* name, const char* label, const char* help, const char* undoLabel, int Selection::*field,
                 uint32_t (*make)(Document&, uint32_t, Edge)) {
    return {.name = name,
            .label = label,
            .menu = "Patch",
            .forms = {{arg::opt(arg::edge())}},
            .help = help,
            .enabled = hasPatch,
            .exec = [=](CommandContext& ctx) { execFromEdge(ctx, undoLabel, field, make); }};
}

void execAddNet(CommandContext& ctx) {
    EditSession& s = ctx.session;
    uint32_t rows = 7, cols = 7;
    if (ctx.has(1)) rows = ctx.index(0), cols = ctx.index(1);
    static constexpr NetShape kShapes[] = {NetShape::Flat, NetShape::Tube, NetShape::Torus};
    const NetShape shape = ctx.has(2) ? kShapes[ctx.index(2)] : NetShape::Flat;
    const Basis basis = ctx.has(3) ? *parseBasis(ctx.word(3)) : Basis::BSpline;
    int created = -1;
    s.apply("Add net", [&](Document& d) {
        const size_t first = d.points.size();
        created = int(addNetSurface(d, rows, cols, shape, basis, s.cursor, newItemSize(d), s.camera.zUp));
        moveClearOfExisting(d, first);
    });
    s.sel.clear();
    s.sel.surface = created;
}

void execDelete(CommandContext& ctx) {
    const Selection sel = ctx.session.sel;
    ctx.session.apply("Delete", [&](Document& d) { deleteSelection(d, sel); });
    ctx.session.sel.clear();
}

void execDuplicate(CommandContext& ctx) {
    EditSession& s = ctx.session;
    const Vec3 off(0.1 * modelSize(s.doc), 0.0, 0.0);
    if (s.sel.triangle >= 0) {
        const uint32_t tri = uint32_t(s.sel.triangle);
        int created = -1;
        s.apply("Duplicate triangle", [&](Document& d) { created = int(duplicateTriangle(d, tri, off)); });
        s.sel.clear();
        s.sel.triangle = created;
    } else {
        const uint32_t p = uint32_t(s.sel.patch);
        int created = -1;
        s.apply("Duplicate patch", [&](Document& d) { created = int(duplicatePatch(d, p, off)); });
        s.sel.clear();
        s.sel.patch = created;
    }
}

void execMirror(CommandContext& ctx) {
    const int axis = int(ctx.index(0));
    EditSession& s = ctx.session;
    const std::vector<uint32_t> selected = s.selectedPoints();
    MirrorResult made;
    s.apply(
        "Mirror " + std::string(1, char('X' + axis)), [&](Document& d) { made = mirrorItems(d, selected, axis, s.cursor[axis]); }, true,
        Brought::DetectedJoins);
    s.sel.clear();
    s.sel.points = made.points;
    if (made.patches.size() == 1) s.sel.patch = int(made.patches[0]);
}

// Every visible patch whose 16 points are all selected (the selected patch among them): a whole
// revolve that came out inside out is turned in one step, as mirror takes whole patches.
void execFlip(CommandContext& ctx) {
    EditSession& s = ctx.session;
    const std::vector<uint32_t> patches = wholeItems(s.doc.patches, s.selectedPoints());
    if (patches.empty()) throw EditError("flip: select a patch, or whole patches (all their points)");
    const std::string label = patches.size() == 1 ? "Flip patch" : "Flip " + std::to_string(patches.size()) + " patches";
    s.apply(label, [&](Document& d) { flipPatches(d, patches); });
}

// Form 0: an edge of the selected patch continued by a C1 patch; form 1 (C DX DY DZ): a curve
// extruded, live (runCurveExtrude).
void execExtrude(CommandContext& ctx) {
    if (ctx.form == 1) return runCurveExtrude(ctx);
    if (!hasPatch(ctx.session)) throw EditError("select a patch to extrude its edge, or give a curve and an offset (C DX DY DZ)");
    execFromEdge(ctx, "Extrude edge", &Selection::patch, extrudeEdge);
}

// `split` and `split-ring`: patch p cut along u (or v) at t with its whole ring.
void splitAlong(CommandContext& ctx, uint32_t p, bool u, double t) {
    if (!(t > 0.0 && t < 1.0)) throw EditError("T must lie strictly between 0 and 1");
    size_t cut = 0, joins = 0;
    ctx.session.apply("Split patch", [&](Document& d) {
        cut = splitRing(d, p, u, t).size();
        joins = d.joins.size();
    });
    ctx.host.status("split " + std::to_string(cut) + (cut == 1 ? " patch" : " patches (the ring through its joins)") + "; " +
                    std::to_string(joins) + " joins");
}

void execSplit(CommandContext& ctx) {
    splitAlong(ctx, uint32_t(ctx.session.sel.patch), ctx.index(0) == 0, ctx.has(1) ? ctx.number(1) : 0.5);
}

void execSplitRing(CommandContext& ctx) { splitAlong(ctx, ctx.index(0), ctx.index(1) == 0, ctx.number(2)); }

void execJoin(CommandContext& ctx) {
    const Document& doc = ctx.session.doc;
    const std::pair<uint32_t, Edge> a = joinSide(ctx.word(0), doc), b = joinSide(ctx.word(1), doc);
    const Continuity c = *parseContinuity(ctx.word(2));
    const int ja = findJoin(doc, a.first, a.second);
    const bool change = ja >= 0 && ja == findJoin(doc, b.first, b.second);
    // Under live symmetry the mirror images of the two edges are joined too.
    const bool quads = !isTriangleEdge(a.second) && !isTriangleEdge(b.second);
    const auto ma = quads ? mirrorEdge(doc, a.first, a.second, ctx.session.symmetry) : std::nullopt;
    const auto mb = quads ? mirrorEdge(doc, b.first, b.second, ctx.session.symmetry) : std::nullopt;
    const bool mirrored = ma && mb && *ma != a && *ma != b && *mb != a && *mb != b;
    std::string corner, mirrorCorner;
    ctx.session.apply(change ? "Join continuity" : "Join edges", [&](Document& d) {
        joinEdges(d, a.first, a.second, b.first, b.second, c, &corner);
        if (mirrored) joinEdges(d, ma->first, ma->second, mb->first, mb->second, c, &mirrorCorner);
    });
    if (!corner.empty()) ctx.host.status(corner + (mirrorCorner.empty() ? "" : "; and by symmetry " + mirrorCorner));
    if (mirrored && corner.empty())
        ctx.host.status("joined " + ctx.word(0) + " " + ctx.word(1) + " and, by symmetry, " + std::to_string(ma->first) + ":" +
                        std::string(edgeName(ma->second)) + " " + std::to_string(mb->first) + ":" + std::string(edgeName(mb->second)));
}

void execFillHole(CommandContext& ctx) {
    std::vector<std::string> args = ctx.rest(0);
    const bool triangle = !args.empty() && args.back() == "triangle";
    if (triangle) args.pop_back();
    if (args.size() < 3 || args.size() > 6) throw EditError("fill-hole needs 3 to 6 sides, got " + std::to_string(args.size()));
    std::vector<HoleSide> sides;
    for (const std::string& arg : args) {
        if (!arg.empty() && (arg[0] == 'c' || arg[0] == 'C')) {
            sides.push_back(HoleSide{{}, int32_t(commandIndex(arg.substr(1), ctx.session.doc.curves.size(), "curve"))});
            continue;
        }
        HoleSide side;
        const size_t plus = arg.find('+');
        side.edges.push_back(patchEdge(arg.substr(0, plus), ctx.session.doc));
        if (plus != std::string::npos) side.edges.push_back(patchEdge(arg.substr(plus + 1), ctx.session.doc));
        sides.push_back(std::move(side));
    }
    std::string note;
    ctx.session.apply("Fill hole", [&](Document& d) { note = triangle ? fillHoleWithTriangle(d, sides) : fillHole(d, sides); });
    ctx.host.status(note);
}

void execTolerances(CommandContext& ctx) {
    const double v[3] = {ctx.number(0), ctx.number(1), ctx.number(2)};
    for (size_t i = 0; i < 3; ++i)
        if (!(v[i] > 0.0) || v[i] > 1e9) throw EditError("a tolerance must be a positive number, got " + ctx.word(i));
    ctx.session.apply(
        "Continuity tolerances",
        [&](Document& d) {
            d.tolerances = ContinuityTolerances{v[0], v[1], v[2]};
        },
        false);
}

void execUnjoin(CommandContext& ctx) {
    EditSession& s = ctx.session;
    if (!ctx.has(0) && !hasPatch(s)) throw EditError("select a patch or name its edge (A:EDGE)");
    const auto [p, e] = ctx.has(0) ? joinSide(ctx.word(0), s.doc) : std::pair{uint32_t(s.sel.patch), s.activeEdge};
    const int j = findJoin(s.doc, p, e);
    if (j < 0)
        throw EditError("edge " + std::string(edgeName(e)) + " of " + (isTriangleEdge(e) ? "triangle " : "patch ") + std::to_string(p) +
                        " is not joined");
    s.apply("Unjoin", [j](Document& d) { unjoin(d, size_t(j)); });
}

}  // namespace

void addModelCommands(CommandTable& t) {
    using namespace arg;
    t.add(addAtCursor("add-patch", "Flat Patch", "Add a flat 1x1 Bézier patch at the 3D cursor", "Add patch", &Selection::patch,
                      addFlatPatch));
    t.add(addAtCursor("add-triangle", "Bézier Triangle", "Add a flat cubic Bézier triangle (10 points) at the 3D cursor", "Add triangle",
                      &Selection::triangle, addTriangle));
    t.add(addAtCursor("add-curve", "Bézier Curve",
                      "Add a cubic Bézier curve (4 points) at the 3D cursor, drawn through the isoline tessellator", "Add curve",
                      &Selection::curve, addCurve));
    t.add({.name = "add-net",
           .label = "Net Surface",
           .menu = "Add",
           .forms = {{},
                     {count("ROWS"), count("COLS"), opt(choice("SHAPE", {"flat", "tube", "torus"})),
                      opt(choice("BASIS", {"bezier", "bspline", "catmull-rom"}))}},
           .help = "Add a control net (default 7x7 flat B-spline) at the 3D cursor",
           .exec = execAddNet});
    t.add({.name = "delete",
           .label = "Delete",
           .menu = "Edit",
           .help = "Delete the selected patch, net, triangle or curve (or everything the selected points cover)",
           .bindings = {{"", "", {"Delete"}}},
           .enabled = [](const EditSession& s) { return !s.sel.empty(); },
           .exec = execDelete});
    t.add({.name = "duplicate",
           .label = "Duplicate",
           .menu = "Edit",
           .help = "Copy the selected patch or Bézier triangle with its own points",
           .bindings = {{"", "", {"Shift+D"}}},
           .enabled = [](const EditSession& s) { return hasPatch(s) || s.sel.triangle >= 0; },
           .exec = execDuplicate});
    t.add({.name = "mirror",
           .label = "Mirror",
           .menu = "Edit",
           .forms = {{axis()}},
           .help = "Copy the selected patches, triangles and curves reflected across the plane through the 3D cursor normal to X, Y or Z, "
                   "joined where they meet the plane (C1 where the rows there are perpendicular to it)",
           .bindings = {{"Mirror X", "X", {}}, {"Mirror Y", "Y", {}}, {"Mirror Z", "Z", {}}},
           .exec = execMirror});
    t.add({.name = "flip",
           .label = "Flip",
           .menu = "Patch",
           .help = "Reverse the u direction of the selected patch, or of every patch whose points are all selected, so their normals "
                   "point the other way",
           .enabled = [](const EditSession& s) { return hasPatch(s) || !s.sel.points.empty(); },
           .exec = execFlip});
    // Two forms: an edge of the selected patch continued by a C1 patch, or a curve extruded (live).
    Command extrude = fromEdge("extrude", "Extrude Edge",
                               "Add a C1 patch continuing an edge of the selected patch (default: the highlighted edge); with a curve or "
                               "patch edge C and an offset, the surface C sweeps along it (live while C is edited)",
                               "Extrude edge", &Selection::patch, extrudeEdge);
    extrude.forms = {{opt(edge())}, {word("C"), number("DX"), number("DY"), number("DZ")}};
    extrude.enabled = nullptr;
    extrude.exec = execExtrude;
    t.add(std::move(extrude));
    t.add({.name = "split",
           .label = "Split",
           .menu = "Patch",
           .forms = {{choice("DIR", {"u", "v"}), opt(number("T"))}},
           .help = "Exact de Casteljau split of the selected patch along u or v at T (default 0.5); the cut runs on through every "
                   "joined edge it crosses (the whole ring, as `split-ring`), so no join is dropped",
           .bindings = {{"Split at u", "u", {}}, {"Split at v", "v", {}}},
           .enabled = hasPatch,
           .exec = execSplit});
    t.add({.name = "split-ring",
           .label = "Split Ring",
           .menu = "Patch",
           .forms = {{patch("P"), choice("DIR", {"u", "v"}), number("T")}},
           .help = "Split patch P along u or v at T and every patch joined across the cut line, ring after ring (Blender's loop "
                   "cut): each join the cut crosses becomes two, so every join is kept",
           .exec = execSplitRing});
    t.add({.name = "join",
           .label = "Join",
           .menu = "Patch",
           .forms = {{word("A:EDGE"), word("B:EDGE"), choice("CONTINUITY", {"C0", "C1", "G1", "C2", "G2"})}},
           .help =
               "Join an edge of patch A to an edge of patch B (edges u0 v0 u1 v1) with C0, C1, G1, C2 or G2 continuity, held while you "
               "drag; B is turned to lie beyond the seam with agreeing normals, and when the edges do not meet A stays and B's boundary, "
               "tangent (and for C2/G2 third) rows move onto it (Match). G1 and G2 keep the shape parameters measured when joining; "
               "on two edges joined already it changes the join's continuity in place (the side that joined first stays). A join that "
               "cannot hold "
               "together with the others, or only by folding a patch, is refused, naming them, and the document stays as it was. A "
               "side tN:e0|e1|e2 is an edge of Bézier triangle N, joined C0 or G1 to a patch's edge or another triangle's",
           .exec = execJoin});
    t.add({.name = "fill-hole",
           .label = "Fill Hole",
           .menu = "Surface",
           // At least three words; the sides (3 to 6) are counted once a trailing `triangle` is taken off.
           .forms = {{word("SIDE"), word("SIDE"), shown(many(word("SIDE")), "SIDE [SIDE …] [triangle]")}},
           .help = "Fill a hole bounded by 3 to 6 sides, each an open patch edge (P:u0 …), two edges end to end (P:u0+Q:v1) or a "
                   "curve of one segment (cN), in order round the hole: one patch per hole corner, meeting at a centre, G1 to every "
                   "surrounding patch and to each other, held live like any join. A side of one edge is split at its middle first "
                   "(through its ring; no join is dropped), a curve too (the fill shares its points: move them and the fill's edge "
                   "follows). Where a side's two ends ask different tangent ratios, its joins are fitted: held within 0.1°. With "
                   "`triangle`, three sides of one cubic each "
                   "(edges or curves) are filled by one Bézier triangle instead, G1 to every side that is a patch edge",
           .exec = execFillHole});
    t.add({.name = "tolerances",
           .label = "Continuity Tolerances",
           .menu = "Patch",
           .forms = {{number("POSITION"), number("ANGLE_DEG"), number("CURVATURE_PCT")}},
           .help = "What the continuity readout checks every join against (Rhino's three): the gap between the sides in model units, "
                   "the largest angle between their normals in degrees and the curvature deviation across the seam in percent; "
                   "joins out of tolerance show in the Continuity panel, in the viewport (Boundaries) and in `info`",
           .exec = execTolerances});
    t.add(windowToggle("join-pick", "Join by Picking", "Patch", WindowToggle::JoinTool, {"J"},
                       "Hover an open edge and click it, then click the edge to join it to; the join shows at once (C1) "
                       "and the panel changes its continuity, keeps it (Enter) or takes it back (Esc). It runs `join`"));
    t.add(windowToggle("draw-curve", "Draw Curve", "Add", WindowToggle::CurveTool, {"C"},
                       "Click points on the plane through the 3D cursor (facing the view, or XY, XZ, YZ), snapping to points, "
                       "edges and the grid; the curve through them shows as you go and Enter makes it (`curve-through`, or "
                       "`curve-control` with Control points); Backspace takes the last point back, Esc cancels"));
    t.add({.name = "unjoin",
           .label = "Unjoin Edge",
           .menu = "Patch",
           .forms = {{opt(word("A:EDGE"))}},
           .help = "Remove the join on an edge (default: the selected patch's highlighted edge; tN:e1 for a triangle's edge); the "
                   "patches can then move apart",
           .exec = execUnjoin});
    t.add(fromEdge("curve-from-edge", "Curve from Edge",
                   "A curve on an edge of the selected patch that shares its points (default: the highlighted edge)", "Curve from edge",
                   &Selection::curve, curveFromEdge));
}

}  // namespace commands
}  // namespace pw

// Selection and transform commands: select, move, rotate, scale, cursor.
#include <algorithm>
#include <charconv>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/constructions.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/edit/live_constructions.hpp"
#include "core/solve/constraint_solver.hpp"

#include "core/select/picking.hpp"
#include "core/select/selection_ops.hpp"
#include "core/select/slide.hpp"
#include "core/select/soft_selection.hpp"
#include "core/select/symmetry.hpp"

namespace pw {

namespace {

// "3" or "0,2,5" → indices below `count`.
std::vector<uint32_t> indexList(const std::string& word, size_t count, const char* what) {
    std::vector<uint32_t> out;
    size_t start = 0;
    while (start <= word.size()) {
        const size_t comma = std::min(word.find(',', start), word.size());
        out.push_back(commandIndex(word.substr(start, comma - start), count, what));
        start = comma + 1;
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// Selects the points of items `list` of `items`; with one item, that item as `field` too.
template <class Item>
void selectItems(Selection& sel, const std::vector<Item>& items, const std::string& list, const char* what, int Selection::*field) {
    const std::vector<uint32_t> ids = indexList(list, items.size(), what);
    for (uint32_t i : ids) sel.points.insert(sel.points.end(), items[i].idx.begin(), items[i].idx.end());
    if (ids.size() == 1) sel.*field = int(ids[0]);
}

void select(CommandContext& ctx) {
    expectArgs(ctx, 1, 2);
    const std::string& what = ctx.args[0];
    const Document& doc = ctx.session.doc;
    Selection& sel = ctx.session.sel;
    if (what == "all" || what == "none") {
        expectArgs(ctx, 1, 1);
        sel.clear();
        if (what == "all") {
            const std::vector<bool> shown = visiblePointMask(doc);
            for (size_t i = 0; i < shown.size(); ++i)
                if (shown[i]) sel.points.push_back(uint32_t(i));
        }
        return;
    }
    if (what == "linked" || what == "invert") {
        expectArgs(ctx, 1, 1);
        const std::vector<uint32_t> from = ctx.session.selectedPoints();
        if (what == "linked" && from.empty()) throw EditError("nothing is selected: select a point or an item to extend");
        std::vector<uint32_t> pts = what == "linked" ? linkedPoints(doc, from) : invertedPoints(doc, from);
        sel.clear();
        sel.points = std::move(pts);
        return;
    }
    expectArgs(ctx, 2, 2);
    const std::string& list = ctx.args[1];
    sel.clear();
    if (what == "point") {
        sel.points = indexList(list, doc.points.size(), "point");
    } else if (what == "patch") {
        selectItems(sel, doc.patches, list, "patch", &Selection::patch);
    } else if (what == "net") {
        selectItems(sel, doc.surfaces, list, "net", &Selection::surface);
    } else if (what == "triangle") {
        selectItems(sel, doc.triangles, list, "triangle", &Selection::triangle);
    } else if (what == "curve") {
        selectItems(sel, doc.curves, list, "curve", &Selection::curve);
    } else {
        throw EditError("expected all, none, linked, invert, point, patch, net, triangle or curve, got '" + what + "'");
    }
    std::sort(sel.points.begin(), sel.points.end());
    sel.points.erase(std::unique(sel.points.begin(), sel.points.end()), sel.points.end());
}

// Moves the selection's points by `f`; the joins are held by the solver with the moved points fixed
// (a whole joined group moved rigidly needs no correction and gets none).
// Moves the selection point by point: f(index, position) is where each point goes.
void transformSelection(CommandContext& ctx, const std::string& label, const std::function<Vec3(uint32_t, const Vec3&)>& f) {
    const std::vector<uint32_t> moved = ctx.session.selectedPoints();
    if (moved.empty()) throw EditError("nothing is selected (select points, a patch, a net, a triangle or a curve first)");
    if (const std::string why = constructedPointsRefusal(ctx.session.doc, moved); !why.empty()) throw EditError(why);
    const Symmetry sym = ctx.session.symmetry;
    size_t around = 0, reached = 0;
    ctx.session.apply(
        label,
        [&](Document& d) {
            // Soft selection: the points around take their share (the solver may still move them,
            // and holds the joins around them too); under symmetry their partners follow as well.
            const TransformSetup t = setUpTransform(d, moved, ctx.session.soft, sym);
            const SoftWeights& soft = t.soft;
            const std::vector<uint32_t>& driven = t.driven;
            around = soft.points.size();
            for (size_t k = 0; k < soft.points.size(); ++k) {
                const uint32_t p = soft.points[k];
                if (!std::binary_search(driven.begin(), driven.end(), p))
                    d.points[p] = glm::mix(d.points[p], f(p, d.points[p]), soft.weights[k]);
            }
            for (uint32_t p : moved) d.points[p] = f(p, d.points[p]);
            applySymmetry(d.points, t.pairs, sym);
            if (!d.constructions.empty()) rerunConstructions(d);  // surfaces made from moved curves follow
            if (const Projection p = t.solver->project(d.points); !p.ok())
                throw EditError("the joins cannot follow: " + conflictMessage(p));
            const Document& was = ctx.session.doc;
            for (size_t i = 0; i < d.points.size() && i < was.points.size(); ++i) reached += d.points[i] != was.points[i] ? 1 : 0;
        },
        false);
    // How far the edit reached: the selection, its soft share and what the joins forced.
    std::string what = label + ": " + std::to_string(reached) + (reached == 1 ? " point moved" : " points moved") + " (" +
                       std::to_string(moved.size()) + " selected";
    if (around > 0) what += ", " + std::to_string(around) + " within the " + softDescription(ctx.session.soft);
    ctx.host.status(what + ")");
}

// The same transform for every point (move, rotate, scale).
void transformSelection(CommandContext& ctx, const std::string& label, const std::function<Vec3(const Vec3&)>& f) {
    transformSelection(ctx, label, [&f](uint32_t, const Vec3& p) { return f(p); });
}

}  // namespace

void addSelectCommands(CommandTable& t) {
    t.add({.name = "select",
           .label = "Select",
           .menu = "Select",
           .usage = "all|none|linked|invert|point N[,N...]|patch N[,N...]|net N|triangle N|curve N",
           .help = "Select control points, or whole patches, nets, triangles or curves by number; linked: everything connected to the "
                   "selection; invert",
           .bindings = {{"Select All", "all", {"A"}},
                        {"Select None", "none", {"Alt+A"}},
                        {"Select Linked", "linked", {"L", "Ctrl+L"}},
                        {"Invert Selection", "invert", {"Ctrl+I"}}},
           .run = select});
    t.add({.name = "move",
           .label = "Move",
           .usage = "DX DY DZ",
           .help = "Move the selection by a vector; joins are held",
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 3, 3);
               const Vec3 d(commandNumber(ctx.args[0], "DX"), commandNumber(ctx.args[1], "DY"), commandNumber(ctx.args[2], "DZ"));
               transformSelection(ctx, "Move", [d](const Vec3& p) { return p + d; });
           }});
    t.add({.name = "slide",
           .label = "Slide",
           .usage = "u|v|n DIST",
           .help = "Slide each selected point along its own control polygon in u or v, or along the surface normal there (n), by "
                   "DIST (Rhino's UVN move); soft selection slides the points around it along theirs, and joins are held",
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 2, 2);
               const auto axis = parseSlideAxis(ctx.args[0]);
               if (!axis) throw EditError("expected u, v or n, got '" + ctx.args[0] + "'");
               const double dist = commandNumber(ctx.args[1], "DIST");
               // Directions from the shape before the slide, so that every point moves by DIST.
               const Document& doc = ctx.session.doc;
               for (uint32_t p : ctx.session.selectedPoints()) {
                   const auto d = slideDirection(doc, p, *axis);
                   if (!d)
                       throw EditError("point " + std::to_string(p) +
                                       " has no control polygon to slide along (a point of a patch or net slides)");
               }
               auto dirOf = [&doc, axis = *axis](uint32_t p) { return slideDirection(doc, p, axis).value_or(Vec3(0.0)); };
               std::vector<Vec3> cache(doc.points.size(), Vec3(std::nan("")));
               transformSelection(ctx, "Slide", [&](uint32_t p, const Vec3& at) {
                   if (std::isnan(cache[p].x)) cache[p] = dirOf(p);
                   return at + dist * cache[p];
               });
           }});
    t.add({.name = "rotate",
           .label = "Rotate",
           .usage = "X|Y|Z DEG",
           .help = "Rotate the selection about an axis through the pivot (median, active or 3D cursor); joins are held",
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 2, 2);
               Vec3 axis(0.0);
               axis[axisIndex(ctx.args[0])] = 1.0;
               const double rad = glm::radians(commandNumber(ctx.args[1], "DEG"));
               const Vec3 c = ctx.session.transformPivot();
               const glm::dmat4 m = glm::rotate(glm::dmat4(1.0), rad, axis);
               transformSelection(ctx, "Rotate", [&](const Vec3& p) { return c + Vec3(m * glm::dvec4(p - c, 0.0)); });
           }});
    t.add({.name = "scale",
           .label = "Scale",
           .usage = "S | SX SY SZ",
           .help = "Scale the selection about the pivot (median, active or 3D cursor); joins are held",
           .run = [](CommandContext& ctx) {
               if (ctx.args.size() != 1) expectArgs(ctx, 3, 3);
               Vec3 s(commandNumber(ctx.args[0], "S"));
               if (ctx.args.size() == 3)
                   s = Vec3(commandNumber(ctx.args[0], "SX"), commandNumber(ctx.args[1], "SY"), commandNumber(ctx.args[2], "SZ"));
               const Vec3 c = ctx.session.transformPivot();
               transformSelection(ctx, "Scale", [&](const Vec3& p) { return c + s * (p - c); });
           }});
    t.add({.name = "hide",
           .label = "Hide",
           .menu = "Select",
           .usage = "[unselected]",
           .help = "Hide the selected items (or every item the selection does not touch); hidden items are not drawn or picked",
           .bindings = {{"Hide Selected", "", {"H"}}, {"Hide Unselected", "unselected", {"Shift+H"}}},
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 0, 1);
               if (ctx.args.size() == 1 && ctx.args[0] != "unselected")
                   throw EditError("expected 'unselected' or nothing, got '" + ctx.args[0] + "'");
               const bool unselected = ctx.args.size() == 1;
               const std::vector<uint32_t> pts = ctx.session.selectedPoints();
               if (pts.empty()) throw EditError("nothing is selected (select what to hide, or what to keep for 'hide unselected')");
               const Selection sel = ctx.session.sel;
               ctx.session.apply(unselected ? "Hide unselected" : "Hide", [&](Document& d) {
                   if (hideItems(d, sel, pts, unselected) == 0) throw EditError("the selection covers no whole item to hide");
               });
               if (!unselected) ctx.session.sel.clear();
           }});
    t.add({.name = "unhide",
           .label = "Reveal Hidden",
           .menu = "Select",
           .help = "Show every hidden item again and select it",
           .bindings = {{"", "", {"Alt+H"}}},
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 0, 0);
               std::vector<uint32_t> revealed;
               ctx.session.apply("Reveal hidden", [&](Document& d) { revealed = revealItems(d); });
               ctx.session.sel.clear();
               ctx.session.sel.points = std::move(revealed);
           }});
    t.add({.name = "pivot",
           .label = "Pivot",
           .menu = "Select",
           .usage = "median|active|cursor",
           .help = "What rotate and scale turn about: the median of the selection, the active point or item, or the 3D cursor",
           .bindings = {{"Pivot: Median", "median", {}}, {"Pivot: Active", "active", {}}, {"Pivot: 3D Cursor", "cursor", {}}},
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 1, 1);
               const auto m = parsePivot(ctx.args[0]);
               if (!m) throw EditError("expected median, active or cursor, got '" + ctx.args[0] + "'");
               ctx.session.pivot = *m;
           }});
    t.add({.name = "symmetry",
           .label = "Symmetry",
           .menu = "Select",
           .usage = "X|Y|Z|off",
           .help = "Live symmetry: every transform moves each point's mirror partner across the plane normal to the axis through "
                   "the 3D cursor, and points on that plane stay on it",
           .bindings = {{"Symmetry: Off", "off", {}}, {"Symmetry: X", "X", {}}, {"Symmetry: Y", "Y", {}}, {"Symmetry: Z", "Z", {}}},
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 1, 1);
               if (ctx.args[0] == "off") {
                   ctx.session.symmetry = {};
                   return;
               }
               const int a = axisIndex(ctx.args[0]);
               ctx.session.symmetry = Symmetry{a, ctx.session.cursor[a]};
           }});
    t.add({.name = "soft",
           .label = "Soft Selection",
           .menu = "Select",
           .usage = "on|off|toggle|RADIUS [smooth|linear|sharp|constant]",
           .help = "Soft selection (Blender's proportional editing): transforms also carry the points within RADIUS of the moved ones, "
                   "measured along the control nets and across joins, by the falloff; the joins are held as always. The wheel "
                   "changes the radius while moving",
           .bindings = {{"Soft Selection", "toggle", {"O"}}},
           .checked = [](const EditSession& s, const CommandHost&) { return s.soft.on; },
           .run =
               [](CommandContext& ctx) {
                   expectArgs(ctx, 1, 2);
                   SoftSelection& soft = ctx.session.soft;
                   const std::string& w = ctx.args[0];
                   SoftSelection next = soft;
                   if (w == "on" || w == "off" || w == "toggle") {
                       next.on = w == "on" || (w == "toggle" && !soft.on);
                   } else {
                       next.radius = commandNumber(w, "RADIUS");
                       if (!(next.radius > 0.0) || next.radius > 1e9) throw EditError("the radius must be a positive number, got " + w);
                       next.on = true;
                   }
                   if (ctx.args.size() == 2) {
                       const auto f = parseFalloff(ctx.args[1]);
                       if (!f) throw EditError("expected smooth, linear, sharp or constant, got '" + ctx.args[1] + "'");
                       next.falloff = *f;
                   }
                   soft = next;
                   ctx.host.status(softDescription(soft));
               }});
    t.add({.name = "snap",
           .label = "Snap To",
           .menu = "Select",
           .usage = "grid|points|edges|surfaces",
           .help = "What a move snaps to while Ctrl is held: grid increments, control points, boundary edges or surfaces",
           .bindings = {{"Snap: Grid", "grid", {}},
                        {"Snap: Points", "points", {}},
                        {"Snap: Edges", "edges", {}},
                        {"Snap: Surfaces", "surfaces", {}}},
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 1, 1);
               const auto m = parseSnapTarget(ctx.args[0]);
               if (!m) throw EditError("expected grid, points, edges or surfaces, got '" + ctx.args[0] + "'");
               ctx.session.snap = *m;
           }});
    t.add({.name = "cursor",
           .label = "Place 3D Cursor",
           .usage = "X Y Z",
           .help = "Place the 3D cursor, where new patches, triangles, curves and nets appear",
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 3, 3);
               ctx.session.cursor = Vec3(commandNumber(ctx.args[0], "X"), commandNumber(ctx.args[1], "Y"), commandNumber(ctx.args[2], "Z"));
           }});
}

}  // namespace pw

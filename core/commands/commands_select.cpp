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
inline namespace commands {

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

void execSelect(CommandContext& ctx) {
    const std::string& what = ctx.args[0];
    const Document& doc = ctx.session.doc;
    Selection& sel = ctx.session.sel;
    if (what == "all" || what == "none") {
        sel.clear();
        if (what == "all") {
            const std::vector<bool> shown = visiblePointMask(doc);
            for (size_t i = 0; i < shown.size(); ++i)
                if (shown[i]) sel.points.push_back(uint32_t(i));
        }
        return;
    }
    if (what == "linked" || what == "invert") {
        const std::vector<uint32_t> from = ctx.session.selectedPoints();
        if (what == "linked" && from.empty()) throw EditError("nothing is selected: select a point or an item to extend");
        std::vector<uint32_t> pts = what == "linked" ? linkedPoints(doc, from) : invertedPoints(doc, from);
        sel.clear();
        sel.points = std::move(pts);
        return;
    }
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

// Every run below sees words the table has checked against the command's forms.

void execMove(CommandContext& ctx) {
    const Vec3 d(ctx.number(0), ctx.number(1), ctx.number(2));
    transformSelection(ctx, "Move", [d](const Vec3& p) { return p + d; });
}

void execSlide(CommandContext& ctx) {
    const SlideAxis axis = *parseSlideAxis(ctx.word(0));
    const double dist = ctx.number(1);
    // Directions from the shape before the slide, so that every point moves by DIST.
    const Document& doc = ctx.session.doc;
    for (uint32_t p : ctx.session.selectedPoints())
        if (!slideDirection(doc, p, axis)) throw EditError(slideRefusal(p));
    std::vector<Vec3> cache(doc.points.size(), Vec3(std::nan("")));
    transformSelection(ctx, "Slide", [&](uint32_t p, const Vec3& at) {
        if (std::isnan(cache[p].x)) cache[p] = slideDirection(doc, p, axis).value_or(Vec3(0.0));
        return at + dist * cache[p];
    });
}

void execRotate(CommandContext& ctx) {
    Vec3 axis(0.0);
    axis[ctx.index(0)] = 1.0;
    const double rad = glm::radians(ctx.number(1));
    const Vec3 c = ctx.session.transformPivot();
    const glm::dmat4 m = glm::rotate(glm::dmat4(1.0), rad, axis);
    transformSelection(ctx, "Rotate", [&](const Vec3& p) { return c + Vec3(m * glm::dvec4(p - c, 0.0)); });
}

void execScale(CommandContext& ctx) {
    const Vec3 s = ctx.form == 0 ? Vec3(ctx.number(0)) : Vec3(ctx.number(0), ctx.number(1), ctx.number(2));
    const Vec3 c = ctx.session.transformPivot();
    transformSelection(ctx, "Scale", [&](const Vec3& p) { return c + s * (p - c); });
}

void execHide(CommandContext& ctx) {
    const bool unselected = ctx.has(0);
    const std::vector<uint32_t> pts = ctx.session.selectedPoints();
    if (pts.empty()) throw EditError("nothing is selected (select what to hide, or what to keep for 'hide unselected')");
    const Selection sel = ctx.session.sel;
    ctx.session.apply(unselected ? "Hide unselected" : "Hide", [&](Document& d) {
        if (hideItems(d, sel, pts, unselected) == 0) throw EditError("the selection covers no whole item to hide");
    });
    if (!unselected) ctx.session.sel.clear();
}

void execUnhide(CommandContext& ctx) {
    std::vector<uint32_t> revealed;
    ctx.session.apply("Reveal hidden", [&](Document& d) { revealed = revealItems(d); });
    ctx.session.sel.clear();
    ctx.session.sel.points = std::move(revealed);
}

void execPivot(CommandContext& ctx) { ctx.session.pivot = *parsePivot(ctx.word(0)); }

void execSymmetry(CommandContext& ctx) {
    if (ctx.form == 0) {
        ctx.session.symmetry = {};
        return;
    }
    const int a = int(ctx.index(0));
    ctx.session.symmetry = Symmetry{a, ctx.session.cursor[a]};
}

void execSoft(CommandContext& ctx) {
    SoftSelection& soft = ctx.session.soft;
    SoftSelection next = soft;
    if (ctx.form == 0) {
        const std::string& w = ctx.word(0);
        next.on = w == "on" || (w == "toggle" && !soft.on);
    } else {
        next.radius = ctx.number(0);
        if (!(next.radius > 0.0)) throw EditError("the radius must be a positive number, got " + ctx.word(0));
        next.on = true;
    }
    if (ctx.has(1)) next.falloff = *parseFalloff(ctx.word(1));
    soft = next;
    ctx.host.status(softDescription(soft));
}

void execSnap(CommandContext& ctx) { ctx.session.snap = *parseSnapTarget(ctx.word(0)); }

void execCursor(CommandContext& ctx) { ctx.session.cursor = Vec3(ctx.number(0), ctx.number(1), ctx.number(2)); }

}  // namespace

void addSelectCommands(CommandTable& t) {
    using namespace arg;
    t.add({.name = "select",
           .label = "Select",
           .menu = "Select",
           .forms = {{choice("WHAT", {"all", "none", "linked", "invert"})},
                     {choice("ITEM", {"point", "patch", "net", "triangle", "curve"}), shown(word("N"), "N[,N...]")}},
           .help = "Select control points, or whole patches, nets, triangles or curves by number; linked: everything connected to the "
                   "selection; invert",
           .bindings = {{"Select All", "all", {"A"}},
                        {"Select None", "none", {"Alt+A"}},
                        {"Select Linked", "linked", {"L", "Ctrl+L"}},
                        {"Invert Selection", "invert", {"Ctrl+I"}}},
           .exec = execSelect});
    t.add({.name = "move",
           .label = "Move",
           .forms = {{number("DX"), number("DY"), number("DZ")}},
           .help = "Move the selection by a vector; joins are held",
           .exec = execMove});
    t.add({.name = "slide",
           .label = "Slide",
           .forms = {{anyCase(choice("DIR", {"u", "v", "n"})), number("DIST")}},
           .help = "Slide each selected point along its own control polygon in u or v, or along the surface normal there (n), by "
                   "DIST (Rhino's UVN move); soft selection slides the points around it along theirs, and joins are held",
           .exec = execSlide});
    t.add({.name = "rotate",
           .label = "Rotate",
           .forms = {{axis(), number("DEG")}},
           .help = "Rotate the selection about an axis through the pivot (median, active or 3D cursor); joins are held",
           .exec = execRotate});
    t.add({.name = "scale",
           .label = "Scale",
           .forms = {{number("S")}, {number("SX"), number("SY"), number("SZ")}},
           .help = "Scale the selection about the pivot (median, active or 3D cursor); joins are held",
           .exec = execScale});
    t.add({.name = "hide",
           .label = "Hide",
           .menu = "Select",
           .forms = {{opt(choice("WHICH", {"unselected"}))}},
           .help = "Hide the selected items (or every item the selection does not touch); hidden items are not drawn or picked",
           .bindings = {{"Hide Selected", "", {"H"}}, {"Hide Unselected", "unselected", {"Shift+H"}}},
           .exec = execHide});
    t.add({.name = "unhide",
           .label = "Reveal Hidden",
           .menu = "Select",
           .help = "Show every hidden item again and select it",
           .bindings = {{"", "", {"Alt+H"}}},
           .exec = execUnhide});
    t.add({.name = "pivot",
           .label = "Pivot",
           .menu = "Select",
           .forms = {{choice("PIVOT", {"median", "active", "cursor"})}},
           .help = "What rotate and scale turn about: the median of the selection, the active point or item, or the 3D cursor",
           .bindings = {{"Pivot: Median", "median", {}}, {"Pivot: Active", "active", {}}, {"Pivot: 3D Cursor", "cursor", {}}},
           .exec = execPivot});
    t.add({.name = "symmetry",
           .label = "Symmetry",
           .menu = "Select",
           .forms = {{choice("OFF", {"off"})}, {axis()}},
           .help = "Live symmetry: every transform moves each point's mirror partner across the plane normal to the axis through "
                   "the 3D cursor, and points on that plane stay on it",
           .bindings = {{"Symmetry: Off", "off", {}}, {"Symmetry: X", "X", {}}, {"Symmetry: Y", "Y", {}}, {"Symmetry: Z", "Z", {}}},
           .exec = execSymmetry});
    t.add({.name = "soft",
           .label = "Soft Selection",
           .menu = "Select",
           .forms = {{choice("MODE", {"on", "off", "toggle"}), opt(choice("FALLOFF", {"smooth", "linear", "sharp", "constant"}))},
                     {number("RADIUS"), opt(choice("FALLOFF", {"smooth", "linear", "sharp", "constant"}))}},
           .help = "Soft selection (Blender's proportional editing): transforms also carry the points within RADIUS of the moved ones, "
                   "measured along the control nets and across joins, by the falloff; the joins are held as always. The wheel "
                   "changes the radius while moving",
           .bindings = {{"Soft Selection", "toggle", {"O"}}},
           .checked = [](const EditSession& s, const CommandHost&) { return s.soft.on; },
           .exec = execSoft});
    t.add({.name = "snap",
           .label = "Snap To",
           .menu = "Select",
           .forms = {{choice("TARGET", {"grid", "points", "edges", "surfaces"})}},
           .help = "What a move snaps to while Ctrl is held: grid increments, control points, boundary edges or surfaces",
           .bindings = {{"Snap: Grid", "grid", {}},
                        {"Snap: Points", "points", {}},
                        {"Snap: Edges", "edges", {}},
                        {"Snap: Surfaces", "surfaces", {}}},
           .exec = execSnap});
    t.add({.name = "cursor",
           .label = "Place 3D Cursor",
           .forms = {{number("X"), number("Y"), number("Z")}},
           .help = "Place the 3D cursor, where new patches, triangles, curves and nets appear",
           .exec = execCursor});
}

}  // namespace commands
}  // namespace pw

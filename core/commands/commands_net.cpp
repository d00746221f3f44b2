// Net commands, the Net panel's actions as script lines: basis, tension, keep-C1, closing, rows and
// columns inserted or deleted, a net to Bézier patches and joined patches to a net.
#include <set>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/ops/net_ops.hpp"
#include "core/solve/constraint_solver.hpp"

namespace pw {
inline namespace commands {

namespace {

// The patches joined to patch p, directly or through others (the grid a conversion takes).
std::vector<uint32_t> joinedComponent(const Document& doc, uint32_t p) {
    std::set<uint32_t> seen{p};
    std::vector<uint32_t> todo{p};
    while (!todo.empty()) {
        const uint32_t q = todo.back();
        todo.pop_back();
        for (const Join& j : doc.joins) {
            if (!quadJoin(j)) continue;
            const uint32_t other = j.patchA == q ? j.patchB : j.patchB == q ? j.patchA : q;
            if (other != q && other < doc.patches.size() && seen.insert(other).second) todo.push_back(other);
        }
    }
    return {seen.begin(), seen.end()};
}

void execNetBasis(CommandContext& ctx) {
    const uint32_t n = ctx.index(0);
    const Basis b = *parseBasis(ctx.word(1));
    ctx.session.apply("Net basis", [&](Document& d) {
        setNetBasis(d, n, b, d.surfaces[n].tension);
        if (b == Basis::Bezier && d.surfaces[n].keepC1) projectConstraints(d, {});
    });
}

void execNetTension(CommandContext& ctx) {
    const uint32_t n = ctx.index(0);
    const double t = ctx.number(1);
    if (!(t >= 0.0 && t <= 1.0)) throw EditError("TENSION must lie in [0, 1], got " + ctx.word(1));
    if (ctx.session.doc.surfaces[n].basis != Basis::CatmullRom) throw EditError("net " + ctx.word(0) + " is not a Catmull-Rom net");
    if (ctx.preview) {
        ctx.session.doc.surfaces[n].tension = t;
        ctx.session.changed(false);
        return;
    }
    ctx.session.apply(
        "Net tension", [&](Document& d) { d.surfaces[n].tension = t; }, false);
}

void execNetKeepC1(CommandContext& ctx) {
    const uint32_t n = ctx.index(0);
    const bool keep = ctx.index(1) == 0;
    if (ctx.session.doc.surfaces[n].basis != Basis::Bezier) throw EditError("net " + ctx.word(0) + " is not a Bézier net");
    ctx.session.apply("Net continuity", [&](Document& d) {
        d.surfaces[n].keepC1 = keep;
        if (keep) projectConstraints(d, {});
    });
}

void execNetClosed(CommandContext& ctx) {
    const uint32_t n = ctx.index(0);
    const bool alongU = ctx.index(1) == 0, closed = ctx.index(2) == 0;
    ctx.session.apply("Close net", [&](Document& d) { setNetClosed(d, n, alongU, closed); });
}

// `net-insert N row|column K` (a new row or column at K) and `net-delete N row|column K`.
void execNetRows(CommandContext& ctx, bool insert) {
    const uint32_t n = ctx.index(0);
    const bool row = ctx.index(1) == 0;
    const Surface& net = ctx.session.doc.surfaces[n];
    const uint32_t k = ctx.index(2), last = (row ? net.rows : net.cols) - (insert ? 0 : 1);
    if (k > last) throw EditError("K: net " + ctx.word(0) + " has no " + ctx.word(1) + " " + ctx.word(2));
    const std::string what = std::string(insert ? "Insert net " : "Delete net ") + (row ? "row" : "column");
    ctx.session.apply(what, [&](Document& d) {
        if (insert)
            row ? insertNetRow(d, n, k) : insertNetColumn(d, n, k);
        else
            row ? deleteNetRow(d, n, k) : deleteNetColumn(d, n, k);
    });
    if (!insert) ctx.session.sel.points.clear();
}

void execNetInsert(CommandContext& ctx) { execNetRows(ctx, true); }
void execNetDelete(CommandContext& ctx) { execNetRows(ctx, false); }

void execNetToPatches(CommandContext& ctx) {
    const uint32_t n = ctx.index(0);
    ctx.session.apply("Convert net to patches", [&](Document& d) { convertNetToPatches(d, n); });
    ctx.session.sel.clear();
}

void execPatchesToNet(CommandContext& ctx) {
    const std::vector<uint32_t> grid = joinedComponent(ctx.session.doc, ctx.index(0));
    int created = -1;
    ctx.session.apply("Convert patches to net", [&](Document& d) { created = int(convertPatchesToNet(d, grid)); });
    ctx.session.sel.clear();
    ctx.session.sel.surface = created;
}

}  // namespace

void addNetCommands(CommandTable& t) {
    using namespace arg;
    const CommandArg rowOrColumn = choice("ROW|COLUMN", {"row", "column"});
    t.add({.name = "net-basis",
           .label = "Net Basis",
           .forms = {{net(), choice("BASIS", {"bezier", "bspline", "catmull-rom"})}},
           .help = "The same net under another basis: Bézier (windows step by 3, C0 or kept C1), uniform B-spline (C2, approximating) "
                   "or Catmull-Rom (C1, through its inner points)",
           .exec = execNetBasis});
    t.add({.name = "net-tension",
           .label = "Net Tension",
           .forms = {{net(), number("TENSION")}},
           .help = "A Catmull-Rom net's tension in [0, 1]: 0.5 is the classic spline, 0 gives straight segments",
           .previewable = true,
           .exec = execNetTension});
    t.add({.name = "net-keep-c1",
           .label = "Net Keeps C1",
           .forms = {{net(), choice("ON|OFF", {"on", "off"})}},
           .help = "A Bézier net holds every seam point midway between its neighbours while you drag (otherwise its windows only meet "
                   "C0)",
           .exec = execNetKeepC1});
    t.add({.name = "net-closed",
           .label = "Close Net",
           .forms = {{net(), choice("DIR", {"u", "v"}), choice("ON|OFF", {"on", "off"})}},
           .help = "Close a net along u (columns wrap around: the last window joins the first) or v (rows wrap), or open it",
           .exec = execNetClosed});
    t.add({.name = "net-insert",
           .label = "Insert Net Row or Column",
           .forms = {{net(), rowOrColumn, count("K")}},
           .help = "A new row or column of net N at K (0 = first), midway between its neighbours",
           .exec = execNetInsert});
    t.add({.name = "net-delete",
           .label = "Delete Net Row or Column",
           .forms = {{net(), rowOrColumn, count("K")}},
           .help = "Remove row or column K of net N; a net keeps at least 4",
           .exec = execNetDelete});
    t.add({.name = "net-to-patches",
           .label = "Net to Bézier Patches",
           .forms = {{net()}},
           .help = "Replace net N by independent Bézier patches describing the same surface exactly, joined as the basis implies (C1 "
                   "for splines and kept-C1 Bézier nets, C0 otherwise)",
           .exec = execNetToPatches});
    t.add({.name = "patches-to-net",
           .label = "Patches to B-spline Net",
           .forms = {{patch()}},
           .help = "Replace patch P and the patches joined to it by one uniform B-spline net: exact when they form a regular C2 grid "
                   "(for example a converted B-spline net), refused otherwise",
           .exec = execPatchesToNet});
}

}  // namespace commands
}  // namespace pw

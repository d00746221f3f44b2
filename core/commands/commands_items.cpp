// Item commands the Inspector runs: a patch's, net's, triangle's or curve's name, and one control
// point placed exactly with the joins held.
#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/constructions.hpp"
#include "core/edit/drag_controller.hpp"
#include "core/edit/live_constructions.hpp"
#include "core/select/symmetry.hpp"
#include "core/solve/constraint_solver.hpp"

namespace pw {
inline namespace commands {

namespace {

void execRename(CommandContext& ctx) {
    const uint32_t kind = ctx.index(0);
    const std::string& name = ctx.word(2);
    Document& doc = ctx.session.doc;
    const size_t counts[4] = {doc.patches.size(), doc.surfaces.size(), doc.triangles.size(), doc.curves.size()};
    const char* what[4] = {"patch", "net", "triangle", "curve"};
    const uint32_t i = commandIndex(ctx.word(1), counts[kind], what[kind]);
    if (name.find_first_of("\n\r") != std::string::npos) throw EditError("a name is one line");
    ctx.session.applyOutsideScene(std::string("Rename ") + what[kind], [&](Document& d) {
        std::string& field = kind == 0   ? d.patches[i].name
                             : kind == 1 ? d.surfaces[i].name
                             : kind == 2 ? d.triangles[i].name
                                         : d.curves[i].name;
        field = name;
    });
}

// `point P X Y Z`: pool point P at (X, Y, Z), its mirror partner under live symmetry too; the joins
// are held with it fixed, and a position they cannot follow is refused.
void execPoint(CommandContext& ctx) {
    EditSession& s = ctx.session;
    const uint32_t p = commandIndex(ctx.word(0), s.doc.points.size(), "point");
    const Vec3 to(ctx.number(1), ctx.number(2), ctx.number(3));
    if (const std::string why = constructedPointsRefusal(s.doc, {p}); !why.empty()) throw EditError(why);
    const Symmetry sym = s.symmetry;
    s.apply(
        "Set point",
        [&](Document& d) {
            const TransformSetup t = setUpTransform(d, {p}, SoftSelection{}, sym);
            d.points[p] = to;
            applySymmetry(d.points, t.pairs, sym);
            if (!d.constructions.empty()) rerunConstructions(d);
            if (const Projection pr = t.solver->project(d.points); !pr.ok())
                throw EditError("the joins cannot follow: " + conflictMessage(pr));
        },
        false);
}

}  // namespace

void addItemCommands(CommandTable& t) {
    using namespace arg;
    t.add({.name = "rename",
           .label = "Rename",
           .forms = {{choice("ITEM", {"patch", "net", "triangle", "curve"}), count("N"), word("NAME")}},
           .help = "Name patch, net, triangle or curve N (shown in the outliner, written to every format that keeps names); "
                   "quote a name with spaces",
           .exec = execRename});
    t.add({.name = "point",
           .label = "Place Point",
           .forms = {{count("P"), number("X"), number("Y"), number("Z")}},
           .help = "Place control point P at X Y Z exactly (its mirror partner too under live symmetry); the joins are held, and a "
                   "place they cannot follow is refused",
           .exec = execPoint});
}

}  // namespace commands
}  // namespace pw

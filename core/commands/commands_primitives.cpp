// Rational modelling commands (issue 21): the exact primitives add-sphere, add-cylinder, add-cone
// and add-torus at the 3D cursor (core/construct/primitives.hpp), and `weight`, which sets the weight of the
// selected control points (rational patches, core/eval/rational_eval.hpp).
#include <algorithm>
#include <cstdio>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/construct/primitives.hpp"
#include "core/edit/edit_session.hpp"
#include "core/edit/live_constructions.hpp"
#include "core/model/placement.hpp"

namespace pw {
inline namespace commands {

namespace {

double defaultSize(const Document& d) { return std::max(0.1 * modelSize(d), 0.5); }

using Make = PrimitiveResult (*)(Document&, const Vec3&, double, double, bool);

std::string formatWeight(double w) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", w);
    return buf;
}

// Every exec below sees words the table has checked against the command's forms.

// Adds a primitive of one or two sizes (the arguments, or else `ratio`s of the model's scale) at the
// 3D cursor, beside the model where the cursor is inside it; the new points are selected.
void execPrimitive(CommandContext& ctx, const char* undoLabel, double ratio1, double ratio2, Make make) {
    EditSession& s = ctx.session;
    const double base = defaultSize(s.doc);
    const double a = ctx.has(0) ? ctx.number(0) : ratio1 * base;
    const double b = ctx.has(1) ? ctx.number(1) : ratio2 * base;
    PrimitiveResult made;
    s.apply(undoLabel, [&](Document& d) {
        const size_t firstPoint = d.points.size();
        made = make(d, s.cursor, a, b, s.camera.zUp);
        moveClearOfExisting(d, firstPoint);
    });
    s.sel.clear();
    s.sel.points = made.points;
}

// A command adding a primitive (execPrimitive) whose sizes are named `first` and `second` (null:
// one size only), both optional.
Command primitive(const char* name, const char* label, const char* help, const char* undoLabel, const char* first, const char* second,
                  double ratio1, double ratio2, Make make) {
    using namespace arg;
    CommandForm form{opt(number(first))};
    if (second) form.push_back(opt(number(second)));
    return {.name = name, .label = label, .menu = "Add", .forms = {form}, .help = help, .exec = [=](CommandContext& ctx) {
                execPrimitive(ctx, undoLabel, ratio1, ratio2, make);
            }};
}

void execWeight(CommandContext& ctx) {
    EditSession& s = ctx.session;
    const double w = ctx.number(0);
    const std::vector<uint32_t> pts = s.selectedPoints();
    if (pts.empty()) throw EditError("select the control points to weigh first");
    if (const std::string why = constructedPointsRefusal(s.doc, pts); !why.empty()) throw EditError(why);
    s.apply("Weight " + formatWeight(w), [&](Document& d) {
        for (uint32_t i : pts) setPointWeight(d, i, w);
        if (const auto tp = weightedTrianglePoint(d))
            throw EditError("point " + std::to_string((*tp)[1]) + " belongs to triangle " + std::to_string((*tp)[0]) +
                            "; Bézier triangles take no weights");
    });
}

}  // namespace

void addPrimitiveCommands(CommandTable& t) {
    using namespace arg;
    t.add(primitive("add-sphere", "Sphere (exact)",
                    "Add an exact sphere at the 3D cursor: eight rational bicubic patches (quarter circles of weights 1, √2/2, 1), "
                    "watertight, normals outward",
                    "Add sphere", "RADIUS", nullptr, 1.0, 0.0,
                    [](Document& d, const Vec3& c, double r, double, bool zUp) { return addSphere(d, c, r, zUp); }));
    t.add(primitive("add-cylinder", "Cylinder (exact)",
                    "Add an exact closed cylinder standing on the 3D cursor: rational patches for the side and both caps", "Add cylinder",
                    "RADIUS", "HEIGHT", 1.0, 2.0, addCylinder));
    t.add(primitive("add-cone", "Cone (exact)",
                    "Add an exact closed cone standing on the 3D cursor: rational patches for the side and the base", "Add cone", "RADIUS",
                    "HEIGHT", 1.0, 2.0, addCone));
    t.add(primitive("add-torus", "Torus (exact)",
                    "Add an exact torus around the 3D cursor: sixteen rational patches; MAJOR is the distance from the axis to the tube's "
                    "centre, MINOR the tube's radius",
                    "Add torus", "MAJOR", "MINOR", 1.0, 0.35, addTorus));
    t.add({.name = "weight",
           .label = "Set Weight",
           .menu = "Edit",
           .forms = {{number("W")}},
           .help = "Set the weight of the selected control points (rational patches: a heavier point pulls the surface towards it; "
                   "1 = polynomial). Bézier triangles take no weights",
           .exec = execWeight});
}

}  // namespace commands
}  // namespace pw

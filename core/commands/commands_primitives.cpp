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

namespace {

double defaultSize(const Document& d) { return std::max(0.1 * modelSize(d), 0.5); }

using Make = PrimitiveResult (*)(Document&, const Vec3&, double, double, bool);

// A command adding a primitive of one or two sizes (default: `ratio`s of the model's scale) at the
// 3D cursor, beside the model where the cursor is inside it; the new points are selected.
Command primitive(const char* name, const char* label, const char* usage, const char* help, const char* undoLabel, const char* first,
                  const char* second, double ratio1, double ratio2, Make make) {
    const size_t maxArgs = second ? 2 : 1;
    return {.name = name, .label = label, .menu = "Add", .usage = usage, .help = help, .run = [=](CommandContext& ctx) {
                expectArgs(ctx, 0, maxArgs);
                EditSession& s = ctx.session;
                const double base = defaultSize(s.doc);
                const double a = ctx.args.size() >= 1 ? commandNumber(ctx.args[0], first) : ratio1 * base;
                const double b = ctx.args.size() >= 2 ? commandNumber(ctx.args[1], second) : ratio2 * base;
                PrimitiveResult made;
                s.apply(undoLabel, [&](Document& d) {
                    const size_t firstPoint = d.points.size();
                    made = make(d, s.cursor, a, b, s.camera.zUp);
                    moveClearOfExisting(d, firstPoint);
                });
                s.sel.clear();
                s.sel.points = made.points;
            }};
}

std::string formatWeight(double w) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", w);
    return buf;
}

}  // namespace

void addPrimitiveCommands(CommandTable& t) {
    t.add(primitive("add-sphere", "Sphere (exact)", "[RADIUS]",
                    "Add an exact sphere at the 3D cursor: eight rational bicubic patches (quarter circles of weights 1, √2/2, 1), "
                    "watertight, normals outward",
                    "Add sphere", "RADIUS", nullptr, 1.0, 0.0,
                    [](Document& d, const Vec3& c, double r, double, bool zUp) { return addSphere(d, c, r, zUp); }));
    t.add(primitive("add-cylinder", "Cylinder (exact)", "[RADIUS HEIGHT]",
                    "Add an exact closed cylinder standing on the 3D cursor: rational patches for the side and both caps", "Add cylinder",
                    "RADIUS", "HEIGHT", 1.0, 2.0, addCylinder));
    t.add(primitive("add-cone", "Cone (exact)", "[RADIUS HEIGHT]",
                    "Add an exact closed cone standing on the 3D cursor: rational patches for the side and the base", "Add cone", "RADIUS",
                    "HEIGHT", 1.0, 2.0, addCone));
    t.add(primitive("add-torus", "Torus (exact)", "[MAJOR MINOR]",
                    "Add an exact torus around the 3D cursor: sixteen rational patches; MAJOR is the distance from the axis to the tube's "
                    "centre, MINOR the tube's radius",
                    "Add torus", "MAJOR", "MINOR", 1.0, 0.35, addTorus));
    t.add({.name = "weight",
           .label = "Set Weight",
           .menu = "Edit",
           .usage = "W",
           .help = "Set the weight of the selected control points (rational patches: a heavier point pulls the surface towards it; "
                   "1 = polynomial). Bézier triangles take no weights",
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 1, 1);
               EditSession& s = ctx.session;
               const double w = commandNumber(ctx.args[0], "W");
               const std::vector<uint32_t> pts = s.selectedPoints();
               if (pts.empty()) throw EditError("select the control points to weigh first");
               if (const std::string why = constructedPointsRefusal(s.doc, pts); !why.empty()) throw EditError(why);
               s.apply("Weight " + formatWeight(w), [&](Document& d) {
                   for (uint32_t i : pts) setPointWeight(d, i, w);
                   if (const auto tp = weightedTrianglePoint(d))
                       throw EditError("point " + std::to_string((*tp)[1]) + " belongs to triangle " + std::to_string((*tp)[0]) +
                                       "; Bézier triangles take no weights");
               });
           }});
}

}  // namespace pw

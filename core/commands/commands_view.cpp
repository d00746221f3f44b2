// View and display commands: named views, projection, frame, overlays, shading, tessellation
// levels and partitioning; and the window's own toggles (help, palette, presentation, panels).
#include <algorithm>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/commands/command_table.hpp"
#include "core/model/camera_math.hpp"
#include "core/model/settings.hpp"

namespace pw {

namespace {

struct Overlay {
    const char* name;
    const char* label;
    bool DisplaySettings::*flag;
    const char* help;
};
constexpr Overlay kOverlays[] = {
    {"grid", "Control Net", &DisplaySettings::showGrid, "Show the control points and net lines"},
    {"wireframe", "Wireframe", &DisplaySettings::showWireframe, "Show the tessellated triangles"},
    {"normals", "Normals", &DisplaySettings::showNormals, "Show surface normals"},
    {"boundaries", "Boundaries", &DisplaySettings::showBoundaries,
     "Patch boundaries coloured by continuity (grey open, red C0, green C1, blue G1)"},
    {"isocurves", "Isocurves", &DisplaySettings::showIsocurves, "Isoparametric curves of every patch through the isoline tessellator"},
    {"combs", "Curvature Combs", &DisplaySettings::showCombs,
     "Curvature combs on every curve and isocurve (2 isocurve lines: the boundaries) and the curvature graph across the selected join"},
};

const Overlay& overlayNamed(const std::string& name) {
    for (const Overlay& o : kOverlays)
        if (name == o.name) return o;
    throw EditError("expected an overlay grid, wireframe, normals, boundaries, isocurves or combs, got '" + name + "'");
}

// A command that sets one enum-valued setting from its name (one of `usage`, '|'-separated), as
// one undo step named `label`.
template <class E>
Command enumSetting(const char* name, const char* label, const char* usage, const char* help, std::optional<E> (*parse)(std::string_view),
                    void (*set)(Document&, E)) {
    return {.name = name, .label = label, .usage = usage, .help = help, .run = [=](CommandContext& ctx) {
                expectArgs(ctx, 1, 1);
                const std::optional<E> v = parse(ctx.args[0]);
                if (!v) throw EditError("expected one of " + std::string(usage) + ", got '" + ctx.args[0] + "'");
                ctx.session.apply(
                    label, [&](Document& d) { set(d, *v); }, false);
            }};
}

// "on", "off" or nothing (toggle).
bool switchArg(const CommandContext& ctx, size_t i, bool current) {
    if (ctx.args.size() <= i) return !current;
    if (ctx.args[i] == "on") return true;
    if (ctx.args[i] == "off") return false;
    throw EditError("expected on or off, got '" + ctx.args[i] + "'");
}

}  // namespace

void addViewCommands(CommandTable& t) {
    t.add({.name = "view",
           .label = "View",
           .menu = "View",
           .usage = "front|back|right|left|top|bottom|iso",
           .help = "Look at the model from a named direction",
           .bindings = {{"Front", "front", {"Numpad1", "1"}},
                        {"Back", "back", {"Ctrl+Numpad1", "Ctrl+1"}},
                        {"Right", "right", {"Numpad3", "3"}},
                        {"Left", "left", {"Ctrl+Numpad3", "Ctrl+3"}},
                        {"Top", "top", {"Numpad7", "7"}},
                        {"Bottom", "bottom", {"Ctrl+Numpad7", "Ctrl+7"}},
                        {"Iso", "iso", {}}},
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 1, 1);
               const auto c = applyNamedView(ctx.session.camera, ctx.args[0]);
               if (!c) throw EditError("expected front, back, right, left, top, bottom or iso, got '" + ctx.args[0] + "'");
               ctx.session.camera = *c;
           }});
    t.add({.name = "ortho",
           .label = "Orthographic",
           .menu = "View",
           .usage = "[on|off]",
           .help = "Toggle perspective / orthographic projection",
           .bindings = {{"", "", {"Numpad5", "5"}}},
           .checked = [](const EditSession& s, const CommandHost&) { return s.camera.orthographic; },
           .run =
               [](CommandContext& ctx) {
                   expectArgs(ctx, 0, 1);
                   ctx.session.camera.orthographic = switchArg(ctx, 0, ctx.session.camera.orthographic);
               }});
    t.add({.name = "frame",
           .label = "Frame Selection",
           .menu = "View",
           .help = "Fit the selection (or the model) in the view",
           .bindings = {{"", "", {"F"}}},
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 0, 0);
               const Bounds box = frameTargetBounds(ctx.session.doc, ctx.session.sel);
               if (!ctx.host.frame(box)) ctx.session.camera = frameBounds(ctx.session.camera, box, 16.0 / 9.0);
           }});
    t.add(windowToggle("xray", "Select Through (X-ray)", "View", WindowToggle::XRay, {"Alt+Z"},
                       "Box selection takes the points behind the surface too (off: only the points you can see)"));
    t.add(windowToggle("ground-grid", "Ground Grid", "View", WindowToggle::GroundGrid, {}, "Show the ground-plane grid"));
    t.add(windowToggle("full-detail", "Full Detail", "View", WindowToggle::FullDetail, {},
                       "Draw a document too heavy for the CPU renderer at its own levels (off: screen-adaptive, 8 px a segment, "
                       "while it is that heavy)"));
    t.add(windowToggle("domain-view", "Domain View", "View", WindowToggle::DomainView, {},
                       "The parametric domain tessellated by the GPU with the current levels (Teaching panel for more)"));
    t.add(windowToggle("shaders", "Shaders", "View", WindowToggle::ShaderPanel, {},
                       "The GLSL of the tessellation stages in use, with the defines of each variant"));
    t.add(windowToggle("presentation", "Presentation Mode", "View", WindowToggle::Presentation, {"F5"},
                       "Hide the editing panels; levels and counts large, high contrast (F5 toggles back)"));
    t.add({.name = "domain-origin",
           .label = "Domain Origin",
           .menu = "View",
           .usage = "upper-left|lower-left",
           .help = "The domain view's picture, kept with the document: upper-left (the D3D notes' and Vulkan's default: v = 0 on "
                   "top, edges tagged [i]) or lower-left (GL)",
           .bindings = {{"Upper-Left (D3D, Vulkan)", "upper-left", {}}, {"Lower-Left (GL)", "lower-left", {}}},
           .checked = [](const EditSession& s, const CommandHost&) { return s.doc.display.domainUpperLeft; },
           .run =
               [](CommandContext& ctx) {
                   expectArgs(ctx, 1, 1);
                   const auto upperLeft = parseDomainOrigin(ctx.args[0]);
                   if (!upperLeft) throw EditError("expected upper-left or lower-left, got '" + ctx.args[0] + "'");
                   ctx.session.apply(
                       "Domain origin", [&](Document& d) { d.display.domainUpperLeft = *upperLeft; }, false);
               }});
    t.add({.name = "presentation-text",
           .label = "Presentation Text",
           .menu = "View",
           .usage = "bigger|smaller|SCALE",
           .help = "Presentation mode's text size: a quarter step larger or smaller, or SCALE times the interface's (1 to 4)",
           .bindings = {{"Larger Presentation Text", "bigger", {"Ctrl+="}}, {"Smaller Presentation Text", "smaller", {"Ctrl+-"}}},
           .windowOnly = true,
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 1, 1);
               const std::string& a = ctx.args[0];
               const float now = ctx.host.presentationTextScale();
               float scale = 0.0f;
               if (a == "bigger" || a == "smaller") {
                   // Quarter steps from the current size, landing on the quarter grid.
                   scale = std::round(now * 4.0f + (a == "bigger" ? 1.0f : -1.0f)) / 4.0f;
                   scale = std::clamp(scale, limits::kMinPresentationText, limits::kMaxPresentationText);
               } else {
                   const double v = commandNumber(a, "SCALE");
                   if (!(v >= limits::kMinPresentationText && v <= limits::kMaxPresentationText))
                       throw EditError("SCALE must lie within [" + std::to_string(int(limits::kMinPresentationText)) + ", " +
                                       std::to_string(int(limits::kMaxPresentationText)) + "], got " + a);
                   scale = float(v);
               }
               ctx.host.setPresentationTextScale(scale);
           }});

    std::vector<CommandBinding> overlayBindings;
    for (const Overlay& o : kOverlays) overlayBindings.push_back({o.label, o.name, {}});
    t.add({.name = "overlay",
           .label = "Overlay",
           .menu = "Display",
           .usage = "grid|wireframe|normals|boundaries|isocurves [on|off]",
           .help = "Show or hide an overlay: control net, wireframe, normals, boundaries by continuity, isocurves",
           .bindings = overlayBindings,
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 1, 2);
               const Overlay& o = overlayNamed(ctx.args[0]);
               const bool on = switchArg(ctx, 1, ctx.session.doc.display.*o.flag);
               ctx.session.apply(
                   o.label, [&](Document& d) { d.display.*o.flag = on; }, false);
           }});
    t.add({.name = "comb",
           .label = "Comb Scale and Density",
           .menu = "Display",
           .usage = "SCALE [TEETH]",
           .help = "Curvature comb length (1 = a tooth of 0.02 × model size² × curvature; negative draws the teeth inward) and teeth per "
                   "curve (2..21); `overlay combs` shows them",
           .run = [](CommandContext& ctx) {
               expectArgs(ctx, 1, 2);
               const double scale = commandNumber(ctx.args[0], "SCALE");
               if (std::abs(scale) > 1e6) throw EditError("SCALE must lie within ±1e6, got " + ctx.args[0]);
               int teeth = ctx.session.doc.display.combDensity;
               if (ctx.args.size() == 2) {
                   const double t = commandNumber(ctx.args[1], "TEETH");
                   if (t != std::floor(t) || t < 2 || t > 21) throw EditError("TEETH must be a whole number in 2..21, got " + ctx.args[1]);
                   teeth = int(t);
               }
               ctx.session.apply(
                   "Comb",
                   [&](Document& d) {
                       d.display.combScale = float(scale);
                       d.display.combDensity = teeth;
                   },
                   false);
           }});
    t.add(enumSetting<ShadingMode>("shading", "Shading", "lit|normal|patch|uv|zebra|gauss|mean|level", "How the surface is coloured",
                                   parseShading, [](Document& d, ShadingMode m) { d.display.shading = m; }));
    t.add({.name = "tess",
           .label = "Tessellation Levels",
           .usage = "LEVEL | O0 O1 O2 O3 I0 I1",
           .help = "Set every outer and inner level (one number), or the four outer and two inner levels",
           .run = [](CommandContext& ctx) {
               if (ctx.args.size() != 1) expectArgs(ctx, 6, 6);
               std::array<float, 6> v{};
               for (size_t i = 0; i < 6; ++i) {
                   const double x = commandNumber(ctx.args[ctx.args.size() == 1 ? 0 : i], "LEVEL");
                   if (auto problem = settingProblem(setting("tess.level"), {x})) throw EditError("LEVEL: " + *problem);
                   v[i] = float(x);
               }
               ctx.session.apply(
                   "Tessellation levels",
                   [&](Document& d) {
                       std::copy_n(v.begin(), 4, d.tess.outer.begin());
                       std::copy_n(v.begin() + 4, 2, d.tess.inner.begin());
                       d.tess.linked = ctx.args.size() == 1;
                   },
                   false);
           }});
    t.add(enumSetting<Spacing>("spacing", "Partitioning", "equal|fractional_odd|fractional_even|pow2",
                               "Spacing of the tessellator: equal, fractional odd/even (smooth level changes), pow2 (rounded up)",
                               parseSpacing, [](Document& d, Spacing sp) { d.tess.spacing = sp; }));

    t.add(windowToggle("palette", "Command Palette...", "Help", WindowToggle::Palette, {"F3"},
                       "Search every command by name and run it (Enter)"));
    t.add(windowToggle("help", "Keys and Commands", "Help", WindowToggle::Help, {"F1", "Shift+/"},
                       "List every command with its keys, and the mouse actions"));
}

}  // namespace pw

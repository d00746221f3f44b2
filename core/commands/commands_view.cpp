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
inline namespace commands {

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

// The overlays' names, as the `overlay` command's choices.
std::vector<std::string> overlayNames() {
    std::vector<std::string> names;
    for (const Overlay& o : kOverlays) names.emplace_back(o.name);
    return names;
}

// Sets one enum-valued setting from its name (one of the command's choices), as one undo step
// named `label`.
template <class E>
void execEnumSetting(CommandContext& ctx, const char* label, std::optional<E> (*parse)(std::string_view), void (*set)(Document&, E)) {
    const E v = *parse(ctx.word(0));
    ctx.session.apply(
        label, [&](Document& d) { set(d, v); }, false);
}

// A command that sets one enum-valued setting from its name (one of `choices`), as one undo step
// named `label`.
template <class E>
Command enumSetting(const char* name, const char* label, const char* what, std::vector<std::string> choices, const char* help,
                    std::optional<E> (*parse)(std::string_view), void (*set)(Document&, E)) {
    return {
        .name = name,
        .label = label,
        .forms = {{arg::choice(what, std::move(choices))}},
        .help = help,
        .exec = [=](CommandContext& ctx) { execEnumSetting(ctx, label, parse, set); },
    };
}

// Word i, "on" or "off" (choice index 0 or 1), or nothing (toggle).
bool switchArg(const CommandContext& ctx, size_t i, bool current) { return ctx.has(i) ? ctx.index(i) == 0 : !current; }

// Every exec below sees words the table has checked against the command's forms.

void execView(CommandContext& ctx) { ctx.session.camera = *applyNamedView(ctx.session.camera, ctx.word(0)); }

void execOrtho(CommandContext& ctx) { ctx.session.camera.orthographic = switchArg(ctx, 0, ctx.session.camera.orthographic); }

void execFrame(CommandContext& ctx) {
    const Bounds box = frameTargetBounds(ctx.session.doc, ctx.session.sel);
    if (!ctx.host.frame(box)) ctx.session.camera = frameBounds(ctx.session.camera, box, 16.0 / 9.0);
}

void execDomainOrigin(CommandContext& ctx) {
    const bool upperLeft = *parseDomainOrigin(ctx.word(0));
    ctx.session.apply(
        "Domain origin", [&](Document& d) { d.display.domainUpperLeft = upperLeft; }, false);
}

void execPresentationText(CommandContext& ctx) {
    const float now = ctx.host.presentationTextScale();
    float scale = 0.0f;
    if (ctx.form == 0) {
        // Quarter steps from the current size, landing on the quarter grid.
        scale = std::round(now * 4.0f + (ctx.word(0) == "bigger" ? 1.0f : -1.0f)) / 4.0f;
        scale = std::clamp(scale, limits::kMinPresentationText, limits::kMaxPresentationText);
    } else {
        const double v = ctx.number(0);
        if (!(v >= limits::kMinPresentationText && v <= limits::kMaxPresentationText))
            throw EditError("SCALE must lie within [" + std::to_string(int(limits::kMinPresentationText)) + ", " +
                            std::to_string(int(limits::kMaxPresentationText)) + "], got " + ctx.word(0));
        scale = float(v);
    }
    ctx.host.setPresentationTextScale(scale);
}

void execOverlay(CommandContext& ctx) {
    const Overlay& o = kOverlays[ctx.index(0)];
    const bool on = switchArg(ctx, 1, ctx.session.doc.display.*o.flag);
    ctx.session.apply(
        o.label, [&](Document& d) { d.display.*o.flag = on; }, false);
}

void execComb(CommandContext& ctx) {
    const double scale = ctx.number(0);
    if (std::abs(scale) > 1e6) throw EditError("SCALE must lie within ±1e6, got " + ctx.word(0));
    int teeth = ctx.session.doc.display.combDensity;
    if (ctx.has(1)) {
        const uint32_t t = ctx.index(1);
        if (t < 2 || t > 21) throw EditError("TEETH must be a whole number in 2..21, got " + ctx.word(1));
        teeth = int(t);
    }
    ctx.session.apply(
        "Comb",
        [&](Document& d) {
            d.display.combScale = float(scale);
            d.display.combDensity = teeth;
        },
        false);
}

void execTess(CommandContext& ctx) {
    const bool linked = ctx.form == 0;
    std::array<float, 6> v{};
    for (size_t i = 0; i < 6; ++i) {
        const double x = ctx.number(linked ? 0 : i);
        if (auto problem = settingProblem(setting("tess.level"), {x})) throw EditError("LEVEL: " + *problem);
        v[i] = float(x);
    }
    ctx.session.apply(
        "Tessellation levels",
        [&](Document& d) {
            std::copy_n(v.begin(), 4, d.tess.outer.begin());
            std::copy_n(v.begin() + 4, 2, d.tess.inner.begin());
            d.tess.linked = linked;
        },
        false);
}

}  // namespace

void addViewCommands(CommandTable& t) {
    using namespace arg;
    t.add({.name = "view",
           .label = "View",
           .menu = "View",
           .forms = {{choice("VIEW", {"front", "back", "right", "left", "top", "bottom", "iso"})}},
           .help = "Look at the model from a named direction",
           .bindings = {{"Front", "front", {"Numpad1", "1"}},
                        {"Back", "back", {"Ctrl+Numpad1", "Ctrl+1"}},
                        {"Right", "right", {"Numpad3", "3"}},
                        {"Left", "left", {"Ctrl+Numpad3", "Ctrl+3"}},
                        {"Top", "top", {"Numpad7", "7"}},
                        {"Bottom", "bottom", {"Ctrl+Numpad7", "Ctrl+7"}},
                        {"Iso", "iso", {}}},
           .exec = execView});
    t.add({.name = "ortho",
           .label = "Orthographic",
           .menu = "View",
           .forms = {{}, {choice("MODE", {"on", "off"})}},
           .help = "Toggle perspective / orthographic projection",
           .bindings = {{"", "", {"Numpad5", "5"}}},
           .checked = [](const EditSession& s, const CommandHost&) { return s.camera.orthographic; },
           .exec = execOrtho});
    t.add({.name = "frame",
           .label = "Frame Selection",
           .menu = "View",
           .help = "Fit the selection (or the model) in the view",
           .bindings = {{"", "", {"F"}}},
           .exec = execFrame});
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
           .forms = {{choice("ORIGIN", {"upper-left", "lower-left"})}},
           .help = "The domain view's picture, kept with the document: upper-left (the D3D notes' and Vulkan's default: v = 0 on "
                   "top, edges tagged [i]) or lower-left (GL)",
           .bindings = {{"Upper-Left (D3D, Vulkan)", "upper-left", {}}, {"Lower-Left (GL)", "lower-left", {}}},
           .checked = [](const EditSession& s, const CommandHost&) { return s.doc.display.domainUpperLeft; },
           .exec = execDomainOrigin});
    t.add({.name = "presentation-text",
           .label = "Presentation Text",
           .menu = "View",
           .forms = {{choice("STEP", {"bigger", "smaller"})}, {number("SCALE")}},
           .help = "Presentation mode's text size: a quarter step larger or smaller, or SCALE times the interface's (1 to 4)",
           .bindings = {{"Larger Presentation Text", "bigger", {"Ctrl+="}}, {"Smaller Presentation Text", "smaller", {"Ctrl+-"}}},
           .windowOnly = true,
           .exec = execPresentationText});

    std::vector<CommandBinding> overlayBindings;
    for (const Overlay& o : kOverlays) overlayBindings.push_back({o.label, o.name, {}});
    t.add({.name = "overlay",
           .label = "Overlay",
           .menu = "Display",
           .forms = {{choice("OVERLAY", overlayNames()), opt(choice("MODE", {"on", "off"}))}},
           .help = "Show or hide an overlay: control net, wireframe, normals, boundaries by continuity, isocurves",
           .bindings = overlayBindings,
           .exec = execOverlay});
    t.add({.name = "comb",
           .label = "Comb Scale and Density",
           .menu = "Display",
           .forms = {{number("SCALE"), opt(count("TEETH"))}},
           .help = "Curvature comb length (1 = a tooth of 0.02 × model size² × curvature; negative draws the teeth inward) and teeth per "
                   "curve (2..21); `overlay combs` shows them",
           .exec = execComb});
    t.add(enumSetting<ShadingMode>("shading", "Shading", "MODE", {"lit", "normal", "patch", "uv", "zebra", "gauss", "mean", "level"},
                                   "How the surface is coloured", parseShading, [](Document& d, ShadingMode m) { d.display.shading = m; }));
    t.add({.name = "tess",
           .label = "Tessellation Levels",
           .forms = {{number("LEVEL")}, {number("O0"), number("O1"), number("O2"), number("O3"), number("I0"), number("I1")}},
           .help = "Set every outer and inner level (one number), or the four outer and two inner levels",
           .exec = execTess});
    t.add(enumSetting<Spacing>("spacing", "Partitioning", "SPACING", {"equal", "fractional_odd", "fractional_even", "pow2", "integer"},
                               "Spacing of the tessellator: equal, fractional odd/even (smooth level changes), pow2 (rounded up)",
                               parseSpacing, [](Document& d, Spacing sp) { d.tess.spacing = sp; }));

    t.add(windowToggle("palette", "Command Palette...", "Help", WindowToggle::Palette, {"F3"},
                       "Search every command by name and run it (Enter)"));
    t.add(windowToggle("help", "Keys and Commands", "Help", WindowToggle::Help, {"F1", "Shift+/"},
                       "List every command with its keys, and the mouse actions"));
}

}  // namespace commands
}  // namespace pw

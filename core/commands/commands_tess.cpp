// Tessellation-level commands the panels run: an item's own levels (the Inspector), the document's
// levels fixed as a kept lesson and the notes' distance formulas (the Teaching panel).
#include <string>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/model/settings.hpp"
#include "core/tess/tess_presets.hpp"

namespace pw {
inline namespace commands {

namespace {

// Levels from words first.. of the command, each within the tess.level row's range (the settings
// table, as the panels and the file reader take it).
template <size_t N>
std::array<float, N> levelWords(const CommandContext& ctx, size_t first) {
    std::array<float, N> out{};
    for (size_t k = 0; k < N; ++k) {
        const double v = ctx.number(first + k);
        if (auto problem = settingProblem(setting("tess.level"), {v})) throw EditError(*problem);
        out[k] = float(v);
    }
    return out;
}

// `patch-levels P off|O0 O1 O2 O3 I0 I1` and `triangle-levels T off|O0 O1 O2 I`: an item's own
// levels (the override of the document's), previewable while an Inspector slider moves.
template <class Item, size_t N>
void setOwnLevels(CommandContext& ctx, std::vector<Item> Document::*items, const char* step) {
    const uint32_t i = ctx.index(0);
    std::optional<std::array<float, N>> levels;
    if (ctx.form == 1) levels = levelWords<N>(ctx, 1);
    if (ctx.preview) {
        (ctx.session.doc.*items)[i].tessOverride = levels;
        ctx.session.changedLevels();
        return;
    }
    ctx.session.applyLevels(step, [&](Document& d) { (d.*items)[i].tessOverride = levels; });
}

void execPatchLevels(CommandContext& ctx) { setOwnLevels<Patch, 6>(ctx, &Document::patches, "Patch tessellation override"); }
void execTriangleLevels(CommandContext& ctx) {
    setOwnLevels<TrianglePatch, 4>(ctx, &Document::triangles, "Triangle tessellation override");
}

// `tess-fixed SPACING O0 O1 O2 O3 I0 I1`: the document's levels fixed (adaptivity off, edges
// unlinked), as a lesson or preset leaves them when kept.
void execTessFixed(CommandContext& ctx) {
    const Spacing spacing = *parseSpacing(ctx.word(0));
    const std::array<float, 6> l = levelWords<6>(ctx, 1);
    ctx.session.applyOutsideScene("Keep levels", [&](Document& d) {
        TessSettings& t = d.tess;
        t.adaptive = AdaptiveMode::None;
        t.spacing = spacing;
        t.outer = {l[0], l[1], l[2], l[3]};
        t.inner = {l[4], l[5]};
        t.linked = false;
    });
}

// `adaptive-preset notes|notes-edges|notes-terrain`: a distance formula of the notes as the
// document's adaptive tessellation.
void execAdaptivePreset(CommandContext& ctx) {
    const uint32_t which = ctx.index(0);
    ctx.session.applyOutsideScene(which == 0   ? "Distance formula of the notes"
                                  : which == 1 ? "Distance formula of the notes, per edge"
                                               : "Terrain formula of the notes",
                                  [&](Document& d) {
                                      if (which == 2)
                                          applyNotesTerrainFormula(d.tess);
                                      else
                                          applyNotesDistanceFormula(d.tess, which == 0);
                                  });
}

}  // namespace

void addTessCommands(CommandTable& t) {
    using namespace arg;
    t.add({.name = "patch-levels",
           .label = "Patch Levels",
           .forms = {{patch(), choice("OFF", {"off"})},
                     {patch(), number("O0"), number("O1"), number("O2"), number("O3"), number("I0"), number("I1")}},
           .help = "Give patch P its own outer levels (edges u0, v0, u1, v1) and inner levels (along u and v), 1 to 64, instead of the "
                   "document's; off: the document's again",
           .previewable = true,
           .exec = execPatchLevels});
    t.add({.name = "triangle-levels",
           .label = "Triangle Levels",
           .forms = {{triangle(), choice("OFF", {"off"})}, {triangle(), number("O0"), number("O1"), number("O2"), number("I")}},
           .help = "Give Bézier triangle T its own three outer levels (edges u = 0, v = 0, w = 0) and inner level, 1 to 64; off: the "
                   "document's again",
           .previewable = true,
           .exec = execTriangleLevels});
    t.add({.name = "tess-fixed",
           .label = "Keep Levels",
           .forms = {{choice("SPACING", {"equal", "fractional_odd", "fractional_even", "pow2", "integer"}), number("O0"), number("O1"),
                      number("O2"), number("O3"), number("I0"), number("I1")}},
           .help = "Fix the document's tessellation: adaptivity off, this partitioning, these outer and inner levels (1 to 64), edges "
                   "unlinked (what a kept lesson or preset leaves)",
           .exec = execTessFixed});
    t.add({.name = "adaptive-preset",
           .label = "Distance Formula of the Notes",
           .forms = {{choice("FORMULA", {"notes", "notes-edges", "notes-terrain"})}},
           .help = "A distance formula of the notes as the document's adaptive tessellation: the first notes' 64·saturate((d1−d)/(d1−d0)) "
                   "from each patch's centre (notes) or each edge's midpoint (notes-edges), or the terrain notes' 2^lerp(20, 4, s) "
                   "(notes-terrain)",
           .exec = execAdaptivePreset});
}

}  // namespace commands
}  // namespace pw

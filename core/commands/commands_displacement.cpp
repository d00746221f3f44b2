// Displacement commands (DESIGN §11): the document's height map, scale, bias and mapping, and the
// selected patch's, net's or triangle's own scale and bias. Each is one undo step.
#include <cmath>
#include <filesystem>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/eval/displacement.hpp"
#include "core/model/settings.hpp"

namespace pw {
inline namespace commands {

namespace {

// The map as the document names it: relative to the document's folder when it lies there or below
// (the two move together), else absolute.
std::string documentMapPath(const std::filesystem::path& file, const std::string& documentPath) {
    const std::filesystem::path abs = std::filesystem::absolute(file).lexically_normal();
    if (documentPath.empty()) return abs.string();
    const std::filesystem::path dir = std::filesystem::absolute(documentPath).parent_path().lexically_normal();
    const std::filesystem::path rel = abs.lexically_relative(dir);
    if (!rel.empty() && *rel.begin() != "..") return rel.string();
    return abs.string();
}

// A scale or bias: the settings row's range (core/model/settings), as the panel and the reader take it.
float heightNumber(double v, const char* what) {
    if (auto problem = settingProblem(setting("displacement.scale"), {v})) throw EditError(std::string(what) + ": " + *problem);
    return float(v);
}

void requireMap(const CommandContext& ctx) {
    if (!ctx.session.doc.displacement.active()) throw EditError("the document has no height map; load one with `displacement FILE`");
}

void execDisplacement(CommandContext& ctx) {
    if (ctx.has(0) && ctx.word(0) == "off") {
        requireMap(ctx);
        return ctx.session.apply(
            "Remove height map", [](Document& d) { d.displacement.map.clear(); }, false);
    }
    if (!ctx.has(0)) {
        if (ctx.host.hasWindow()) return ctx.host.fileDialog(FileDialogKind::HeightMap);
        throw EditError("expected 1 argument, got 0 (usage: displacement FILE | off)");  // only a window asks for the file
    }
    const HeightMap map = loadHeightMap(ctx.word(0));  // refused here, naming the file, when unreadable
    const std::string stored = documentMapPath(ctx.word(0), ctx.session.path());
    ctx.session.apply(
        "Height map",
        [&](Document& d) {
            const bool first = !d.displacement.active() && d.displacement.scale == 0.0f;
            d.displacement.map = stored;
            if (first) d.displacement.scale = float(0.05 * modelSize(d));  // visible, not overwhelming
        },
        false);
    ctx.host.status("Height map " + std::to_string(map.width) + " x " + std::to_string(map.height) + ", " + std::to_string(map.bits) +
                    "-bit: " + stored);
}

void execDisplacementScale(CommandContext& ctx) {
    requireMap(ctx);
    const float s = heightNumber(ctx.number(0), "the scale");
    ctx.session.apply(
        "Displacement scale", [&](Document& d) { d.displacement.scale = s; }, false);
}

void execDisplacementBias(CommandContext& ctx) {
    requireMap(ctx);
    const float b = heightNumber(ctx.number(0), "the bias");
    ctx.session.apply(
        "Displacement bias", [&](Document& d) { d.displacement.bias = b; }, false);
}

void execDisplacementMapping(CommandContext& ctx) {
    const DisplacementMapping m = *parseDisplacementMapping(ctx.word(0));  // planar or patch, as the form checked
    ctx.session.apply(
        "Displacement mapping", [&](Document& d) { d.displacement.mapping = m; }, false);
}

void execDisplacementOwn(CommandContext& ctx) {
    std::optional<DisplacementOverride> own;
    if (ctx.form == 0) own = DisplacementOverride{heightNumber(ctx.number(0), "the scale"), heightNumber(ctx.number(1), "the bias")};
    const Selection& sel = ctx.session.sel;
    const auto set = [&](Document& d) {
        if (sel.patch >= 0)
            d.patches[size_t(sel.patch)].displacement = own;
        else if (sel.surface >= 0)
            d.surfaces[size_t(sel.surface)].displacement = own;
        else
            d.triangles[size_t(sel.triangle)].displacement = own;
    };
    if (ctx.preview) {  // while the panel's drag moves: no undo step
        set(ctx.session.doc);
        return ctx.session.changed(false);
    }
    ctx.session.apply("Own displacement", set, false);
}

}  // namespace

void addDisplacementCommands(CommandTable& t) {
    using namespace arg;
    t.add({.name = "displacement",
           .label = "Height Map...",
           .menu = "Display",
           // Without a word the editor window asks for the file; a script names it.
           .forms = {{opt(shown(path(), "FILE|off"))}},
           .help = "Displace the surface along its normal by an 8- or 16-bit PNG height map (off: remove it)",
           .exec = execDisplacement});
    t.add({.name = "displacement-scale",
           .label = "Displacement Scale",
           .forms = {{number("S")}},
           .help = "Height of the map's white above its black, in model units",
           .exec = execDisplacementScale});
    t.add({.name = "displacement-bias",
           .label = "Displacement Bias",
           .forms = {{number("B")}},
           .help = "Height of the map's black, in model units",
           .exec = execDisplacementBias});
    t.add({.name = "displacement-mapping",
           .label = "Displacement Mapping",
           .forms = {{choice("MAPPING", {"planar", "patch"})}},
           .help = "Map UVs: planar over the ground plane (crack-free everywhere) or each patch's parameters (nets tile the map)",
           .exec = execDisplacementMapping});
    t.add({.name = "displacement-own",
           .label = "Own Displacement",
           .forms = {{number("S"), number("B")}, {choice("OFF", {"off"})}},
           .help = "Give the selected patch, net or triangle its own displacement scale and bias (off: the document's again)",
           .previewable = true,
           .enabled = [](const EditSession& s) { return s.sel.patch >= 0 || s.sel.surface >= 0 || s.sel.triangle >= 0; },
           .exec = execDisplacementOwn});
}

}  // namespace commands
}  // namespace pw

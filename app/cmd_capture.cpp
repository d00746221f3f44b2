// Tessellators compared: `patchwork capture -o FILE.json` stores the (u, v) patterns this device's
// tessellator makes for the notes' presets (or given sets) as a capture file
// (core/io/tess_capture_file.hpp), and `render --preset P --compare-device FILE -o fig.png` draws
// this device's pattern beside the file's, the primitives that differ highlighted.
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "app/commands.hpp"
#include "app/level_args.hpp"
#include "app/render_args.hpp"
#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/io/tess_capture_file.hpp"
#include "core/tess/tess_presets.hpp"
#include "render/figures/domain_figure_file.hpp"
#include "render/vk/device.hpp"

namespace pw::app {

namespace {

struct CaptureArgs {
    std::string output, preset, domain, tess, outer, inner, spacing, device;
    bool validation = false;
};

// The sets to capture: the presets named (all of them by default) or one --domain set, under the
// preset's own partitioning, the ones --spacing lists, or all four (`--spacing all`).
std::vector<render::DomainPane> captureSets(const CaptureArgs& a) {
    std::vector<render::DomainPane> base;
    if (!a.domain.empty()) {
        if (!a.preset.empty()) badOption("capture", "--preset", "give either --preset or --domain");
        const auto kind = parseDomain(a.domain);
        if (!kind) badOption("capture", "--domain", "'" + a.domain + "' is not one of quad, tri, isoline");
        base.push_back(
            {*kind, domainLevelsFromArgs("capture", *kind, {a.domain, "", "", a.tess, a.outer, a.inner, "", ""}), Spacing::Equal});
    } else {
        if (!a.tess.empty() || !a.outer.empty() || !a.inner.empty()) badOption("capture", "--outer", "levels go with --domain");
        for (const TessPreset& p : tessPresets())
            if (a.preset.empty() || a.preset == "all") base.push_back({p.kind, p.levels, p.spacing});
        if (a.preset != "all")
            for (const std::string& id : splitList(a.preset)) {
                const TessPreset* p = findTessPreset(id);
                if (!p) badOption("capture", "--preset", "'" + id + "' is not a preset (`patchwork presets` lists them)");
                base.push_back({p->kind, p->levels, p->spacing});
            }
    }
    std::vector<Spacing> spacings;
    if (a.spacing == "all")
        spacings = {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2};
    else
        for (const std::string& s : splitList(a.spacing)) spacings.push_back(parseSpacingOption("capture", "--spacing", s));
    std::vector<render::DomainPane> out;
    const auto add = [&](render::DomainPane p) {
        for (const auto& q : out)
            if (q.kind == p.kind && q.spacing == p.spacing && q.levels == p.levels) return;  // a preset twice
        out.push_back(p);
    };
    for (const render::DomainPane& p : base) {
        if (spacings.empty()) add(p);
        for (Spacing s : spacings) add({p.kind, p.levels, s});
    }
    return out;
}

int runCapture(const CaptureArgs& a) {
    if (lowerExtension(a.output) != ".json") badOption("capture", "-o", "'" + a.output + "': a capture is written as .json");
    (void)checkOutputPath(a.output);
    const std::vector<render::DomainPane> sets = captureSets(a);
    render::DeviceOptions dopt;
    dopt.name = a.device;
    dopt.validation = a.validation;
    render::Device dev(dopt);
    render::DomainView view(dev, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_UNDEFINED, VK_SAMPLE_COUNT_1_BIT);
    TessCaptureFile file;
    file.device = dev.name();
    file.driver = dev.driverDescription();
    file.vulkan = dev.apiVersionText();
    size_t asRules = 0;
    std::ostringstream odd;
    for (const render::DomainPane& p : sets) {
        file.patterns.push_back(view.capture(p));
        const DomainCounts want = expectedDomainCounts(p.kind, p.levels, p.spacing, float(dev.caps().maxTessLevel));
        const size_t made = file.patterns.back().primitives();
        if (made == want.primitives)
            ++asRules;
        else
            odd << "  " << describeSet(p.kind, p.spacing, p.levels) << ": " << made << " primitives, the rules say " << want.primitives
                << "\n";
    }
    writeFileAtomic(a.output, writeTessCaptureFile(file));
    std::cout << "wrote " << a.output << ": " << sets.size() << " patterns from " << file.device << " (" << file.driver << ", Vulkan "
              << file.vulkan << "); " << asRules << " of " << sets.size() << " have the primitive count the rules predict\n"
              << odd.str();
    return validationExitCode(dev, "capture");
}

}  // namespace

int runDeviceComparison(const RenderArgs& a, const std::vector<render::DomainPane>& panes, unsigned w, unsigned h) {
    if (panes.size() != 1) badOption("render", "--compare-device", "compares one set: one preset, or one --domain set");
    const render::DomainPane& pane = panes.front();
    const TessCaptureFile file = loadTessCaptureFile(a.compareDevice);
    const TessPattern* other = file.find(pane.kind, pane.spacing, pane.levels);
    if (!other) {
        std::string held;
        for (size_t i = 0; i < file.patterns.size() && i < 6; ++i)
            held += (i ? "; " : "") + describeSet(file.patterns[i].kind, file.patterns[i].spacing, file.patterns[i].levels);
        if (file.patterns.size() > 6) held += "; ...";
        throw InputError(a.compareDevice, "no capture of " + describeSet(pane.kind, pane.spacing, pane.levels) + " (it holds " +
                                              std::to_string(file.patterns.size()) + ": " + held +
                                              "); `patchwork capture` on that device makes one");
    }
    render::DeviceOptions dopt;
    dopt.name = a.device;
    dopt.validation = a.validation;
    render::Device dev(dopt);
    const render::DeviceComparison c = render::encodeDeviceComparison(dev, a.output, w, h, pane, *other, file.device);
    OutputBatch out;
    out.stage(a.output, c.bytes);
    const auto side = [](const TessPattern& p, size_t differ, size_t pointsOnly) {
        return nlohmann::json{{"points", p.distinctPoints().size()},
                              {"primitives", p.primitives()},
                              {"primitivesDiffering", differ},
                              {"pointsElsewhereMissing", pointsOnly}};
    };
    if (!a.stats.empty()) {
        nlohmann::json j{{"set", describeSet(pane.kind, pane.spacing, pane.levels)},
                         {"identical", c.diff.identical()},
                         {"sameOrder", c.diff.sameOrder},
                         {"windingFlips", c.diff.windingFlips}};
        j["this"] = side(c.mine, c.diff.primitivesOnlyA, c.diff.pointsOnlyA);
        j["this"]["device"] = dev.name();
        j["other"] = side(*other, c.diff.primitivesOnlyB, c.diff.pointsOnlyB);
        j["other"]["device"] = file.device;
        out.stage(a.stats, j.dump(2) + "\n");
    }
    out.commit();
    const char* word = pane.kind == DomainKind::Isoline ? " segments" : " triangles";
    std::cout << "wrote " << a.output << ": " << describeSet(pane.kind, pane.spacing, pane.levels) << "\n  " << dev.name() << ": "
              << c.mine.distinctPoints().size() << " points, " << c.mine.primitives() << word << ", " << c.diff.primitivesOnlyA
              << " not in the other\n  " << file.device << ": " << other->distinctPoints().size() << " points, " << other->primitives()
              << word << ", " << c.diff.primitivesOnlyB << " not in this one\n  "
              << (!c.diff.identical() ? "the patterns differ"
                  : c.diff.sameOrder  ? "the same pattern, emitted in the same order"
                                      : "the same triangles, emitted in another order (the numbers)")
              << " (" << c.diff.pointsOnlyA << " points only here, " << c.diff.pointsOnlyB << " only there, " << c.diff.windingFlips
              << " triangles wound the other way)\n";
    return validationExitCode(dev, "render");
}

void registerCaptureCommand(CLI::App& app, Action& run) {
    const auto [cmd, a] = addSubcommand<CaptureArgs>(
        app, run, "capture",
        "Capture the (u,v) patterns this device's tessellator makes (transform feedback) into a file for render --compare-device",
        runCapture);
    cmd->add_option("-o,--output", a->output, "Capture file to write (.json)")->required();
    cmd->add_option("--preset", a->preset, "Preset id(s), comma-separated, or all (the default; see `patchwork presets`)");
    cmd->add_option("--domain", a->domain, "One set instead: quad | tri | isoline, levels from --tess/--outer/--inner");
    cmd->add_option("--tess", a->tess, "With --domain: every level");
    cmd->add_option("--outer", a->outer, "With --domain: outer levels (quad 4, tri 3, isoline 2)");
    cmd->add_option("--inner", a->inner, "With --domain: inner levels (quad 2, tri 1)");
    cmd->add_option("--spacing", a->spacing,
                    "Partitioning(s), comma-separated, or all: equal (integer), fractional_odd, fractional_even, pow2 (default: the "
                    "preset's own; equal for --domain)");
    cmd->add_option("--device", a->device, "Vulkan device: substring of its name");
    cmd->add_flag("--validation", a->validation, "Enable the Vulkan validation layer (also PATCHWORK_VALIDATION=1)");
}

}  // namespace pw::app

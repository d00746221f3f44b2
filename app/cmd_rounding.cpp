// `patchwork rounding [--levels L,L,...] [-o table.svg|.pdf|.png]`: the notes' rounding table, what
// each partitioning makes of each level (segments of one edge, the slide of the two short ones),
// printed and, with -o, drawn as a slide.
#include <iostream>

#include "app/commands.hpp"
#include "app/level_args.hpp"
#include "core/base/file_io.hpp"
#include "core/tess/tess_domain.hpp"
#include "render/figures/rounding_figure.hpp"

namespace pw::app {

namespace {

struct RoundingArgs {
    std::string levels, output, size = "1280x720";
};

int runRounding(const RoundingArgs& a) {
    std::vector<float> levels = notesRoundingLevels();
    if (!a.levels.empty()) {
        levels.clear();
        for (const std::string& l : splitList(a.levels)) levels.push_back(parseLevel("rounding", "--levels", l));
        if (levels.empty() || levels.size() > 12) badOption("rounding", "--levels", "expected 1 to 12 comma-separated levels");
    }
    const std::vector<RoundingRow> rows = roundingTable(levels);
    if (!a.output.empty()) {
        (void)checkOutputPath(a.output);
        const auto [w, h] = parseImageSize("rounding", a.size);
        OutputBatch out;
        out.stage(a.output, render::roundingTableFigure(render::vectorFormatFor(a.output), a.output, w, h, rows));
        out.commit();
    }
    for (const std::string& line : render::roundingTableLines(rows)) std::cout << line << "\n";
    if (!a.output.empty()) std::cout << "wrote " << a.output << "\n";
    return 0;
}

}  // namespace

void registerRoundingCommand(CLI::App& app, Action& run) {
    const auto [cmd, a] = addSubcommand<RoundingArgs>(
        app, run, "rounding",
        "The notes' rounding table: the segments each partitioning makes of each level, and how far the two short ones have slid",
        runRounding);
    cmd->add_option("--levels", a->levels, "Comma-separated levels 1..64 (default the notes' 3, 3.25, 3.75, 4.25, 4.75, 5)");
    cmd->add_option("-o,--output", a->output, "Also draw the table as a slide: .svg, .pdf or .png");
    cmd->add_option("--size", a->size, "Slide size WIDTHxHEIGHT (default 1280x720)");
}

}  // namespace pw::app

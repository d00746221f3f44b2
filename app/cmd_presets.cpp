// `patchwork presets`: the teaching presets (factor sets of the lecture notes) with their ids for
// `render --preset` and `sweep --preset`, and the expected vertex and primitive counts.
#include <iomanip>
#include <iostream>

#include "app/commands.hpp"
#include "core/tess/tess_presets.hpp"

namespace pw::app {

void registerPresetsCommand(CLI::App& app, Action& run) {
    CLI::App* cmd = app.add_subcommand("presets", "List the tessellation presets of the lecture notes (ids for render/sweep --preset)");
    cmd->callback([&run] {
        run = [] {
            for (const TessPreset& p : tessPresets()) {
                const DomainCounts c = expectedDomainCounts(p.kind, p.levels, p.spacing);
                std::cout << std::left << std::setw(36) << p.name << std::setw(34) << p.label << std::right << std::setw(4) << c.vertices
                          << " vertices " << std::setw(4) << c.primitives << " primitives  " << p.note << "\n";
            }
            std::cout << "Model presets in the editor: the notes' Bézier patch (16 control points; version 1 at level 25, version 2 "
                         "at 15; `render --notes-patch 1|2`, `open-notes-patch 1|2`), the notes' distance formula "
                         "64*saturate((d1-d)/(d1-d0)), d0 = 20, d1 = 100, from the patch centre (`--adaptive notes`) or per edge "
                         "(`notes-edges`), and the terrain notes' 2^lerp(20, 4, s) over 10..200 (`notes-terrain`, "
                         "data/terrain_notes.patchwork). The rounding table: `patchwork rounding`.\n";
            return 0;
        };
    });
}

}  // namespace pw::app

// The options `patchwork render` and `patchwork sweep` share (document, levels, spacing, adaptive,
// shading, overlays, view, domain figures, device), parsed into renderer settings.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/displacement_args.hpp"
#include "app/domain_args.hpp"
#include "core/model/document.hpp"
#include "render/scene/renderer.hpp"

namespace pw::app {

struct RenderArgs {
    std::string input, output = "", size = "1280x720", tess, outer, inner, spacing, adaptive, shading, overlay, view, stats, device,
                       targetPx, maxLevel, domain, preset, compare, isolines, combJoin, compareDevice, eye, target, origin, theme, distance;
    std::string distanceCurve, distanceExponents, distanceFrom;  // distance mode's curve and where it measures
    std::string debugCamera;            // auto or X,Y,Z: draw from there, levels and culling still from the view's camera
    std::string mergeWindows = "auto";  // auto | never | always (render/scene/merged_blocks.hpp)
    std::string math;                   // render --math U,V: the Bézier math of patch mathPatch drawn over the model
    int mathPatch = 0;
    int notesPatch = 0;
    double nearFar = 0.0;  // render --near-far F: the view beside the same view F times farther (0: off)  // render --notes-patch 1|2: the
                           // notes' patch instead of a file (0: none)
    bool cull = false, validation = false, noMsaa = false, cullFar = false, stageBars = false;
    DisplacementArgs displacement;
};

// Registers every shared option on `cmd` (not -o: each command says what it writes).
void addRenderOptions(CLI::App* cmd, RenderArgs& a);
// The document's settings with the command-line ones on top, all validated (InputError on bad ones).
render::RenderOptions buildRenderOptions(const RenderArgs& a, const Document& doc, uint32_t width, uint32_t height);
DomainArgs domainArgs(const RenderArgs& a);
// `render --compare-device FILE` (app/cmd_capture.cpp): this device's pattern of the one pane beside
// the capture file's, written to a.output.
int runDeviceComparison(const RenderArgs& a, const std::vector<render::DomainPane>& panes, unsigned width, unsigned height);
// 1 (after saying so on stderr) when the validation layer reported anything, else 0.
int validationExitCode(const render::Device& dev, const std::string& command);

}  // namespace pw::app

// A domain figure as a file, shared by `patchwork render --domain` and the editor's domain view:
// PNG (rendered and labelled), or SVG / PDF by the output's extension (render/figures/figure_vector.hpp);
// and the comparison of this device's pattern with another device's capture (`--compare-device`).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/tess/tess_pattern.hpp"
#include "render/domain/domain_view.hpp"
#include "render/vk/device.hpp"

namespace pw::render {
inline namespace figures {

struct DomainFigureFile {
    std::string bytes;               // the file's contents
    std::vector<DomainStats> stats;  // per pane, from the rendered figure
};

DomainFigureFile encodeDomainFigure(Device& dev, const std::filesystem::path& output, uint32_t width, uint32_t height,
                                    const std::vector<DomainPane>& panes, bool msaa);

// This device's pattern for `pane` beside `other` (the same set, from a capture file made on
// `otherDevice`), each titled by its device, the primitives that differ filled in the highlight
// colour in both, each triangle numbered in the order its device emitted it (where it fits): PNG,
// SVG or PDF by the output's extension.
struct DeviceComparison {
    std::string bytes;
    TessPattern mine;
    PatternDiff diff;  // a: this device, b: the other
};
DeviceComparison encodeDeviceComparison(Device& dev, const std::filesystem::path& output, uint32_t width, uint32_t height,
                                        const DomainPane& pane, const TessPattern& other, const std::string& otherDevice);

}  // namespace figures
}  // namespace pw::render

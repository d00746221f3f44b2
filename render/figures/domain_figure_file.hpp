// A domain figure as a file, shared by `patchwork render --domain` and the editor's domain view:
// PNG (rendered and labelled), or SVG / PDF by the output's extension (render/figures/figure_vector.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "render/domain/domain_view.hpp"
#include "render/vk/device.hpp"

namespace pw::render {

struct DomainFigureFile {
    std::string bytes;               // the file's contents
    std::vector<DomainStats> stats;  // per pane, from the rendered figure
};

DomainFigureFile encodeDomainFigure(Device& dev, const std::filesystem::path& output, uint32_t width, uint32_t height,
                                    const std::vector<DomainPane>& panes, bool msaa);

}  // namespace pw::render

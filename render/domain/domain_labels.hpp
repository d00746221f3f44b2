// Where the domain view's words go: each outer edge labelled with its level (and the segment count
// the partitioning rounds it to, where that differs), and a caption with the inner levels, the
// partitioning and the vertex and primitive counts, and a title naming the domain (and, in figures,
// the device that drew it). Used by the headless figures (drawn with
// LabelRaster) and by the editor's domain panel (drawn by ImGui), so both say the same.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "render/domain/domain_view.hpp"

namespace pw::render {
inline namespace domain {

struct DomainLabel {
    enum class Role { Edge, Caption, Title };
    Role role = Role::Edge;
    float x = 0, y = 0;    // anchor point in target pixels
    float ax = 0, ay = 0;  // anchor within the text box (0 left/top .. 1 right/bottom)
    std::string text;
};

// A level as a lecturer writes it: "4", "4.5", "4.25" (at most two decimals).
std::string formatLevel(float level);

// Labels for the domain drawn with `o`; `counts` are the vertices and primitives to show (the GPU's
// pipeline statistics, or the rules' prediction where the device has none); `textPixels` is the
// line height the caller draws with (captions stack below the domain by it).
// `widthOf` (optional) measures a text at `textPixels`: a caption wider than the pane is then split
// into two lines (levels and partitioning; counts), so neighbouring panes' captions never meet.
std::vector<DomainLabel> domainLabels(const DomainViewOptions& o, uint64_t vertices, uint64_t primitives, float textPixels,
                                      const std::function<float(const std::string&)>& widthOf = {});

// Panes that compare partitionings are titled by them ("fractional_odd"), the lecture's way; one
// pane, or panes of one partitioning, keep the domain's name. Sets each pane's `title`.
void titleByPartitioning(std::vector<DomainViewOptions>& panes);

// The margin a domain view needs around the domain for its labels at this text size.
float domainLabelMargin(float textPixels);

}  // namespace domain
}  // namespace pw::render

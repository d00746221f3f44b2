// `--domain`, `--preset`, `--compare` and the level options of render and sweep turned into the
// panes of a domain figure (render/figures/domain_figure.hpp).
#pragma once

#include <string>
#include <vector>

#include "render/figures/domain_figure.hpp"

namespace pw::app {

struct DomainArgs {
    std::string domain;   // quad | tri | isoline
    std::string preset;   // comma-separated preset ids (one pane each)
    std::string compare;  // comma-separated partitionings (one pane each, same levels)
    std::string tess, outer, inner, spacing;
    std::string origin;  // upper-left | lower-left (default)
};

bool wantsDomain(const DomainArgs& a);

// One to four panes; throws InputError naming `command` and the option at fault.
std::vector<render::DomainPane> domainPanes(const std::string& command, const DomainArgs& a);

// The levels for a domain from --tess / --outer / --inner (quad: 4 outer, 2 inner; tri: 3 and 1;
// isoline: 2 outer, no inner); default 4 everywhere.
DomainLevels domainLevelsFromArgs(const std::string& command, DomainKind kind, const DomainArgs& a);

}  // namespace pw::app

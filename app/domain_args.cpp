#include "app/domain_args.hpp"

#include "app/level_args.hpp"
#include "core/tess/tess_presets.hpp"

namespace pw::app {

bool wantsDomain(const DomainArgs& a) { return !a.domain.empty() || !a.preset.empty(); }

DomainLevels domainLevelsFromArgs(const std::string& command, DomainKind kind, const DomainArgs& a) {
    const size_t nOuter = size_t(outerLevelCount(kind)), nInner = size_t(innerLevelCount(kind));
    const std::string name(domainName(kind));
    DomainLevels l;
    if (!a.tess.empty()) {
        if (!a.outer.empty() || !a.inner.empty()) badOption(command, "--tess", "use either --tess or --outer/--inner");
        const float v = parseLevel(command, "--tess", a.tess);
        l.outer = {v, v, v, v};
        l.inner = {v, v};
    }
    if (!a.outer.empty()) {
        const auto v = parseLevels(command, "--outer", a.outer, nOuter, true);  // 0: the patch is culled
        for (size_t i = 0; i < nOuter; ++i) l.outer[i] = v[i];
    }
    if (!a.inner.empty()) {
        if (nInner == 0) badOption(command, "--inner", "the isoline domain has no inner levels");
        const auto v = parseLevels(command, "--inner", a.inner, nInner);
        for (size_t i = 0; i < nInner; ++i) l.inner[i] = v[i];
    }
    for (size_t i = nOuter; i < 4; ++i) l.outer[i] = 0.0f;  // unused by this domain
    for (size_t i = nInner; i < 2; ++i) l.inner[i] = 0.0f;
    return l;
}

std::vector<render::DomainPane> domainPanes(const std::string& command, const DomainArgs& a) {
    std::vector<render::DomainPane> panes;
    if (!a.preset.empty()) {
        if (!a.domain.empty() || !a.tess.empty() || !a.outer.empty() || !a.inner.empty())
            badOption(command, "--preset", "a preset sets the domain and levels; leave out --domain, --tess, --outer, --inner");
        for (const std::string& id : splitList(a.preset)) {
            const TessPreset* p = findTessPreset(id);
            if (!p) badOption(command, "--preset", "'" + id + "' is not a preset (`patchwork presets` lists them)");
            panes.push_back({p->kind, p->levels, p->spacing});
        }
    } else {
        const auto kind = parseDomain(a.domain);
        if (!kind) badOption(command, "--domain", "'" + a.domain + "' is not one of quad, tri, isoline");
        panes.push_back({*kind, domainLevelsFromArgs(command, *kind, a), Spacing::Equal});
    }
    if (!a.spacing.empty()) {
        const Spacing s = parseSpacingOption(command, "--spacing", a.spacing);
        for (auto& p : panes) p.spacing = s;
    }
    if (!a.compare.empty()) {
        if (panes.size() != 1) badOption(command, "--compare", "compare partitionings of one level set (one preset)");
        const render::DomainPane base = panes.front();
        panes.clear();
        for (const PaneSpec& spec : parsePaneSpecs(command, "--compare", a.compare)) {
            render::DomainPane p = base;
            p.spacing = spec.spacing;
            if (spec.level > 0.0f) p.levels = withUniformLevel(p.levels, spec.level);  // the pane's own level
            panes.push_back(p);
        }
    }
    if (!a.origin.empty()) {
        const auto upperLeft = parseDomainOrigin(a.origin);
        if (!upperLeft)
            badOption(command, "--origin", "'" + a.origin + "' is not one of upper-left (D3D, Vulkan's default), lower-left (GL)");
        for (auto& p : panes) p.upperLeft = *upperLeft;
    }
    if (panes.empty() || panes.size() > 4) badOption(command, a.compare.empty() ? "--preset" : "--compare", "give 1 to 4 panes");
    return panes;
}

}  // namespace pw::app

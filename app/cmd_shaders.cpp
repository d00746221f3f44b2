// `patchwork shaders`: the GLSL of the tessellation pipelines that `render` (or the editor) would
// use with the given settings, stage by stage, with the glslc defines of each variant and the lines
// those defines switch off marked. The same listing as the editor's shader panel.
#include <cstdio>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/domain_args.hpp"
#include "app/level_args.hpp"
#include "app/render_args.hpp"
#include "core/io/document_io.hpp"
#include "render/scene/shader_listing.hpp"

namespace pw::app {
namespace {

struct ShadersArgs {
    RenderArgs render;
    std::string stage, variant;
    bool list = false, activeOnly = false, teaching = false;
};

bool stageMatches(const std::string& stage, const std::string& filter) {
    if (filter.empty()) return true;
    static const std::pair<const char*, const char*> kShort[] = {{"vert", "vertex"},
                                                                 {"tesc", "tessellation control"},
                                                                 {"tese", "tessellation evaluation"},
                                                                 {"geom", "geometry"},
                                                                 {"frag", "fragment"}};
    for (const auto& [s, full] : kShort)
        if (filter == s) return stage.starts_with(full);
    return stage.starts_with(filter);
}

void printListing(const render::ShaderListing& l, bool activeOnly, bool teaching) {
    if (teaching) {  // the short listing of a slide: the marked parts only
        const auto lines = render::teachingListing(l);
        std::cout << "// " << l.variant << ", the parts a lecture shows" << (lines.empty() ? ": none marked" : "") << "\n";
        for (const auto& line : lines) std::cout << line.text << "\n";
        std::cout.flush();
        return;
    }
    std::cout << "// " << l.variant << ": " << l.source << ", glslc --target-env=vulkan1.3 -O";
    for (const auto& d : l.defines) std::cout << " " << d;
    std::cout << "\n// '-' marks lines the defines switch off; included files are shown inline\n";
    for (const auto& line : l.lines) {
        if (activeOnly && !line.active) continue;
        const std::string where = line.file + ":" + std::to_string(line.line);
        std::printf("%-22s %c %s\n", where.c_str(), line.active ? ' ' : '-', line.text.c_str());
    }
    std::fflush(stdout);
}

int runShaders(const ShadersArgs& a) {
    if (!a.variant.empty()) {
        const auto l = render::shaderListing(a.variant);
        if (!l) badOption("shaders", "--variant", "'" + a.variant + "' is not a compiled variant (see `patchwork shaders --list`)");
        printListing(*l, a.activeOnly, a.teaching);
        return 0;
    }
    if (!a.stage.empty()) {
        bool known = false;
        for (const char* s : {"vert", "tesc", "tese", "geom", "frag", "vertex", "tessellation", "geometry", "fragment"})
            known = known || a.stage == s;
        if (!known) badOption("shaders", "--stage", "'" + a.stage + "' is not one of vert, tesc, tese, geom, frag");
    }
    render::ShaderContext c;
    const DomainArgs dargs = domainArgs(a.render);
    if (wantsDomain(dargs)) {
        if (!a.render.input.empty()) badOption("shaders", "--domain", "a domain figure draws no document; leave out the file");
        for (const auto& p : domainPanes("shaders", dargs)) c.domainPanes.emplace_back(p.kind, p.spacing);
        c.windows = false;
    } else {
        const Document doc = a.render.input.empty() ? builtinTeapot() : loadDocument(a.render.input);
        const render::RenderOptions o = buildRenderOptions(a.render, doc, 1280, 720);
        c.tess = o.tess;
        c.display = o.display;
        c.windows = !doc.patches.empty() || !doc.surfaces.empty();
        c.triangles = !doc.triangles.empty();
        c.curves = !doc.curves.empty();
    }
    for (const render::PipelineUse& p : render::pipelinesInUse(c)) {
        std::cout << "== " << p.name << "\n   " << p.why << "\n";
        for (const render::StageUse& s : p.stages) {
            if (!stageMatches(s.stage, a.stage)) continue;
            std::cout << "-- " << s.stage << ": " << s.variant << "\n";
            if (a.list) continue;
            if (const auto l = render::shaderListing(s.variant)) printListing(*l, a.activeOnly, a.teaching);
        }
    }
    return 0;
}

}  // namespace

void registerShadersCommand(CLI::App& app, Action& run) {
    const auto [cmd, a] = addSubcommand<ShadersArgs>(
        app, run, "shaders", "Print the GLSL of the tessellation pipelines the given settings use, with their defines", runShaders);
    addRenderOptions(cmd, a->render);
    cmd->add_option("--stage", a->stage, "Only this stage: vert | tesc | tese | geom | frag");
    cmd->add_option("--variant", a->variant, "Print one compiled variant by name instead");
    cmd->add_flag("--list", a->list, "List the pipelines and their stage variants without the source");
    cmd->add_flag("--active-only", a->activeOnly, "Leave out the lines the defines switch off");
    cmd->add_flag("--teaching", a->teaching,
                  "The short listing a slide shows: only the parts marked for teaching (the evaluation shader's Bernstein sum, the "
                  "tessellator layout, main), defines substituted");
}

}  // namespace pw::app

// `patchwork render [FILE] -o out.png ...`: renders a document headlessly on the GPU tessellation
// pipeline (offscreen Vulkan target) and writes a PNG, optionally with frame statistics as JSON.
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/domain_args.hpp"
#include "app/level_args.hpp"
#include "app/render_args.hpp"
#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/limits.hpp"
#include "core/eval/bezier_math.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/io/document_io.hpp"
#include "core/io/formats.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/model/camera_math.hpp"
#include "core/tess/tess_presets.hpp"
#include "render/figures/domain_figure.hpp"
#include "render/figures/domain_figure_file.hpp"
#include "render/figures/figure_vector.hpp"
#include "render/figures/level_legend.hpp"
#include "render/figures/math_figure.hpp"
#include "render/figures/model_figure.hpp"
#include "render/figures/stage_bars.hpp"
#include "render/scene/renderer.hpp"
#include "render/targets/offscreen_target.hpp"
#include "render/targets/png_writer.hpp"
#include "render/vk/device.hpp"

namespace pw::app {

namespace {

[[noreturn]] void bad(const std::string& option, const std::string& what) { badOption("render", option, what); }
float renderLevel(const std::string& option, const std::string& text) { return app::parseLevel("render", option, text); }
std::vector<float> renderLevels(const std::string& option, const std::string& text, size_t count) {
    return app::parseLevels("render", option, text, count);
}

// --debug-camera auto|X,Y,Z: the camera so far becomes the one that decides levels and culling;
// the picture is drawn from X,Y,Z (auto: behind, beside and above it, far enough back to frame the
// model and that camera's eye), looking at the middle of the model and the eye.
void applyDebugCamera(const std::string& text, const Document& doc, double aspect, render::RenderOptions& o) {
    o.lodCamera = o.camera;
    const ViewMatrices lod = viewMatrices(o.camera, aspect);
    Bounds box = computeBounds(doc.points);
    box.add(Vec3(lod.eye.x, lod.eye.y, lod.eye.z));
    const glm::dvec3 lo(box.min.x, box.min.y, box.min.z), hi(box.max.x, box.max.y, box.max.z), centre = 0.5 * (lo + hi);
    glm::dvec3 eye;
    if (text == "auto") {
        const glm::dvec3 up = o.camera.zUp ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
        glm::dvec3 side = glm::cross(glm::dvec3(lod.forward), up);
        side = glm::length(side) > 1e-9 ? glm::normalize(side) : glm::dvec3(1, 0, 0);
        eye = centre + glm::length(hi - lo) * (0.9 * side + 0.8 * up - 0.5 * glm::dvec3(lod.forward));
    } else {
        eye = parsePoint("render", "--debug-camera", text);
    }
    const auto cam = lookFrom(o.camera, eye, centre);
    if (!cam) bad("--debug-camera", "the debug camera is at the middle of the scene; give another point");
    o.camera = text == "auto" ? frameBounds(*cam, box, aspect, 1.05) : *cam;
}

}  // namespace

render::RenderOptions buildRenderOptions(const RenderArgs& a, const Document& doc, uint32_t width, uint32_t height) {
    render::RenderOptions o = render::optionsFromDocument(doc);
    o.display.showGrid = o.display.showWireframe = o.display.showNormals = o.display.showBoundaries = false;
    if (!a.tess.empty()) {
        if (!a.outer.empty() || !a.inner.empty()) bad("--tess", "use either --tess or --outer/--inner");
        const float l = renderLevel("--tess", a.tess);
        o.tess.outer = {l, l, l, l};
        o.tess.inner = {l, l};
        o.tess.adaptive = AdaptiveMode::None;
    }
    if (!a.outer.empty()) {
        auto v = renderLevels("--outer", a.outer, 4);
        o.tess.outer = {v[0], v[1], v[2], v[3]};
        if (a.inner.empty()) o.tess.inner = {std::max(v[1], v[3]), std::max(v[0], v[2])};
        o.tess.adaptive = AdaptiveMode::None;
    }
    if (!a.inner.empty()) {
        auto v = renderLevels("--inner", a.inner, 2);
        o.tess.inner = {v[0], v[1]};
        o.tess.adaptive = AdaptiveMode::None;
    }
    if (!a.spacing.empty()) {
        o.tess.spacing = parseSpacingOption("render", "--spacing", a.spacing);
    }
    if (a.adaptive == "notes" || a.adaptive == "notes-edges") {  // the first notes' 64 saturate((100 - d) / (100 - 20)), 0 culls
        applyNotesDistanceFormula(o.tess, a.adaptive == "notes");
    } else if (a.adaptive == "notes-terrain") {  // 2^lerp(20, 4, s), edges from midpoints, inner from the centre
        applyNotesTerrainFormula(o.tess);
    } else if (!a.adaptive.empty()) {
        auto m = parseAdaptive(a.adaptive);
        if (!m)
            bad("--adaptive", "'" + a.adaptive + "' is not one of none, distance, screen, orientation, notes, notes-edges, notes-terrain");
        o.tess.adaptive = *m;
    }
    if (!a.distanceCurve.empty()) {
        const auto c = parseDistanceCurve(a.distanceCurve);
        if (!c) bad("--distance-curve", "'" + a.distanceCurve + "' is not one of linear, pow2");
        o.tess.distanceCurve = *c;
    }
    if (!a.distanceExponents.empty()) {
        const auto v = parseNumbers("render", "--distance-exponents", a.distanceExponents, 2, limits::kMinDistanceExponent,
                                    limits::kMaxDistanceExponent, "NEAR,FAR exponents");
        o.tess.distanceExponents = {float(v[0]), float(v[1])};
    }
    if (!a.distanceFrom.empty()) {
        const auto f = parseDistanceFrom(a.distanceFrom);
        if (!f) bad("--distance-from", "'" + a.distanceFrom + "' is not one of edges, centre, edges-inner-centre");
        o.tess.distanceFrom = *f;
    }
    if (!a.distance.empty()) {
        const auto v = parseNumbers("render", "--distance", a.distance, 2, 0.0, limits::kMaxCoordinate, "NEAR,FAR");
        o.tess.distanceNear = float(v[0]);
        o.tess.distanceFar = float(v[1]);
        if (o.tess.distanceFar <= o.tess.distanceNear) bad("--distance", "FAR must be beyond NEAR");
    }
    if (a.cullFar) o.tess.cullFar = true;
    if (!a.targetPx.empty()) {
        o.tess.targetPixels = float(parseNumber("render", "--target-px", a.targetPx, 0.5, 1000.0));
    }
    if (!a.maxLevel.empty()) o.tess.maxLevel = renderLevel("--max-level", a.maxLevel);
    if (!a.isolines.empty()) {
        const auto v = renderLevels("--isolines", a.isolines, 2);
        o.tess.isolineLevels = {v[0], v[1]};
    }
    if (!a.combJoin.empty()) {
        const double j = parseNumber("render", "--comb-join", a.combJoin, 0.0, 1e9);
        if (j != std::floor(j) || j >= double(doc.joins.size()))
            bad("--comb-join", "'" + a.combJoin + "' is not a join of the document (it has " + std::to_string(doc.joins.size()) + ")");
        o.combJoin = int(j);
        o.display.showCombs = true;
    }
    if (a.cull) o.tess.cullBackfaces = true;
    if (!a.shading.empty()) {
        std::optional<ShadingMode> s = a.shading == "curvature" ? std::optional(ShadingMode::GaussCurvature) : parseShading(a.shading);
        if (!s) bad("--shading", "'" + a.shading + "' is not one of lit, normal, patch, uv, zebra, curvature, gauss, mean, level");
        o.display.shading = *s;
    }
    for (const std::string& ov : splitList(a.overlay)) {
        if (ov == "grid")
            o.display.showGrid = true;
        else if (ov == "wire")
            o.display.showWireframe = true;
        else if (ov == "normals")
            o.display.showNormals = true;
        else if (ov == "boundaries")
            o.display.showBoundaries = true;
        else if (ov == "isocurves")
            o.display.showIsocurves = true;
        else if (ov == "combs")
            o.display.showCombs = true;
        else if (ov != "none")
            bad("--overlay", "'" + ov + "' is not one of grid, wire, normals, boundaries, isocurves, combs, none");
    }
    // Combs are drawn on curves and on the isocurve overlay: with neither they would draw nothing.
    if (o.display.showCombs && a.combJoin.empty() && !o.display.showIsocurves && doc.curves.empty())
        bad("--overlay",
            "combs are drawn on curves and on the isocurve overlay, and the document has no curves: add isocurves "
            "(--overlay isocurves,combs)");
    const double aspect = double(width) / double(height);
    // Slides: a light background, a grey wire and the model framed tightly (with a named view).
    const bool light = a.theme == "light";
    if (!a.theme.empty() && !light && a.theme != "dark") bad("--theme", "'" + a.theme + "' is not one of dark, light");
    if (light) {
        o.display.background = {0.97f, 0.97f, 0.95f};
        o.wireColor = {0.42f, 0.45f, 0.52f, 1.0f};
    }
    if (!a.eye.empty() || !a.target.empty()) {
        if (!a.view.empty()) bad(a.eye.empty() ? "--target" : "--eye", "use either --view or --eye/--target");
        const Bounds box = computeBounds(doc.points);
        const glm::dvec3 centre = 0.5 * (glm::dvec3(box.min.x, box.min.y, box.min.z) + glm::dvec3(box.max.x, box.max.y, box.max.z));
        const glm::dvec3 target = a.target.empty() ? centre : parsePoint("render", "--target", a.target);
        if (a.eye.empty()) {  // the document's view direction and distance, aimed at the target
            o.camera.target = {target.x, target.y, target.z};
        } else {
            const auto cam = lookFrom(o.camera, parsePoint("render", "--eye", a.eye), target);
            if (!cam) bad("--eye", "the eye is at the target; give two different points");
            o.camera = *cam;
        }
    } else if (!a.view.empty()) {
        auto cam = applyNamedView(doc.camera, a.view);
        if (!cam) bad("--view", "'" + a.view + "' is not one of front, back, left, right, top, bottom, iso");
        o.camera = frameBounds(*cam, computeBounds(doc.points), aspect);
    } else if (doc.camera == Camera{}) {
        o.camera = frameBounds(doc.camera, computeBounds(doc.points), aspect);
    }
    if (light && a.eye.empty()) {  // the surface itself (not its control net) fills the frame
        std::vector<glm::dvec3> surface;
        for (const auto& p : tessellateDocument(doc, 6).positions) surface.emplace_back(p[0], p[1], p[2]);
        o.camera = frameTightly(o.camera, surface, aspect);
    }
    if (!a.debugCamera.empty()) applyDebugCamera(a.debugCamera, doc, aspect, o);
    if (a.mergeWindows == "never")
        o.mergeWindows = render::MergeWindows::Never;
    else if (a.mergeWindows == "always")
        o.mergeWindows = render::MergeWindows::Always;
    else if (a.mergeWindows != "auto")
        bad("--merge-windows", "'" + a.mergeWindows + "' is not one of auto, never, always");
    o.display.normalLength = float(0.03 * modelSize(doc));
    return o;
}

namespace {

// `render --domain/--preset`: the parametric domain tessellated by the GPU, labelled.
int runDomainRender(const RenderArgs& a, const std::vector<render::DomainPane>& panes, unsigned w, unsigned h) {
    render::DeviceOptions dopt;
    dopt.name = a.device;
    dopt.validation = a.validation;
    int rc = 0;
    {
        render::Device dev(dopt);
        const render::DomainFigureFile figure = render::encodeDomainFigure(dev, a.output, w, h, panes, !a.noMsaa);
        const auto& stats = figure.stats;
        // The figure and the stats appear together or not at all; what was written is said after.
        OutputBatch out;
        out.stage(a.output, figure.bytes);
        std::ostringstream said;
        nlohmann::json j;
        j["device"] = dev.name();
        for (size_t i = 0; i < panes.size(); ++i) {
            const auto& p = panes[i];
            const DomainCounts want = expectedDomainCounts(p.kind, p.levels, p.spacing, float(dev.caps().maxTessLevel));
            const auto shown = render::shownCounts(stats[i], p);
            said << "wrote " << a.output << " pane " << i + 1 << ": " << domainName(p.kind) << " " << spacingName(p.spacing) << ", "
                 << (want.culled ? "culled (an outer level is 0: the tessellator discards the patch, nothing is drawn), " : "") << shown[0]
                 << " vertices, " << shown[1] << " primitives";
            if (stats[i].valid)
                said << " (GPU: " << stats[i].primitives << " primitives, " << stats[i].vertices << " evaluations)";
            else
                said << " (rules; the device has no pipeline statistics)";
            said << "\n";
            j["panes"].push_back({{"domain", domainName(p.kind)},
                                  {"spacing", spacingName(p.spacing)},
                                  {"outer", p.levels.outer},
                                  {"inner", p.levels.inner},
                                  {"culled", want.culled},
                                  {"statisticsValid", stats[i].valid},
                                  {"evaluations", stats[i].vertices},  // evaluation shader invocations
                                  {"primitives", stats[i].primitives},
                                  {"expectedVertices", want.vertices},
                                  {"expectedPrimitives", want.primitives}});
        }
        if (!a.stats.empty()) out.stage(a.stats, j.dump(2) + "\n");
        out.commit();
        std::cout << said.str();
        rc = validationExitCode(dev, "render");
    }
    return rc;
}

int runRender(const RenderArgs& a) {
    if (a.output.empty()) bad("-o", "an output .png (or, for a domain figure, .svg or .pdf) file is required");
    // Refuse unwritable outputs before the work (a device node, a read-only file, a missing folder).
    (void)checkOutputPath(a.output);
    if (!a.stats.empty()) (void)checkOutputPath(a.stats);
    const auto [w, h] = parseImageSize("render", a.size);
    const DomainArgs dargs = domainArgs(a);
    if (wantsDomain(dargs)) {
        if (!a.input.empty()) bad("--domain", "a domain figure draws no document; leave out the file");
        if (!a.compareDevice.empty()) return runDeviceComparison(a, domainPanes("render", dargs), w, h);
        return runDomainRender(a, domainPanes("render", dargs), w, h);
    }
    if (!a.compareDevice.empty()) bad("--compare-device", "compares domain patterns: give --preset or --domain");
    if (render::vectorFormatFor(a.output))
        bad("-o", "'" + a.output + "': SVG and PDF figures are of the tessellated domain (--domain, --preset); write the model as .png");
    if (a.notesPatch != 0 && !a.input.empty()) bad("--notes-patch", "draws the notes' patch: leave out the file");
    if (a.notesPatch < 0 || a.notesPatch > kNotesPatchVersions)
        bad("--notes-patch", "expected 1 or 2, got " + std::to_string(a.notesPatch));
    Document doc = a.notesPatch ? notesBezierPatch(a.notesPatch) : a.input.empty() ? builtinTeapot() : loadDocument(a.input);
    // --math U,V: one patch's evaluation drawn over the model (one pane).
    std::optional<MathDiagram> math;
    Net16 mathNet{};
    if (!a.math.empty()) {
        if (!a.compare.empty()) bad("--math", "draws over one view: leave out --compare");
        const auto uv = parseNumbers("render", "--math", a.math, 2, 0.0, 1.0, "U,V within [0, 1]");
        if (a.mathPatch < 0 || size_t(a.mathPatch) >= doc.patches.size())
            bad("--math-patch",
                std::to_string(a.mathPatch) + " is not a patch of this document (it has " + std::to_string(doc.patches.size()) + ")");
        const Patch& p = doc.patches[size_t(a.mathPatch)];
        if (p.basis != Basis::Bezier)
            bad("--math-patch", "patch " + std::to_string(a.mathPatch) + " is a " + std::string(basisName(p.basis)) +
                                    " window; the math figure shows Bézier patches");
        const WindowNet net = gatherWindow(doc, p.idx);
        mathNet = net.points;
        math = bezierMathDiagram(mathNet, bezierMath(net.points, net.weights, uv[0], uv[1]));
    }
    applyDisplacementArgs("render", a.displacement, doc);
    const std::shared_ptr<const HeightMap> map = loadDocumentHeightMap(doc, a.input);
    // --compare: the model in 2 or 4 panes, each with its own partitioning (and level).
    std::vector<render::ModelPane> panes;
    for (const PaneSpec& p : a.compare.empty() ? std::vector<PaneSpec>{} : parsePaneSpecs("render", "--compare", a.compare))
        panes.push_back({p.spacing, p.level});
    // --near-far F: the distance-adaptive slide, the view beside the same view F times farther.
    if (a.nearFar != 0.0) {
        if (!panes.empty()) bad("--near-far", "makes its own two panes: leave out --compare");
        std::ostringstream factor;
        factor << a.nearFar;
        if (!(a.nearFar > 1.0 && a.nearFar <= 1000.0)) bad("--near-far", "expected a factor in (1, 1000], got " + factor.str());
        panes.push_back({doc.tess.spacing, 0.0f, 1.0, "near"});
        panes.push_back({doc.tess.spacing, 0.0f, a.nearFar, "far \u00d7" + factor.str()});
    }
    const auto [paneW, paneH] = render::paneSize(int(panes.size()), w, h);  // the camera is framed for a pane's aspect
    render::RenderOptions opt = buildRenderOptions(a, doc, paneW, paneH);
    if (math && a.eye.empty()) {  // the control net, which the math is drawn on, fills the frame (room for the numbers)
        opt.camera = frameTightly(opt.camera, {mathNet.begin(), mathNet.end()}, double(paneW) / double(std::max(paneH, 1u)), 1.25);
    }

    render::DeviceOptions dopt;
    dopt.name = a.device;
    dopt.validation = a.validation;
    int rc = 0;
    {
        render::Device dev(dopt);
        // Levels above what this device's tessellator generates are clamped there; say so.
        float highest = 0.0f;
        for (float l : opt.tess.outer) highest = std::max(highest, l);
        for (float l : opt.tess.inner) highest = std::max(highest, l);
        for (const auto& p : panes) highest = std::max(highest, p.level);
        if (highest > float(dev.caps().maxTessLevel))
            std::cerr << "patchwork render: level " << highest << " clamped to the device maximum " << dev.caps().maxTessLevel << "\n";
        render::OffscreenTarget target(dev, w, h, !a.noMsaa);
        render::Renderer renderer(dev, target);
        renderer.setDocument(doc, map);
        // The PNG and the stats appear together or not at all; what was written is said after.
        OutputBatch out;
        std::ostringstream said;
        if (panes.empty()) {
            const render::FrameStats st = renderer.render(opt);
            std::string mathSaid;
            std::vector<uint8_t> rgba = target.pixels();
            if (opt.display.shading == ShadingMode::Level)
                render::drawLevelLegend(rgba, w, h, {0, 0, int(w), int(h)}, render::LabelRaster());
            const float barPx = std::clamp(float(h) / 45.0f, 10.0f, 30.0f);
            if (a.stageBars)
                render::drawStageBars({w, h, rgba}, {0.0f, 0.0f, float(w), float(h)}, render::stageCounts(st), barPx,
                                      render::LabelRaster());
            if (math) {
                const MathDiagram& d = *math;
                const float px = std::clamp(float(h) / 40.0f, 11.0f, 40.0f);
                render::drawMathDiagram({w, h, rgba}, d, opt.camera, {0.0f, 0.0f, float(w), float(h)}, px, render::LabelRaster());
                mathSaid = "Bezier math of patch " + std::to_string(a.mathPatch) + ": " + d.legend[0] + ", " + d.legend[3] + "\n";
            }
            out.stage(a.output, render::encodePng(a.output, w, h, rgba));
            said << "wrote " << a.output << " (" << w << "x" << h << ", " << dev.name() << "): " << st.triangles() << " triangles, "
                 << st.patches << " patches (" << st.patchesCulled << " culled), " << st.draws << " draws, GPU " << st.gpuMs << " ms\n"
                 << mathSaid;
            if (!a.stats.empty()) out.stage(a.stats, render::statsToJson(st) + "\n");
        } else {
            const render::LabelRaster labels;
            std::vector<uint8_t> rgba;
            const auto results = render::renderModelFigure(renderer, target, labels, opt, panes, 0.0f, rgba);
            if (opt.display.shading == ShadingMode::Level)
                for (const render::PaneResult& r : results) render::drawLevelLegend(rgba, w, h, r.rect, labels);
            if (a.stageBars)
                for (const render::PaneResult& r : results)
                    render::drawStageBars({w, h, rgba}, {float(r.rect[0]), float(r.rect[1]), float(r.rect[2]), float(r.rect[3])},
                                          render::stageCounts(r.stats), std::clamp(float(r.rect[3]) / 40.0f, 10.0f, 30.0f), labels);
            out.stage(a.output, render::encodePng(a.output, w, h, rgba));
            nlohmann::json j;
            j["device"] = dev.name();
            for (size_t i = 0; i < results.size(); ++i) {
                const render::PaneResult& r = results[i];
                said << "wrote " << a.output << " pane " << i + 1 << ": " << (panes[i].label.empty() ? "" : panes[i].label + " \u00b7 ")
                     << render::paneCaption(r.tess, r.stats.triangles()) << ", GPU " << r.stats.gpuMs << " ms\n";
                nlohmann::json p = render::statsJson(r.stats);
                p["spacing"] = spacingName(r.tess.spacing);
                p["outer"] = r.tess.outer;
                p["inner"] = r.tess.inner;
                p["rect"] = r.rect;
                j["panes"].push_back(std::move(p));
            }
            if (a.nearFar != 0.0 && results.size() == 2 && results[1].stats.triangles() > 0) {
                const double ratio = double(results[0].stats.triangles()) / double(results[1].stats.triangles());
                said << "near/far: " << ratio << "x the far view's triangles\n";
                j["nearOverFar"] = ratio;
            }
            if (!a.stats.empty()) out.stage(a.stats, j.dump(2) + "\n");
        }
        out.commit();
        std::cout << said.str();
        rc = validationExitCode(dev, "render");
    }
    return rc;
}

}  // namespace

int validationExitCode(const render::Device& dev, const std::string& command) {
    if (!dev.validationEnabled() || render::Device::validationMessageCount() == 0) return 0;
    std::cerr << "patchwork " << command << ": " << render::Device::validationMessageCount() << " Vulkan validation message(s)\n";
    return 1;
}

DomainArgs domainArgs(const RenderArgs& a) { return {a.domain, a.preset, a.compare, a.tess, a.outer, a.inner, a.spacing, a.origin}; }

void addRenderOptions(CLI::App* cmd, RenderArgs& a) {
    cmd->add_option("file", a.input, "Document (" + formatList(FormatUse::Load, ", ") + "); default: the built-in teapot");
    cmd->add_option("--size", a.size, "Image size WIDTHxHEIGHT (default 1280x720)");
    cmd->add_option("--tess", a.tess, "Uniform tessellation level 1..64 (all outer and inner levels)");
    cmd->add_option(
        "--outer", a.outer,
        "Four outer levels a,b,c,d (edges u0, v0, u1, v1), 1..64; with --domain tri three, isoline two (lines, segments); 0 in a "
        "domain figure culls the patch");
    cmd->add_option("--inner", a.inner, "Two inner levels a,b (along u, along v), 1..64; with --domain tri one");
    cmd->add_option("--spacing", a.spacing, "equal (or integer, as the notes say) | fractional_odd | fractional_even | pow2");
    cmd->add_option(
        "--adaptive", a.adaptive,
        "none | distance | screen | orientation | notes (the first notes' formula from the patch centre: 64 at 20, 0 (culled) from "
        "100) | notes-edges (the same per edge: crack-free) | notes-terrain (the terrain notes: 2^lerp(20, 4, s) over 10..200, "
        "fractional_even)");
    cmd->add_option("--distance", a.distance, "Distance mode: NEAR,FAR (full level at NEAR or closer, level 1 at FAR or beyond)");
    cmd->add_option("--distance-curve", a.distanceCurve,
                    "Distance mode's curve: linear (max level at NEAR, 0 at FAR) | pow2 (2^lerp(E0, E1, s), the terrain notes)");
    cmd->add_option("--distance-exponents", a.distanceExponents, "pow2 distance curve: exponents E0,E1 at NEAR and FAR (default 20,4)");
    cmd->add_option("--distance-from", a.distanceFrom,
                    "Where distance is measured: edges (each edge's midpoint: crack-free, the default) | centre (the patch centre, "
                    "the first notes: neighbours disagree, cracks) | edges-inner-centre (the terrain notes)");
    cmd->add_option("--debug-camera", a.debugCamera,
                    "auto | X,Y,Z: draw from another camera while levels and culling stay those of the view: culled patches "
                    "greyed in place, the view's frustum drawn");
    cmd->add_option("--merge-windows", a.mergeWindows,
                    "auto (on CPU renderers) | never | always: draw windows of a net that get the same levels "
                    "several to a patch (the same vertices; levels other than powers of two on lavapipe only, whose placement is known; "
                    "lavapipe pays per patch)");
    cmd->add_flag("--cull-far", a.cullFar, "Distance mode: cull patches centred at or beyond FAR (the notes' level 0) instead of level 1");
    cmd->add_option("--target-px", a.targetPx, "Screen-space adaptive: pixels per segment (default 8)");
    cmd->add_option("--max-level", a.maxLevel, "Adaptive: largest level, 1..64");
    cmd->add_option("--shading", a.shading,
                    "lit | normal | patch | uv | zebra | curvature | gauss | mean | level (by tessellation level, with a legend)");
    cmd->add_option(
        "--overlay", a.overlay,
        "Comma-separated overlays: grid, wire, normals, boundaries, isocurves, combs (curvature combs on curves and isocurves)");
    cmd->add_option("--comb-join", a.combJoin,
                    "Draw the curvature graph across join J (combs on the isocurves crossing it; turns combs on)");
    cmd->add_option("--isolines", a.isolines,
                    "Isoline levels LINES,SEGMENTS for curves and the isocurve overlay (default: the document's, 2,16)");
    cmd->add_option("--view", a.view, "front | back | left | right | top | bottom | iso (framed to the model)");
    cmd->add_option("--theme", a.theme, "dark (default) | light: a light background, a grey wire, the model framed tightly (slides)");
    cmd->add_option("--eye", a.eye, "Camera position X,Y,Z in model units, looking at --target (instead of --view)");
    cmd->add_option("--target", a.target, "Point X,Y,Z the camera looks at (default: the centre of the model's bounds)");
    cmd->add_option("--stats", a.stats, "Write frame statistics (triangles, GPU time, ...) as JSON to this file");
    cmd->add_option("--domain", a.domain, "Draw the parametric domain instead: quad | tri | isoline (levels from --tess/--outer/--inner)");
    cmd->add_option("--origin", a.origin,
                    "Domain figure: upper-left (the D3D notes' and Vulkan's default: v = 0 on top, edges tagged [i] = "
                    "SV_TessFactor[i] = gl_TessLevelOuter[i]) or lower-left (GL, the default)");
    cmd->add_option("--preset", a.preset,
                    "Domain figure of the notes' factor sets: preset id(s), comma-separated (see `patchwork presets`)");
    cmd->add_option(
        "--compare", a.compare,
        "2-4 panes side by side, each a partitioning with an optional level: equal,fractional_odd:4.5 (model or domain figure)");
    cmd->add_option("--device", a.device, "Vulkan device: substring of its name");
    cmd->add_flag("--cull", a.cull, "Cull back-facing patches (conservative normal-cone test)");
    cmd->add_flag("--validation", a.validation, "Enable the Vulkan validation layer (also PATCHWORK_VALIDATION=1)");
    cmd->add_flag("--no-msaa", a.noMsaa, "Single-sample rendering");
    addDisplacementOptions(cmd, a.displacement);
}

void registerRenderCommand(CLI::App& app, Action& run) {
    const auto [cmd, a] = addSubcommand<RenderArgs>(
        app, run, "render", "Render a document offscreen on the GPU tessellation pipeline to a PNG (domain figures also SVG, PDF)",
        runRender);
    addRenderOptions(cmd, *a);
    cmd->add_option("--compare-device", a->compareDevice,
                    "Domain figure: this device's pattern beside the one in this capture file (patchwork capture; data/captures), "
                    "differences highlighted");
    cmd->add_option("--near-far", a->nearFar,
                    "F: two panes, the view and the same view F times farther (the distance-adaptive slide: use with --adaptive "
                    "distance or notes and --shading level); prints the far/near triangle ratio");
    cmd->add_option("--math", a->math,
                    "U,V: draw the Bézier math of one patch at (U, V) over the model: each control point's Bernstein weight, the "
                    "de Casteljau rows and column, the point, its tangents and normal");
    cmd->add_option("--math-patch", a->mathPatch, "The patch --math shows (default 0)");
    cmd->add_flag("--stage-bars", a->stageBars,
                  "Draw each pane's per-stage counters: vertex shader invocations, control shader patches, evaluation shader "
                  "invocations, triangles (log-scaled bars, the numbers beside them)");
    cmd->add_option("--notes-patch", a->notesPatch,
                    "Render the lecture notes' 16-point Bézier patch instead of a file: 1 the first notes' (level 25), 2 the second "
                    "notes' (level 15, integer)");
    cmd->add_option("-o,--output", a->output, "Output PNG; a domain figure also .svg or .pdf (vector paths, one per triangle)")->required();
}

}  // namespace pw::app

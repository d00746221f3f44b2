// `patchwork render [FILE] -o out.png ...`: renders a document headlessly on the GPU tessellation
// pipeline (offscreen Vulkan target) and writes a PNG, optionally with frame statistics as JSON.
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "camera_math.hpp"
#include "commands.hpp"
#include "device.hpp"
#include "document_io.hpp"
#include "errors.hpp"
#include "file_io.hpp"
#include "limits.hpp"
#include "offscreen_target.hpp"
#include "png_writer.hpp"
#include "renderer.hpp"

namespace pw::app {

namespace {

struct RenderArgs {
    std::string input, output = "", size = "1280x720", tess, outer, inner, spacing, adaptive, shading, overlay, view, stats,
                device, targetPx, maxLevel;
    bool cull = false, validation = false, noMsaa = false;
};

[[noreturn]] void bad(const std::string& option, const std::string& what) {
    throw InputError("render", option + ": " + what);
}

float parseLevel(const std::string& option, const std::string& text) {
    float v = 0.0f;
    try {
        size_t used = 0;
        v = std::stof(text, &used);
        if (used != text.size()) throw std::invalid_argument("trailing");
    } catch (const std::exception&) {
        bad(option, "'" + text + "' is not a number");
    }
    if (!std::isfinite(v) || v < limits::kMinTessLevel || v > limits::kMaxTessLevel)
        bad(option, "tessellation level '" + text + "' must be from 1 to 64");
    return v;
}

std::vector<float> parseLevels(const std::string& option, const std::string& text, size_t count) {
    std::vector<float> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) out.push_back(parseLevel(option, item));
    if (out.size() != count) bad(option, "expected " + std::to_string(count) + " comma-separated levels, got '" + text + "'");
    return out;
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) out.push_back(item);
    return out;
}

// Applies the command-line settings on top of the document's (validating everything first).
render::RenderOptions buildOptions(const RenderArgs& a, const Document& doc, uint32_t width, uint32_t height) {
    render::RenderOptions o = render::optionsFromDocument(doc);
    o.display.showGrid = o.display.showWireframe = o.display.showNormals = o.display.showBoundaries = false;
    if (!a.tess.empty()) {
        if (!a.outer.empty() || !a.inner.empty()) bad("--tess", "use either --tess or --outer/--inner");
        const float l = parseLevel("--tess", a.tess);
        o.tess.outer = {l, l, l, l};
        o.tess.inner = {l, l};
        o.tess.adaptive = AdaptiveMode::None;
    }
    if (!a.outer.empty()) {
        auto v = parseLevels("--outer", a.outer, 4);
        o.tess.outer = {v[0], v[1], v[2], v[3]};
        if (a.inner.empty()) o.tess.inner = {std::max(v[1], v[3]), std::max(v[0], v[2])};
        o.tess.adaptive = AdaptiveMode::None;
    }
    if (!a.inner.empty()) {
        auto v = parseLevels("--inner", a.inner, 2);
        o.tess.inner = {v[0], v[1]};
        o.tess.adaptive = AdaptiveMode::None;
    }
    if (!a.spacing.empty()) {
        auto s = parseSpacing(a.spacing);
        if (!s) bad("--spacing", "'" + a.spacing + "' is not one of equal, fractional_odd, fractional_even, pow2");
        o.tess.spacing = *s;
    }
    if (!a.adaptive.empty()) {
        auto m = parseAdaptive(a.adaptive);
        if (!m) bad("--adaptive", "'" + a.adaptive + "' is not one of none, distance, screen, orientation");
        o.tess.adaptive = *m;
    }
    if (!a.targetPx.empty()) {
        float px = 0;
        try { px = std::stof(a.targetPx); } catch (const std::exception&) { px = NAN; }
        if (!std::isfinite(px) || px < 0.5f || px > 1000.0f) bad("--target-px", "'" + a.targetPx + "' must be from 0.5 to 1000");
        o.tess.targetPixels = px;
    }
    if (!a.maxLevel.empty()) o.tess.maxLevel = parseLevel("--max-level", a.maxLevel);
    if (a.cull) o.tess.cullBackfaces = true;
    if (!a.shading.empty()) {
        std::optional<ShadingMode> s = a.shading == "curvature" ? std::optional(ShadingMode::GaussCurvature) : parseShading(a.shading);
        if (!s) bad("--shading", "'" + a.shading + "' is not one of lit, normal, patch, uv, zebra, curvature, gauss, mean");
        o.display.shading = *s;
    }
    for (const std::string& ov : splitList(a.overlay)) {
        if (ov == "grid") o.display.showGrid = true;
        else if (ov == "wire") o.display.showWireframe = true;
        else if (ov == "normals") o.display.showNormals = true;
        else if (ov == "boundaries") o.display.showBoundaries = true;
        else if (ov != "none") bad("--overlay", "'" + ov + "' is not one of grid, wire, normals, boundaries, none");
    }
    const double aspect = double(width) / double(height);
    if (!a.view.empty()) {
        auto cam = applyNamedView(doc.camera, a.view);
        if (!cam) bad("--view", "'" + a.view + "' is not one of front, back, left, right, top, bottom, iso");
        o.camera = frameBounds(*cam, computeBounds(doc.points), aspect);
    } else if (doc.camera == Camera{}) {
        o.camera = frameBounds(doc.camera, computeBounds(doc.points), aspect);
    }
    o.display.normalLength = float(0.03 * modelSize(doc));
    return o;
}

int runRender(const RenderArgs& a) {
    if (a.output.empty()) bad("-o", "an output .png file is required");
    unsigned w = 0, h = 0;
    {
        char x = 0;
        std::stringstream ss(a.size);
        if (!(ss >> w >> x >> h) || x != 'x' || !ss.eof() || w < 1 || h < 1 || w > 8192 || h > 8192)
            bad("--size", "'" + a.size + "' must be WIDTHxHEIGHT with sides from 1 to 8192");
    }
    const Document doc = a.input.empty() ? builtinTeapot() : loadDocument(a.input);
    const render::RenderOptions opt = buildOptions(a, doc, w, h);

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
        if (highest > float(dev.caps().maxTessLevel))
            std::cerr << "patchwork render: level " << highest << " clamped to the device maximum " << dev.caps().maxTessLevel << "\n";
        render::OffscreenTarget target(dev, w, h, !a.noMsaa);
        render::Renderer renderer(dev, target);
        renderer.setDocument(doc);
        const render::FrameStats st = renderer.render(opt);
        render::writePng(a.output, w, h, target.pixels());
        std::cout << "wrote " << a.output << " (" << w << "x" << h << ", " << dev.name() << "): " << st.triangles()
                  << " triangles, " << st.patches << " patches (" << st.patchesCulled << " culled), " << st.draws
                  << " draws, GPU " << st.gpuMs << " ms\n";
        if (!a.stats.empty()) {
            writeFileAtomic(a.stats, render::statsToJson(st) + "\n");
        }
        if (dev.validationEnabled() && render::Device::validationMessageCount() > 0) {
            std::cerr << "patchwork render: " << render::Device::validationMessageCount() << " Vulkan validation message(s)\n";
            rc = 1;
        }
    }
    return rc;
}

}  // namespace

void registerRenderCommand(CLI::App& app, Action& run) {
    auto a = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render a document offscreen on the GPU tessellation pipeline to a PNG");
    cmd->add_option("file", a->input, "Document (.patchwork, .bpt, .gltf, .glb); default: the built-in teapot");
    cmd->add_option("-o,--output", a->output, "Output PNG")->required();
    cmd->add_option("--size", a->size, "Image size WIDTHxHEIGHT (default 1280x720)");
    cmd->add_option("--tess", a->tess, "Uniform tessellation level 1..64 (all outer and inner levels)");
    cmd->add_option("--outer", a->outer, "Four outer levels a,b,c,d (edges u0, v0, u1, v1), 1..64");
    cmd->add_option("--inner", a->inner, "Two inner levels a,b (along u, along v), 1..64");
    cmd->add_option("--spacing", a->spacing, "equal | fractional_odd | fractional_even | pow2");
    cmd->add_option("--adaptive", a->adaptive, "none | distance | screen | orientation");
    cmd->add_option("--target-px", a->targetPx, "Screen-space adaptive: pixels per segment (default 8)");
    cmd->add_option("--max-level", a->maxLevel, "Adaptive: largest level, 1..64");
    cmd->add_option("--shading", a->shading, "lit | normal | patch | uv | zebra | curvature | gauss | mean");
    cmd->add_option("--overlay", a->overlay, "Comma-separated overlays: grid, wire, normals, boundaries");
    cmd->add_option("--view", a->view, "front | back | left | right | top | bottom | iso (framed to the model)");
    cmd->add_option("--stats", a->stats, "Write frame statistics (triangles, GPU time, ...) as JSON to this file");
    cmd->add_option("--device", a->device, "Vulkan device: substring of its name");
    cmd->add_flag("--cull", a->cull, "Cull back-facing patches (conservative normal-cone test)");
    cmd->add_flag("--validation", a->validation, "Enable the Vulkan validation layer (also PATCHWORK_VALIDATION=1)");
    cmd->add_flag("--no-msaa", a->noMsaa, "Single-sample rendering");
    cmd->callback([a, &run] { run = [a] { return runRender(*a); }; });
}

}  // namespace pw::app

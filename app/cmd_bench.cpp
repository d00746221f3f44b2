// `patchwork bench`: fixed scenes rendered offscreen at 1280x720 (submit and wait per frame) on the
// tessellation pipeline and, in the same run, as the same triangles pre-tessellated on the CPU and
// drawn as a plain mesh. Reports medians of wall, submit+wait and GPU times, triangles per frame,
// million triangles per second and the tessellated/plain throughput ratio.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/displacement_args.hpp"
#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/construct/model_builders.hpp"
#include "core/construct/terrain.hpp"
#include "core/io/document_io.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/model/camera_math.hpp"
#include "core/trim/trim_loops.hpp"
#include "render/scene/renderer.hpp"
#include "render/targets/offscreen_target.hpp"
#include "render/vk/device.hpp"

#ifdef PATCHWORK_HAVE_EDITOR
#include "ui/editor/editor.hpp"
#endif

namespace pw::app {

namespace {

struct BenchArgs {
    int frames = 20;
    std::vector<std::string> scenes;
    std::string json, device;
    bool validation = false;
    bool msaa = false;
    bool editor = false;            // the editor's frame while dragging, against a bare render
    std::string file;               // the document: offscreen with its own settings, or the editor's (default: the teapot)
    std::optional<float> level;     // editor: uniform level (default: a --file's own levels, else 16)
    std::string size = "1280x720";  // editor: window size
};

struct Scene {
    std::string name;
    std::function<Document()> make;
    float level = 16;
    bool adaptive = false;
    bool grid = false;
    bool bigOnly = false;    // only on real GPUs unless named
    std::string comparedTo;  // adaptive: the uniform scene with the same view
    bool terrain = false;    // the terrain's own table (runTerrain), only when named
    std::string path;        // --file: a document measured with its own settings (levels, adaptivity, camera, display)
    bool corner = false;     // the camera aimed at the model's corner: about half of it off screen (culling on the CPU)
    bool trimmed = false;    // against the same document untrimmed, frame by frame (issue 64)
};

// The 32 x 32 grid with four round holes in every patch: 4 096 trim loops.
Document trimmedGrid() {
    Document d = makePatchGrid(32, 32);
    for (Patch& p : d.patches)
        for (const UV c : {UV{0.27, 0.27}, UV{0.73, 0.27}, UV{0.27, 0.73}, UV{0.73, 0.73}}) p.trims.push_back(circleLoop(c, 0.17, true));
    return d;
}

std::vector<Scene> allScenes() {
    return {
        {"teapot16", [] { return builtinTeapot(); }, 16, false, true, false, ""},
        {"teapot64", [] { return builtinTeapot(); }, 64, false, false, false, ""},
        {"grid32", [] { return makePatchGrid(32, 32); }, 16, false, false, false, ""},
        {"grid32-adaptive8px", [] { return makePatchGrid(32, 32); }, 16, true, false, false, "grid32"},
        {"grid64-adaptive8px", [] { return makePatchGrid(64, 64); }, 16, true, false, false, ""},
        {"grid128", [] { return makePatchGrid(128, 128); }, 16, false, false, true, ""},
        {"grid64-corner", [] { return makePatchGrid(64, 64); }, 16, false, false, false, "", false, "", true},
        {"terrain", [] { return makeTerrainDocument(); }, 64, true, false, true, "", true},
        {"grid32-trimmed", [] { return trimmedGrid(); }, 16, false, false, false, "grid32", false, "", false, true},
    };
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Measure {
    double wall = 0, submit = 0, gpu = 0;
    uint64_t triangles = 0;
    uint32_t draws = 0, mergedWindows = 0, mergedBlocks = 0;
};

// Renders each option set `frames` times, alternating between them frame by frame, so that the
// load of a shared machine (±30 % between runs) falls on every variant alike; medians per variant.
std::vector<Measure> measureInterleaved(render::Renderer& r, const std::vector<render::RenderOptions>& variants, int frames) {
    for (const auto& o : variants) r.render(o);  // first frame after a switch
    std::vector<std::vector<double>> wall(variants.size()), submit(variants.size()), gpu(variants.size());
    std::vector<Measure> m(variants.size());
    for (int i = 0; i < frames; ++i) {
        for (size_t v = 0; v < variants.size(); ++v) {
            const render::FrameStats s = r.render(variants[v]);
            wall[v].push_back(s.wallMs);
            submit[v].push_back(s.submitMs);
            gpu[v].push_back(s.gpuMs);
            m[v].triangles = s.triangles();
            m[v].draws = s.draws;
            m[v].mergedWindows = s.mergedWindows;
            m[v].mergedBlocks = s.mergedBlocks;
        }
    }
    for (size_t v = 0; v < variants.size(); ++v) {
        m[v].wall = median(wall[v]);
        m[v].submit = median(submit[v]);
        m[v].gpu = median(gpu[v]);
    }
    return m;
}

int runEditorBench(const BenchArgs& a) {
#ifdef PATCHWORK_HAVE_EDITOR
    ui::EditorBenchOptions o;
    o.file = a.file;
    o.frames = a.frames;
    o.level = a.level;
    if (std::sscanf(a.size.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 64 || o.height < 64 || o.width > 16384 ||
        o.height > 16384)
        throw InputError("bench", "--size: expected WIDTHxHEIGHT (64..16384), got '" + a.size + "'");
    o.json = a.json;
    if (a.validation) ::setenv("PATCHWORK_VALIDATION", "1", 1);  // the editor's device reads it
    return ui::runEditorBench(o);
#else
    (void)a;
    std::cerr << "patchwork bench: this build has no editor (configure with -DPATCHWORK_BUILD_EDITOR=ON)\n";
    return 2;
#endif
}

// The lecture notes' terrain (core/construct/terrain.hpp): one row per view (near the ground, far above) and
// culling (off, on) with distance-adaptive levels, after the uniform level 64 reference; triangles,
// culled patches and GPU time, and what adaptivity and culling saved.
nlohmann::json runTerrain(render::Renderer& renderer, int frames) {
    const Document doc = makeTerrainDocument();
    renderer.setDocument(doc, std::make_shared<const HeightMap>(makeTerrainHeightMap()));
    render::RenderOptions base = render::optionsFromDocument(doc);
    base.display.showGrid = false;
    Camera far = base.camera;
    far.target = {0.0, 0.0, 0.0};
    far.distance = 420.0;
    far.pitchDeg = 50.0;
    struct Row {
        const char* name;
        bool nearView, adaptive, cull;
    };
    const Row rows[] = {{"near uniform 64", true, false, false},
                        {"near adaptive", true, true, false},
                        {"near adaptive+cull", true, true, true},
                        {"far adaptive", false, true, false},
                        {"far adaptive+cull", false, true, true}};
    std::vector<render::RenderOptions> variants;
    for (const Row& r : rows) {
        render::RenderOptions o = base;
        if (!r.nearView) o.camera = far;
        o.tess.adaptive = r.adaptive ? AdaptiveMode::Distance : AdaptiveMode::None;
        o.tess.outer = {64, 64, 64, 64};
        o.tess.inner = {64, 64};
        o.tess.cullOffscreen = r.cull;
        o.tess.cullBackfaces = false;
        variants.push_back(o);
    }
    const std::vector<Measure> m = measureInterleaved(renderer, variants, frames);
    std::printf("terrain: %zu patches, %ux%u height map; distance-adaptive levels (d0 %.0f, d1 %.0f), off-screen culling\n",
                expandPatches(doc).size(), 512u, 512u, doc.tess.distanceNear, doc.tess.distanceFar);
    std::printf("%-20s %9s %9s %11s %8s %9s\n", "view", "wall ms", "gpu ms", "triangles", "culled", "vs unif.");
    nlohmann::json j = nlohmann::json::array();
    for (size_t i = 0; i < m.size(); ++i) {
        const render::FrameStats s = renderer.render(variants[i]);  // the counters of this view
        const double fewer = m[i].triangles ? double(m[0].triangles) / double(m[i].triangles) : 0.0;
        std::printf("%-20s %9.2f %9.2f %11llu %8u %8.1fx\n", rows[i].name, m[i].wall, m[i].gpu, (unsigned long long)m[i].triangles,
                    s.patchesCulled, fewer);
        j.push_back({{"view", rows[i].name},
                     {"near", rows[i].nearView},
                     {"adaptive", rows[i].adaptive},
                     {"cull", rows[i].cull},
                     {"wall_ms", m[i].wall},
                     {"gpu_ms", m[i].gpu},
                     {"triangles", m[i].triangles},
                     {"patches_culled", s.patchesCulled},
                     {"displaced_edges", s.displacedEdges},
                     {"fewer_triangles_than_uniform", fewer}});
    }
    std::fflush(stdout);
    return j;
}

int runBench(const BenchArgs& a) {
    if (a.frames < 1 || a.frames > 100000) throw InputError("bench", "--frames: must be from 1 to 100000");
    if (a.editor) return runEditorBench(a);
    std::vector<Scene> scenes = allScenes();
    if (!a.file.empty()) {  // the document alone, as it opens (read before the device starts: bad files fail fast)
        if (!a.scenes.empty()) throw InputError("bench", "--file and --scene: give one or the other");
        const Document doc = loadDocument(a.file);
        (void)loadDocumentHeightMap(doc, a.file);
        Scene sc;
        sc.name = std::filesystem::path(a.file).filename().string();
        sc.make = [doc] { return doc; };
        sc.path = a.file;
        sc.adaptive = doc.tess.adaptive != AdaptiveMode::None;
        scenes = {sc};
    }
    for (const std::string& n : a.scenes)
        if (std::none_of(scenes.begin(), scenes.end(), [&](const Scene& s) { return s.name == n; })) {
            std::string names;
            for (auto& s : scenes) names += " " + s.name;
            throw InputError("bench", "--scene: unknown scene '" + n + "' (scenes:" + names + ")");
        }

    render::DeviceOptions dopt;
    dopt.name = a.device;
    dopt.validation = a.validation;
    render::Device dev(dopt);
    const bool cpuDevice = dev.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    constexpr uint32_t W = 1280, H = 720;
    render::OffscreenTarget target(dev, W, H, a.msaa);
    target.setReadback(false);
    render::Renderer renderer(dev, target);
    std::cout << "device: " << dev.name() << ", 1280x720" << (target.samples() > 1 ? " 4x MSAA" : " 1 sample") << ", " << a.frames
              << " frames per scene, medians; " << renderer.pipelines().cost->described << " pipelines described in "
              << renderer.pipelines().cost->createMs << " ms (each made when first drawn)\n";
    std::printf("%-20s %9s %9s %9s %11s %8s %7s | %9s %8s %7s\n", "scene", "wall ms", "submit", "gpu ms", "triangles", "Mtri/s", "draws",
                "plain ms", "Mtri/s", "ratio");

    bool warmed = false;
    nlohmann::json out = nlohmann::json::array();
    std::map<std::string, uint64_t> trianglesByScene;
    for (const Scene& sc : scenes) {
        const bool named = std::find(a.scenes.begin(), a.scenes.end(), sc.name) != a.scenes.end();
        if (!a.scenes.empty() && !named) continue;
        if (a.scenes.empty() && (sc.terrain || (sc.bigOnly && cpuDevice))) continue;
        if (sc.terrain) {
            if (!warmed) renderer.warmUp();
            warmed = true;
            out.push_back({{"scene", sc.name}, {"views", runTerrain(renderer, a.frames)}});
            continue;
        }
        const Document doc = sc.make();
        const std::shared_ptr<const HeightMap> map = sc.path.empty() ? nullptr : loadDocumentHeightMap(doc, sc.path);
        if (!warmed) {  // every pipeline variant once, so no measured frame pays for shader JIT
            renderer.warmUp();
            warmed = true;
        }
        renderer.setDocument(doc, map);
        render::RenderOptions o = render::optionsFromDocument(doc);
        const bool own = !sc.path.empty();  // --file: the document's own levels, adaptivity, culling, display and camera
        // The same triangles as a plain pre-tessellated mesh, measured frame by frame alongside: at
        // the scene's level, or at a document's own where its levels are one uniform integer.
        bool plain = !sc.adaptive;
        int plainLevel = int(sc.level);
        if (own) {
            const float l = doc.tess.outer[0];
            const auto isL = [&](float x) { return x == l; };
            plain = plain && std::all_of(doc.tess.outer.begin(), doc.tess.outer.end(), isL) &&
                    std::all_of(doc.tess.inner.begin(), doc.tess.inner.end(), isL) && doc.tess.spacing == Spacing::Equal &&
                    l == std::floor(l) && !doc.displacement.active();
            plainLevel = int(l);
        } else {
            o.display.showGrid = sc.grid;
            o.display.showWireframe = o.display.showNormals = o.display.showBoundaries = false;
            o.display.shading = ShadingMode::Lit;
            o.tess.outer = {sc.level, sc.level, sc.level, sc.level};
            o.tess.inner = {sc.level, sc.level};
            o.tess.spacing = Spacing::Equal;
            o.tess.adaptive = sc.adaptive ? AdaptiveMode::ScreenSpace : AdaptiveMode::None;
            o.tess.targetPixels = 8.0f;
            o.tess.cullBackfaces = false;
            const Bounds b = computeBounds(doc.points);
            o.camera = frameBounds(doc.camera, b, double(W) / H);
            if (sc.corner) {
                o.camera.target = {b.max.x, b.max.y, b.max.z};
                o.camera.distance *= 0.5;
            }
        }
        std::vector<render::RenderOptions> variants{o};
        if (plain) {
            renderer.setPlainMesh(tessellateDocument(doc, plainLevel));
            variants.push_back(o);
            variants.back().plainMesh = true;
        }
        // Uniform levels: also the raw tessellator (the same windows and levels through trivial shaders), the floor.
        size_t rawAt = 0;
        if (plain) {
            rawAt = variants.size();
            variants.push_back(o);
            variants.back().rawTessellator = true;
        }
        // A document with nets on a CPU renderer: also every window its own patch (no merged blocks), in the same run.
        size_t eachAt = 0;
        if (cpuDevice && !doc.surfaces.empty()) {
            eachAt = variants.size();
            variants.push_back(o);
            variants.back().mergeWindows = render::MergeWindows::Never;
        }
        if (sc.trimmed) {  // the trims' cost: the same grid untrimmed (lit, and with the full varyings trims draw with)
            Document bare = doc;
            for (Patch& p : bare.patches) p.trims.clear();
            render::RenderOptions full = o;
            full.display.shading = ShadingMode::PatchId;
            std::vector<double> gpu[3], wall[3];
            uint64_t tris[3] = {0, 0, 0};
            // Blocks of 10 frames per variant, alternated, after 3 frames of warming each (an upload
            // between two timed frames would leave the GPU idle and slow).
            for (int block = 0; block < std::max(1, a.frames / 10); ++block)
                for (int k = 0; k < 3; ++k) {
                    renderer.setDocument(k == 0 ? doc : bare, nullptr);
                    const render::RenderOptions& ok = k == 2 ? full : o;
                    for (int w = 0; w < 3; ++w) renderer.render(ok);
                    for (int i = 0; i < 10; ++i) {
                        const render::FrameStats s = renderer.render(ok);
                        gpu[k].push_back(s.gpuMs);
                        wall[k].push_back(s.wallMs);
                        tris[k] = s.triangles();
                    }
                }
            const double tg = median(gpu[0]), bg = median(gpu[1]), tw = median(wall[0]), bw = median(wall[1]), fg = median(gpu[2]);
            std::printf(
                "%-20s %9.2f %9s %9.2f %11llu %8s %7s | untrimmed %.2f ms GPU (%.2f wall), with full varyings %.2f: %.2fx the "
                "untrimmed frame\n",
                sc.name.c_str(), tw, "-", tg, (unsigned long long)tris[0], "-", "-", bg, bw, fg, bg > 0 ? tg / bg : 0.0);
            out.push_back({{"scene", sc.name},
                           {"patches", doc.patches.size()},
                           {"trim_loops", 4 * doc.patches.size()},
                           {"gpu_ms", tg},
                           {"wall_ms", tw},
                           {"triangles", tris[0]},
                           {"untrimmed", {{"gpu_ms", bg}, {"wall_ms", bw}, {"triangles", tris[1]}}},
                           {"untrimmed_full_varyings_gpu_ms", fg},
                           {"trimmed_over_untrimmed_gpu", bg > 0 ? tg / bg : 0.0},
                           {"trimmed_over_untrimmed_wall", bw > 0 ? tw / bw : 0.0}});
            continue;
        }
        const std::vector<Measure> measured = measureInterleaved(renderer, variants, a.frames);
        const Measure& t = measured[0];
        trianglesByScene[sc.name] = t.triangles;
        const double mtri = t.gpu > 0 ? double(t.triangles) / (t.gpu * 1000.0) : 0.0;
        nlohmann::json j{{"scene", sc.name},   {"patches", expandPatches(doc).size()},
                         {"wall_ms", t.wall},  {"submit_wait_ms", t.submit},
                         {"gpu_ms", t.gpu},    {"triangles", t.triangles},
                         {"mtri_per_s", mtri}, {"draws", t.draws}};
        if (own) {
            j["file"] = sc.path;
            j["adaptive"] = sc.adaptive;
        }
        double plainMs = 0, plainMtri = 0, ratio = 0;
        if (plain) {
            const Measure& pm = measured[1];
            plainMs = pm.gpu;
            plainMtri = pm.gpu > 0 ? double(pm.triangles) / (pm.gpu * 1000.0) : 0.0;
            ratio = plainMtri > 0 ? mtri / plainMtri : 0.0;
            j["plain"] = {{"wall_ms", pm.wall},
                          {"submit_wait_ms", pm.submit},
                          {"gpu_ms", pm.gpu},
                          {"triangles", pm.triangles},
                          {"mtri_per_s", plainMtri}};
            j["throughput_ratio_tess_over_plain"] = ratio;
            renderer.setPlainMesh(TriangleMesh{});
        } else if (trianglesByScene.count(sc.comparedTo) && t.triangles > 0) {
            j["fewer_triangles_than_" + sc.comparedTo] = double(trianglesByScene[sc.comparedTo]) / double(t.triangles);
        }
        if (!plain && own)
            std::printf(
                "%-20s %9.2f %9.2f %9.2f %11llu %8.2f %7u | %9s %8s %7s  (its own %s levels: no plain mesh of the same triangles)\n",
                sc.name.c_str(), t.wall, t.submit, t.gpu, (unsigned long long)t.triangles, mtri, t.draws, "-", "-", "-",
                sc.adaptive ? "adaptive" : "non-uniform");
        else if (!plain)
            std::printf("%-20s %9.2f %9.2f %9.2f %11llu %8.2f %7u | %9s %8s %7s  (%.1fx fewer triangles than %s)\n", sc.name.c_str(),
                        t.wall, t.submit, t.gpu, (unsigned long long)t.triangles, mtri, t.draws, "-", "-", "-",
                        trianglesByScene.count(sc.comparedTo) && t.triangles ? double(trianglesByScene[sc.comparedTo]) / t.triangles : 0.0,
                        sc.comparedTo.c_str());
        else
            std::printf("%-20s %9.2f %9.2f %9.2f %11llu %8.2f %7u | %9.2f %8.2f %7.2f\n", sc.name.c_str(), t.wall, t.submit, t.gpu,
                        (unsigned long long)t.triangles, mtri, t.draws, plainMs, plainMtri, ratio);
        if (rawAt) {
            const Measure& r = measured[rawAt];
            const double vsRaw = t.gpu > 0 ? r.gpu / t.gpu : 0.0;
            j["raw_tessellator"] = {{"wall_ms", r.wall}, {"gpu_ms", r.gpu}, {"triangles", r.triangles}};
            j["throughput_ratio_tess_over_raw"] = vsRaw;
            std::printf(
                "%-20s %9.2f %9.2f %9.2f %11llu %8s %7u |  the raw tessellator (trivial shaders, the same patches and "
                "levels): Patchwork at %.2fx its throughput\n",
                "  raw tessellator", r.wall, r.submit, r.gpu, (unsigned long long)r.triangles, "", r.draws, vsRaw);
        }
        if (eachAt) {
            const Measure& e = measured[eachAt];
            j["merged_windows"] = t.mergedWindows;
            j["merged_blocks"] = t.mergedBlocks;
            j["each_window_a_patch"] = {{"wall_ms", e.wall}, {"gpu_ms", e.gpu}, {"triangles", e.triangles}, {"draws", e.draws}};
            std::printf(
                "%-20s %9.2f %9.2f %9.2f %11llu %8s %7u |  every window its own patch; above, %u of %zu windows merged into "
                "%u patches: %.2fx faster\n",
                "  each window", e.wall, e.submit, e.gpu, (unsigned long long)e.triangles, "", e.draws, t.mergedWindows,
                expandPatches(doc).size(), t.mergedBlocks, t.wall > 0 ? e.wall / t.wall : 0.0);
        }
        {  // A per-patch level edit (the inspector's slider): the whole scene uploaded again, against the levels alone.
            std::vector<double> whole, levels;
            for (int i = 0; i < 5; ++i) {
                const auto t0 = std::chrono::steady_clock::now();
                renderer.setDocument(doc, map);
                const auto t1 = std::chrono::steady_clock::now();
                renderer.updateLevels(doc);
                const auto t2 = std::chrono::steady_clock::now();
                whole.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
                levels.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
            }
            j["level_edit"] = {{"scene_upload_ms", median(whole)}, {"levels_only_ms", median(levels)}};
            std::printf("%-20s level edit: whole scene uploaded %.2f ms, levels only %.3f ms\n", "", median(whole), median(levels));
        }
        out.push_back(j);
        std::fflush(stdout);
    }
    const render::PipelineCost& cost = *renderer.pipelines().cost;
    std::cout << "pipelines: " << cost.made << " of " << cost.described << " made, " << cost.createMs << " ms in all\n";
    if (!a.json.empty()) {
        writeFileAtomic(a.json, nlohmann::json{{"device", dev.name()},
                                               {"width", W},
                                               {"height", H},
                                               {"frames", a.frames},
                                               {"pipelines_made", cost.made},
                                               {"pipelines_described", cost.described},
                                               {"pipeline_ms", cost.createMs},
                                               {"scenes", out}}
                                        .dump(2) +
                                    "\n");
    }
    if (dev.validationEnabled() && render::Device::validationMessageCount() > 0) {
        std::cerr << "patchwork bench: " << render::Device::validationMessageCount() << " Vulkan validation message(s)\n";
        return 1;
    }
    return 0;
}

}  // namespace

void registerBenchCommand(CLI::App& app, Action& run) {
    const auto [cmd, a] = addSubcommand<BenchArgs>(
        app, run, "bench", "Benchmark the GPU tessellation pipeline against a plain pre-tessellated mesh", runBench);
    cmd->add_option("--frames", a->frames, "Measured frames per scene (default 20)");
    cmd->add_option(
        "--scene", a->scenes,
        "Scene(s) to run: teapot16, teapot64, grid32, grid32-adaptive8px, grid64-adaptive8px, grid128, grid32-trimmed (4 096 trim loops, "
        "against the same grid untrimmed), grid64-corner (aimed at its corner: "
        "about half off screen), terrain (only when named: "
        "near and far, culling off and on)");
    cmd->add_option("--json", a->json, "Write the results as JSON");
    cmd->add_option("--device", a->device, "Vulkan device: substring of its name");
    cmd->add_flag("--validation", a->validation, "Enable the Vulkan validation layer");
    cmd->add_flag("--msaa", a->msaa, "Render with 4x MSAA (default: one sample per pixel)");
    cmd->add_flag("--editor", a->editor,
                  "Instead: the editor's frame time while a control point is dragged (G grab, the mouse moving every "
                  "frame) against a bare offscreen render of the same view; needs a display (Xvfb will do)");
    cmd->add_option("--file", a->file,
                    "A document measured offscreen with its own settings (levels, adaptivity, culling, display, camera), against a "
                    "plain mesh where its levels are uniform; with --editor: the document the editor opens (default: the teapot)");
    cmd->add_option("--level", a->level,
                    "With --editor: a uniform tessellation level for the drag (default: a --file's own levels, adaptive ones "
                    "included; the teapot at 16)")
        ->check(CLI::Range(1.0f, 64.0f));
    cmd->add_option("--size", a->size, "With --editor: the window size, WIDTHxHEIGHT (default 1280x720)");
}

}  // namespace pw::app

// `patchwork sweep [FILE] -o PATTERN --from A --to B`: animates a uniform tessellation level from A
// to B and writes the frames as a numbered PNG sequence, headless: the model (with its wireframe,
// so vertices popping in under integer spacing and sliding in under fractional spacing show), or a
// domain figure (--domain / --preset); --compare puts panes with their own partitioning side by
// side. Each frame (or pane) is captioned with its level and triangle count. An output ending in
// .gif, .mp4 or .webm is one animation at --fps instead (render/figures/animation_writer.hpp).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>

#include "app/commands.hpp"
#include "app/level_args.hpp"
#include "app/render_args.hpp"
#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/construct/model_builders.hpp"
#include "core/io/document_io.hpp"
#include "render/domain/domain_labels.hpp"
#include "render/figures/animation_writer.hpp"
#include "render/figures/model_figure.hpp"
#include "render/figures/sweep_figure.hpp"
#include "render/targets/offscreen_target.hpp"
#include "render/targets/png_writer.hpp"

namespace pw::app {

namespace {

struct SweepArgs {
    RenderArgs render;
    std::string output, from = "1", to = "16";
    double seconds = 3.0, fps = 10.0;
    int frames = 0;
};

// File name of frame k: PATTERN with one printf integer conversion (%d, %04d), or DIR/frame_%04d.png.
class FrameNames {
public:
    explicit FrameNames(const std::string& pattern) {
        static const std::regex oneConversion(R"(^[^%]*%0?[1-9]?d[^%]*$)");
        if (pattern.find('%') != std::string::npos) {
            if (!std::regex_match(pattern, oneConversion))
                badOption("sweep", "-o", "'" + pattern + "' needs exactly one %d or %0Nd (N 1-9) for the frame number");
            pattern_ = pattern;
        } else {
            pattern_ = (std::filesystem::path(pattern) / "frame_%04d.png").string();
        }
        const std::filesystem::path dir = std::filesystem::path(pattern_).parent_path();
        std::error_code ec;
        // Remember the folders made here, so that a failed sweep takes them away again.
        for (std::filesystem::path d = dir; !d.empty() && !std::filesystem::exists(d, ec); d = d.parent_path()) created_.push_back(d);
        if (!dir.empty()) std::filesystem::create_directories(dir, ec);
        if (!dir.empty() && !std::filesystem::is_directory(dir))
            throw OutputError(dir.string(), "cannot create the frame directory" + (ec ? ": " + ec.message() : std::string()));
    }
    std::string operator()(int k) const {
        char buf[4096];
        std::snprintf(buf, sizeof buf, pattern_.c_str(), k);
        return buf;
    }

    FrameNames(const FrameNames&) = delete;
    FrameNames& operator=(const FrameNames&) = delete;
    // Takes away the folders the constructor made (innermost first, while empty), unless the sweep
    // was written (keepFolders).
    ~FrameNames() {
        std::error_code ec;
        for (const std::filesystem::path& d : created_) std::filesystem::remove(d, ec);
    }
    void keepFolders() { created_.clear(); }

private:
    std::string pattern_;
    std::vector<std::filesystem::path> created_;
};

int runSweep(const SweepArgs& a) {
    const std::string cmd = "sweep";
    if (!a.render.tess.empty() || !a.render.outer.empty() || !a.render.inner.empty())
        badOption(cmd, "--tess", "a sweep sets the levels itself (--from, --to)");
    if (!a.render.stats.empty()) badOption(cmd, "--stats", "sweep writes no statistics; each frame's caption has its count");
    const float from = parseLevel(cmd, "--from", a.from), to = parseLevel(cmd, "--to", a.to);
    if (!(a.seconds > 0.0 && a.seconds <= 600.0)) badOption(cmd, "--seconds", "must be from 0 to 600");
    if (!(a.fps > 0.0 && a.fps <= 120.0)) badOption(cmd, "--fps", "must be from 0 to 120");
    const int frames = a.frames > 0 ? a.frames : std::max(2, int(std::lround(a.seconds * a.fps)) + 1);
    if (frames < 2 || frames > 10000) badOption(cmd, "--frames", "must be from 2 to 10000");
    const auto [w, h] = parseImageSize(cmd, a.render.size);
    const DomainArgs dargs = domainArgs(a.render);
    const bool domain = wantsDomain(dargs);
    std::vector<render::DomainPane> panes;
    if (domain) {
        if (!a.render.input.empty()) badOption(cmd, "--domain", "a domain sweep draws no document; leave out the file");
        panes = domainPanes(cmd, dargs);
    }
    Document doc = domain ? Document{} : a.render.input.empty() ? builtinTeapot() : loadDocument(a.render.input);
    // The document's displacement (and the options on top of it), as render draws it.
    std::shared_ptr<const HeightMap> heightMap;
    if (!domain) {
        applyDisplacementArgs(cmd, a.render.displacement, doc);
        heightMap = loadDocumentHeightMap(doc, a.render.input);
    }
    // --compare on a model: the panes side by side, each with its partitioning, all at the sweep's level.
    std::vector<render::ModelPane> modelPanes;
    if (!domain && !a.render.compare.empty())
        for (const PaneSpec& p : parsePaneSpecs(cmd, "--compare", a.render.compare)) {
            if (p.level > 0.0f) badOption(cmd, "--compare", "a sweep sets the levels itself; give partitionings only");
            modelPanes.push_back({p.spacing, 0.0f});
        }
    render::RenderOptions opt;
    if (!domain) {
        const auto [paneW, paneH] = render::paneSize(int(modelPanes.size()), w, h);  // the camera is framed for a pane
        opt = buildRenderOptions(a.render, doc, paneW, paneH);
        if (a.render.overlay.empty()) opt.display.showWireframe = true;  // popping and sliding show in the wireframe
    }
    // An animation (.gif, .mp4, .webm: one file through ffmpeg), or numbered PNG frames.
    const std::optional<render::AnimationFormat> animation = render::animationFormatFor(a.output);
    std::unique_ptr<FrameNames> names;
    if (!animation) names = std::make_unique<FrameNames>(a.output);
    (void)checkOutputPath(animation ? a.output : (*names)(0));  // refuse an unwritable output before the work

    render::SweepSpec spec;
    spec.width = w;
    spec.height = h;
    spec.from = from;
    spec.to = to;
    spec.frames = frames;
    spec.msaa = !a.render.noMsaa;
    spec.domainPanes = panes;
    spec.document = &doc;
    spec.heightMap = heightMap;
    spec.options = opt;
    spec.modelPanes = modelPanes;

    render::DeviceOptions dopt;
    dopt.name = a.render.device;
    dopt.validation = a.render.validation;
    int rc = 0;
    {
        render::Device dev(dopt);
        OutputBatch out;  // every frame or none (a full disk leaves no partial sweep)
        std::unique_ptr<render::AnimationEncoder> encoder;
        if (animation) encoder = std::make_unique<render::AnimationEncoder>(a.output, *animation, w, h, a.fps);
        render::renderSweep(dev, spec, [&](int k, const std::vector<uint8_t>& rgba) {
            if (encoder)
                encoder->addFrame(rgba);
            else
                out.stage((*names)(k), render::encodePng((*names)(k), spec.width, spec.height, rgba));
        });
        if (encoder) out.stage(a.output, encoder->finish());
        out.commit();
        std::cout << "wrote " << frames << " frames (" << w << "x" << h << ", level " << render::formatLevel(from) << " to "
                  << render::formatLevel(to) << "): ";
        if (names) {
            names->keepFolders();
            std::cout << (*names)(0) << " .. " << (*names)(frames - 1) << "\n";
        } else {
            std::cout << a.output << " at " << a.fps << " frames per second\n";
        }
        rc = validationExitCode(dev, cmd);
    }
    return rc;
}

}  // namespace

void registerSweepCommand(CLI::App& app, Action& run) {
    const auto [cmd, a] = addSubcommand<SweepArgs>(
        app, run, "sweep", "Animate a tessellation level from --from to --to: a GIF, MP4 or WebM, or numbered PNG frames", runSweep);
    addRenderOptions(cmd, a->render);
    cmd->add_option("-o,--output", a->output,
                    "An animation (.gif, .mp4, .webm; encoded by ffmpeg), a frame file pattern with one %d or %04d, or a directory "
                    "(frame_0000.png ...)")
        ->required();
    cmd->add_option("--from", a->from, "First level, 1..64 (default 1)");
    cmd->add_option("--to", a->to, "Last level, 1..64 (default 16)");
    cmd->add_option("--seconds", a->seconds, "Length of the animation (default 3)");
    cmd->add_option("--fps", a->fps, "Frames per second (default 10)");
    cmd->add_option("--frames", a->frames, "Number of frames (overrides --seconds x --fps)");
}

}  // namespace pw::app

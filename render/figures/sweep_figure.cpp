#include "render/figures/sweep_figure.hpp"

#include <algorithm>
#include <memory>
#include <string>

#include "render/domain/domain_labels.hpp"
#include "render/figures/domain_figure.hpp"
#include "render/figures/label_raster.hpp"
#include "render/targets/offscreen_target.hpp"

namespace pw::render {
inline namespace figures {

namespace {

void caption(const LabelRaster& labels, std::vector<uint8_t>& rgba, unsigned w, unsigned h, const std::string& text) {
    TextStyle st;
    st.pixels = std::clamp(float(h) / 24.0f, 12.0f, 40.0f);
    st.box = true;
    labels.draw({w, h, rgba}, st.pixels * 0.6f, st.pixels * 0.6f, text, st);
}

}  // namespace

float sweepLevel(const SweepSpec& s, int k) { return s.frames > 1 ? s.from + (s.to - s.from) * float(k) / float(s.frames - 1) : s.from; }

void renderSweep(Device& dev, const SweepSpec& s, const std::function<void(int, const std::vector<uint8_t>&)>& frame) {
    const bool domain = !s.domainPanes.empty();
    OffscreenTarget target(dev, s.width, s.height, s.msaa);
    const LabelRaster labels;
    std::unique_ptr<DomainView> view;
    std::unique_ptr<Renderer> renderer;
    if (domain) {
        view = std::make_unique<DomainView>(dev, target.colorFormat(), target.depthFormat(), target.samples());
    } else {
        renderer = std::make_unique<Renderer>(dev, target);
        renderer->warmUp();
        renderer->setDocument(*s.document, s.heightMap);
    }
    RenderOptions opt = s.options;
    opt.tess.adaptive = AdaptiveMode::None;
    std::vector<uint8_t> rgba;
    for (int k = 0; k < s.frames; ++k) {
        const float level = sweepLevel(s, k);
        std::string text = "level " + formatLevel(level);
        if (domain) {
            std::vector<DomainPane> now = s.domainPanes;
            for (auto& p : now) p.levels = withUniformLevel(p.levels, level);
            renderDomainFigure(*view, target, labels, now, 0.0f, rgba);
        } else {
            opt.tess.outer = {level, level, level, level};
            opt.tess.inner = {level, level};
            if (!s.modelPanes.empty()) {
                renderModelFigure(*renderer, target, labels, opt, s.modelPanes, 0.0f, rgba);  // each pane captioned
            } else {
                const FrameStats st = renderer->render(opt);
                rgba = target.pixels();
                text += "  \u00b7  " + std::string(spacingName(opt.tess.spacing)) + "  \u00b7  " + std::to_string(st.triangles()) +
                        " triangles";
            }
        }
        if (s.modelPanes.empty() || domain) caption(labels, rgba, s.width, s.height, text);
        frame(k, rgba);
    }
}

}  // namespace figures
}  // namespace pw::render

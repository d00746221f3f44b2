#include "render/figures/model_figure.hpp"

#include <algorithm>

#include "render/domain/domain_labels.hpp"

namespace pw::render {
inline namespace figures {

std::array<uint32_t, 2> paneSize(int count, uint32_t width, uint32_t height) {
    const auto r = pixelRect(splitPanes(std::max(count, 1), {0.0f, 0.0f, float(width), float(height)}).front());
    return {uint32_t(std::max(r[2], 1)), uint32_t(std::max(r[3], 1))};
}

RenderOptions paneOptions(const RenderOptions& base, const ModelPane& pane, const std::array<float, 4>& rect, size_t index) {
    RenderOptions o = base;
    o.tess.spacing = pane.spacing;
    if (pane.level > 0.0f) {
        o.tess.adaptive = AdaptiveMode::None;
        o.tess.outer = {pane.level, pane.level, pane.level, pane.level};
        o.tess.inner = {pane.level, pane.level};
    }
    o.camera.distance *= pane.farther;  // back along the view direction, the target kept
    o.pane = pixelRect(rect);
    o.keepTarget = index > 0;
    return o;
}

namespace {

// 1234567 -> "1,234,567"
std::string groupDigits(uint64_t n) {
    const std::string digits = std::to_string(n);
    std::string out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string levelsText(const TessSettings& ts) {
    if (ts.adaptive != AdaptiveMode::None) return std::string("adaptive ") + std::string(adaptiveName(ts.adaptive));
    const float l = ts.outer[0];
    const bool uniform = std::all_of(ts.outer.begin(), ts.outer.end(), [&](float v) { return v == l; }) &&
                         std::all_of(ts.inner.begin(), ts.inner.end(), [&](float v) { return v == l; });
    std::string t = uniform ? "level" : "outer";
    const auto add = [&](float v) {
        t += ' ';
        t += formatLevel(v);
    };
    if (uniform) {
        add(l);
        return t;
    }
    for (float v : ts.outer) add(v);
    t += " inner";
    for (float v : ts.inner) add(v);
    return t;
}

}  // namespace

std::string paneCaption(const TessSettings& ts, uint64_t triangles, bool twoLines) {
    return std::string(spacingName(ts.spacing)) + " \u00b7 " + levelsText(ts) + (twoLines ? "\n" : " \u00b7 ") + groupDigits(triangles) +
           " triangles";
}

std::vector<PaneResult> renderModelFigure(Renderer& renderer, OffscreenTarget& target, const LabelRaster& labels, const RenderOptions& base,
                                          const std::vector<ModelPane>& panes, float textPixels, std::vector<uint8_t>& rgba) {
    const VkExtent2D ext = target.extent();
    const auto rects = splitPanes(int(panes.size()), {0.0f, 0.0f, float(ext.width), float(ext.height)});
    std::vector<PaneResult> results;
    for (size_t i = 0; i < rects.size(); ++i) {
        const RenderOptions o = paneOptions(base, panes[i], rects[i], i);
        results.push_back({o.tess, o.pane, renderer.render(o)});
    }
    rgba = target.pixels();
    PixelImage img{ext.width, ext.height, rgba};
    for (size_t i = 0; i < rects.size(); ++i) {
        TextStyle st;
        st.pixels = textPixels > 0.0f ? textPixels : std::clamp(std::min(rects[i][2], rects[i][3]) / 24.0f, 11.0f, 36.0f);
        st.box = true;
        labels.draw(
            img, rects[i][0] + st.pixels * 0.5f, rects[i][1] + st.pixels * 0.5f,
            (panes[i].label.empty() ? "" : panes[i].label + " \u00b7 ") + paneCaption(results[i].tess, results[i].stats.triangles()), st);
    }
    drawPaneDividers(rgba, ext.width, ext.height, rects);
    return results;
}

}  // namespace figures
}  // namespace pw::render

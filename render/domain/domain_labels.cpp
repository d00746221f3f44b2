#include "render/domain/domain_labels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace pw::render {
inline namespace domain {

std::string formatLevel(float level) {
    if (!std::isfinite(level)) return "nan";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", double(level));
    std::string s = buf;
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

void titleByPartitioning(std::vector<DomainViewOptions>& panes) {
    const bool compared =
        std::any_of(panes.begin(), panes.end(), [&](const DomainViewOptions& o) { return o.spacing != panes.front().spacing; });
    for (DomainViewOptions& o : panes) o.title = compared ? std::string(spacingName(o.spacing)) : std::string();
}

float domainLabelMargin(float textPixels) { return std::ceil(textPixels * 4.5f); }

namespace {

// "4.5 → 5" where the partitioning rounds the level to `seg` segments, else "4.5".
std::string roundedText(float level, int seg) {
    std::string t = formatLevel(level);
    if (float(seg) != level) t += " \u2192 " + std::to_string(seg);
    return t;
}

// The segments an edge of `level` gets: the control shader's level (pow2 applied) rounded by the
// tessellator's partitioning (integer for the isolines' line count).
int edgeSegments(float level, Spacing spacing, bool integerSpacing, float maxLevel) {
    return segmentCount(controlShaderLevel(level, spacing), integerSpacing ? Spacing::Equal : tessellatorSpacing(spacing), maxLevel);
}

std::string edgeText(float level, Spacing spacing, bool integerSpacing, float maxLevel) {
    return roundedText(level, edgeSegments(level, spacing, integerSpacing, maxLevel));
}

// "75 %": how far the two short segments of a fractional partitioning have grown (the notes'
// (f − 3) / (5 − 3) for a level between 3 and 5 under fractional_odd); empty where they are full
// length or there are none (equal, pow2, whole levels of the partitioning's parity).
std::string slideText(float level, Spacing spacing, int seg) {
    const float pct = slidePercent(level, spacing, seg);
    if (pct >= 99.5f || pct < 0.5f) return {};
    return std::to_string(int(std::lround(pct))) + " %";
}

// "quad domain · llvmpipe (LLVM 15.0.6, 256 bits)" where it fits the pane; else without the
// parenthesis, else the device alone (titles are drawn 10 % larger than `widthOf` measures).
std::string titleWithDevice(const std::string& title, const std::string& device, float room,
                            const std::function<float(const std::string&)>& widthOf) {
    const auto fits = [&](const std::string& t) { return !widthOf || widthOf(t) * 1.1f <= room; };
    const size_t paren = device.find(" (");
    const std::string shortName = paren == std::string::npos ? device : device.substr(0, paren);
    for (const std::string& t : {title + " \u00b7 " + device, title + " \u00b7 " + shortName})
        if (fits(t)) return t;
    return shortName;
}

}  // namespace

std::vector<DomainLabel> domainLabels(const DomainViewOptions& o, uint64_t vertices, uint64_t primitives, float textPixels,
                                      const std::function<float(const std::string&)>& widthOf) {
    std::vector<DomainLabel> out;
    const DomainPlacement at = placeDomain(o);
    const float gap = std::ceil(textPixels * 0.45f);
    const float maxLevel = 64.0f;
    const auto& L = o.levels;
    const DomainCounts rules = expectedDomainCounts(o.kind, L, o.spacing, maxLevel);
    // An edge's level (and rounding); its slide percentage beside it on the top and bottom edges
    // ("4 → 5 (50 %)"), on a line below it on the side edges (where the margin is narrow).
    const auto edgeLabel = [&](float level) {
        const int seg = edgeSegments(level, o.spacing, false, maxLevel);
        return std::pair{roundedText(level, seg), slideText(controlShaderLevel(level, o.spacing), o.spacing, seg)};
    };
    const auto edge = [&](float dx, float dy, float ax, float ay, std::string text) {
        if (at.flipY && ay != 0.5f) ay = 1.0f - ay;  // the upper-left origin: v = 0 on top
        const auto p = at.toPixels(dx, dy);
        DomainLabel l;
        l.x = p[0] + (ax == 1.0f ? -gap : ax == 0.0f ? gap : 0.0f);
        l.y = p[1] + (ay == 1.0f ? -gap : ay == 0.0f ? gap : 0.0f);
        l.ax = ax;
        l.ay = ay;
        l.text = std::move(text);
        out.push_back(std::move(l));
    };
    int edgeIndex = 0;  // the upper-left pictures tag each edge: [i] is SV_TessFactor[i] and gl_TessLevelOuter[i]
    const auto tag = [&](std::string text) { return o.upperLeft ? "[" + std::to_string(edgeIndex++) + "] " + text : text; };
    const auto slidEdge = [&](float dx, float dy, float ax, float ay, float level) {
        auto [text, slide] = edgeLabel(level);
        text = tag(text);
        const bool side = ay == 0.5f;
        edge(dx, dy, ax, ay, slide.empty() || side ? text : text + " (" + slide + ")");
        if (side && !slide.empty()) {
            DomainLabel under = out.back();
            under.text = slide;
            under.y += textPixels * 1.1f;
            out.push_back(std::move(under));
        }
    };
    // "inner 4.4 → 5 (70 % slid)": each inner level as the tessellator rounds it (an inner 1 with a
    // finer edge counts as 1 + ε: 2 segments, or 3 under fractional_odd).
    const auto innerText = [&](int i) {
        const float l = controlShaderLevel(L.inner[size_t(i)], o.spacing);
        const int seg = rules.innerSegments[size_t(i)];
        const std::string slide = slideText(l, o.spacing, seg);
        return roundedText(L.inner[size_t(i)], seg) + (slide.empty() ? "" : " (" + slide + " slid)");
    };
    std::string inner;
    const char* primitiveWord = "triangles";
    switch (o.kind) {
        case DomainKind::Quad:
            // outer[0] u = 0 (left), [1] v = 0 (bottom), [2] u = 1 (right), [3] v = 1 (top).
            slidEdge(0.0f, 0.5f, 1.0f, 0.5f, L.outer[0]);
            slidEdge(0.5f, 0.0f, 0.5f, 0.0f, L.outer[1]);
            slidEdge(1.0f, 0.5f, 0.0f, 0.5f, L.outer[2]);
            slidEdge(0.5f, 1.0f, 0.5f, 1.0f, L.outer[3]);
            inner = "inner " + innerText(0) + ", " + innerText(1);
            break;
        case DomainKind::Triangle: {
            // Corners (shaders/domain.tese): u = 1 bottom left, v = 1 bottom right, w = 1 top. Edge
            // u = 0 is the right side, v = 0 the left side, w = 0 the bottom.
            const float h = 0.8660254f;
            slidEdge(0.75f, 0.5f * h, 0.0f, 0.5f, L.outer[0]);
            slidEdge(0.25f, 0.5f * h, 1.0f, 0.5f, L.outer[1]);
            slidEdge(0.5f, 0.0f, 0.5f, 0.0f, L.outer[2]);
            inner = "inner " + innerText(0);
            break;
        }
        case DomainKind::Isoline:
            // outer[0]: how many lines (always integer spacing); outer[1]: segments per line.
            edge(0.0f, 0.5f, 1.0f, 0.5f, tag(edgeText(L.outer[0], o.spacing, true, maxLevel) + " lines"));
            edge(0.5f, 0.0f, 0.5f, 0.0f, tag(edgeText(L.outer[1], o.spacing, false, maxLevel) + " segments"));
            primitiveWord = "segments";
            break;
    }
    // Caption under the domain (below the bottom edge label), title above it.
    const auto bottom = at.toPixels(0.5f, at.flipY ? 1.0f : 0.0f);
    DomainLabel cap;
    cap.role = DomainLabel::Role::Caption;
    cap.x = bottom[0];
    cap.y = bottom[1] + gap + textPixels * 1.25f;
    cap.ax = 0.5f;
    const std::string settings = (inner.empty() ? "" : inner + "  \u00b7  ") + std::string(spacingName(o.spacing));
    const std::string counts = rules.culled ? "culled: an outer level of 0 discards the patch"
                                            : std::to_string(vertices) + " vertices, " + std::to_string(primitives) + " " + primitiveWord +
                                                  (o.countsNote.empty() ? "" : ", " + o.countsNote);
    cap.text = settings + "  \u00b7  " + counts;
    if (widthOf && widthOf(cap.text) > o.rect[2] - textPixels) {  // two lines where one does not fit the pane
        cap.text = settings;
        out.push_back(cap);
        cap.y += textPixels * 1.2f;
        cap.text = counts;
    }
    out.push_back(cap);
    const float domainHeight = o.kind == DomainKind::Triangle ? 0.8660254f : 1.0f;
    const auto top = at.toPixels(0.5f, at.flipY ? 0.0f : domainHeight);
    DomainLabel title;
    title.role = DomainLabel::Role::Title;
    title.x = top[0];
    title.y = top[1] - gap - textPixels * 1.25f;
    title.ax = 0.5f;
    title.ay = 1.0f;
    title.text = !o.title.empty() ? o.title : std::string(domainName(o.kind) == "tri" ? "triangle" : domainName(o.kind)) + " domain";
    if (!o.device.empty()) title.text = titleWithDevice(title.text, o.device, o.rect[2] - textPixels, widthOf);
    out.push_back(title);
    return out;
}

}  // namespace domain
}  // namespace pw::render
